// How much light of one source arrives at a surface point, before visibility and the BRDF
// (conventions.md, "Lights"; units in scenes/scene.h).
//
// Area lights (disk, rectangle) are shaded as a point light at their centre whose radiant
// intensity is that of a small flat emitter, I(theta) = L * A * cos(theta), with L the
// radiance, A the area and theta the angle between the light's normal and the direction to
// the point (Lambert's cosine law for a flat Lambertian emitter). This far-field
// approximation is exact in the limit distance >> light size; nearer it misestimates the
// unoccluded irradiance (e.g. by a factor 1 + r^2/d^2 on the axis of a disk of radius r at
// distance d), but it keeps the shadow term separate: how much of the light is visible is
// the job of the visibility buffer V, not of this function.
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct LightArrival {
    glm::vec3 toLight{0.0f};     // unit vector from the point towards the light (or its centre)
    glm::vec3 irradiance{0.0f};  // on a plane facing the light, W/m^2; 0 if no light arrives
};

// Point: I / d^2. Spot: the same inside the cone, 0 outside (a hard cone, no falloff, so
// that the lit region is exactly the cone the shadow techniques are tested on), times its
// cookie's texel there if it has one (cookieTransmission).
// A glTF spot (innerConeAngleDeg set) falls off smoothly from its inner angle to its cone's
// edge, and a light with a range fades to 0 at it, by KHR_lights_punctual's recommended
// formulas (conventions.md, "Lights"); without them the bits are those of the plain rules.
// Directional: the light's irradiance, from its direction; a sun with an angular size the
// same, its disk's irradiance from its centre (exact while the disk is above the horizon:
// conventions.md, "Lights"), its size left to V. Disk, rectangle: the far-field point light above.
LightArrival lightArrival(const Light& light, const glm::vec3& point);

// A spot light's cookie (RTR 4th ed., section 7.2, "gobo map") projected through its cone
// (conventions.md, "Lights"): a square whose side spans the cone, centred on the axis, so
// the cone's circle is inscribed in it. With d the unit axis, up0 = +Y (or -Z when the
// axis is within 1e-3 radians of vertical), right = normalize(d x up0), up = right x d,
// q = P - position and t = tan(half-angle):
//     u = 0.5 + 0.5 dot(q, right) / (t dot(q, d)),   v = 0.5 + 0.5 dot(q, up) / (t dot(q, d)),
// u to the image's right, v up (row 0 at the top). Evaluated in double.
glm::dvec2 cookieCoordinates(const Light& spot, const glm::vec3& point);
// The nearest texel's fraction at (u, v), clamped to the image: column floor(u W), row
// floor((1 - v) H). 1 for a light without a cookie.
glm::vec3 cookieTransmission(const Light& light, const glm::vec3& point);

// True if the point lies inside (or on) a spot light's cone of half-angle coneAngleDeg
// around its direction; evaluated in double. Used by shading and by the shadow reference.
bool insideSpotCone(const Light& light, const glm::vec3& point);

// Whether any light of `light` can arrive at a surface point P with normal N, before
// occlusion: P is in front of the light, dot(N, L - P) > 0 with L the light's position (an
// area light's centre) or, for a directional light, dot(N, direction) > 0; and a spot's P
// lies inside its cone. Where this is false V = 0 (conventions.md, the V channel), so every
// technique and the reference decide it alike. Evaluated in double; inline, since every
// receiver pass asks it per pixel.
//
// LightReach is the same test with the light's type decided once, for a pass over many
// points: towards the light is A - s P, with (A, s) = (direction, 0) for a directional
// light and (position, 1) otherwise. 0 P = 0 and A - 0 = A exactly (P is finite), so both
// kinds get lightReaches' bits without a branch per point.
class LightReach {
public:
    explicit LightReach(const Light& light)
        : light_(light),
          anchor_(light.type == LightType::Directional ? glm::dvec3(light.direction) : glm::dvec3(light.position)),
          pointScale_(light.type == LightType::Directional ? 0.0 : 1.0),
          spot_(light.type == LightType::Spot) {}
    bool operator()(const glm::vec3& P, const glm::vec3& N) const {
        const glm::dvec3 towardsLight = anchor_ - glm::dvec3(P) * pointScale_;
        if (!(glm::dot(glm::dvec3(N), towardsLight) > 0.0)) return false;
        return !spot_ || insideSpotCone(light_, P);
    }

private:
    const Light& light_;
    glm::dvec3 anchor_;
    double pointScale_;
    bool spot_;
};

inline bool lightReaches(const Light& light, const glm::vec3& P, const glm::vec3& N) { return LightReach(light)(P, N); }

// Unit normal of the emitting side: disk: its direction; rectangle: the right-handed
// normalize(cross(halfEdgeU, halfEdgeV)), i.e. the side from which U turns
// counter-clockwise into V, like a front face (conventions.md, "Space and camera").
glm::dvec3 areaLightNormal(const Light& light);

// The light as a homogeneous point: (position, 1) for point, spot and (as their centre)
// area lights; (direction towards the light, 0) for a directional light. The direction from
// a point O to the light is then light.xyz - light.w * O.
glm::dvec4 homogeneousLight(const Light& light);

// Emitting area in m^2: pi r^2 for a disk, 4 |U x V| for a rectangle.
double areaLightArea(const Light& light);

}  // namespace shadowlab
