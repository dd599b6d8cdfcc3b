// The screen-space march of contact shadows (Sousa et al., "Secrets of CryENGINE 3
// Graphics Technology", SIGGRAPH 2011 course; Real-Time Rendering, 4th ed., section 7.10):
// the camera's depth buffer, already drawn for the frame, is read as a heightfield, and a
// ray from each pixel's surface point towards the light is marched over it (RTR 6.8.1). A
// sample that lies behind the surface the buffer holds at its pixel, by no more than the
// depth thickness, is inside that surface: the ray is blocked and the pixel shadowed.
//
// The buffer stores one surface per pixel, so the march knows neither what is off screen
// nor what hides behind the visible surfaces, nor how thick anything is: the thickness is
// a guess that every such technique has to make. Hence it only restores short shadows,
// next to their casters, and a shadow map does the rest (contact_shadows.cpp).
//
// Depth comparison: the G-buffer keeps each pixel's surface point P and normal N, so the
// buffer's depth is taken on the plane (P, N) where the camera's ray through the sample
// meets it, not at the pixel's centre: the receiver-plane comparison of RTR 7.5 (Figure
// 7.24, middle) in screen space. A plane then never shadows itself and no depth bias is
// needed; a curved surface is a plane within the pixel.
//
// Everything per sample is float arithmetic in a fixed order, pixels are independent and
// rows run in parallel, so the mask is the same bytes for any thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

struct MarchSettings {
    float lengthM = 0.25f;      // how far towards the light the ray is marched, m
    int steps = 16;             // samples along it, evenly spaced, the last at lengthM
    float thicknessM = 0.05f;   // how far behind the buffer's surface a sample still counts as inside it, m
};

// One sample of a march, as the debug plot shows it.
struct MarchSample {
    float distanceM = 0.0f;      // along the ray from the surface point
    glm::vec2 pixel{0.0f};       // where it projects, pixel coordinates (centre of pixel i at i + 0.5)
    float sampleDepth = 0.0f;    // its view depth, m along the camera's axis
    float bufferDepth = 0.0f;    // the buffer's surface at that pixel, on the same camera ray; infinite: none
    bool occluded = false;
};

// Why a march ended.
enum class MarchEnd { Lit, Occluded, LeftScreen };

class ScreenMarch {
public:
    // The settings must be valid (MarchSettings' ranges in contact_shadows.cpp).
    ScreenMarch(const GBuffer& g, const Camera& camera, const Light& pointLight, const MarchSettings& settings);

    // Marches from surface pixel k towards the light, calling visit(sample) at every step
    // until visit returns true (the mask stops at the first occluded sample; the plot
    // sees them all), the ray leaves the screen or the steps reach the march length (or
    // the light, if nearer). Occluded if any visited sample was.
    template <class Visit>
    MarchEnd march(size_t k, Visit visit) const;

    // Per pixel: 0 where the march found an occluder, 1 elsewhere (also where the light
    // is behind the surface, which is the shadow map's to say), and why each march ended.
    struct Mask {
        std::vector<float> visibility;
        std::vector<uint8_t> end;   // MarchEnd per pixel; Lit where hit = 0
    };
    Mask mask() const;

private:
    // The pixel coordinates of a clip-space position (OpenGL's window transform, row 0 at
    // the top); false unless its view depth is beyond the near plane and it is on the screen.
    bool toPixel(const glm::vec4& clip, float depth, glm::vec2& pixel) const;

    const GBuffer& g_;
    glm::mat4 clipFromWorld_;
    glm::vec3 eye_, forward_;
    float zNear_;
    float pixelFootprint_;   // a pixel's height at unit view depth, m per m
    Light light_;
    MarchSettings settings_;
};

template <class Visit>
MarchEnd ScreenMarch::march(size_t k, Visit visit) const {
    const glm::vec3 P = g_.position[k];
    const bool directional = light_.type == LightType::Directional;
    const glm::vec3 towards = directional ? light_.direction : light_.position - P;
    const float reach = directional ? settings_.lengthM : glm::min(settings_.lengthM, glm::length(towards));
    const glm::vec3 dir = glm::normalize(towards);
    // The projection is linear in homogeneous coordinates, so along the ray the clip
    // position and the view depth are the start's plus t times the direction's (McGuire and
    // Mara 2014 march in homogeneous clip space the same way): no matrix per sample.
    const glm::vec4 clipP = clipFromWorld_ * glm::vec4(P, 1.0f), clipDir = clipFromWorld_ * glm::vec4(dir, 0.0f);
    const float depthP = glm::dot(P - eye_, forward_), depthDir = glm::dot(dir, forward_);
    bool occluded = false;
    for (int step = 1; step <= settings_.steps; ++step) {
        MarchSample s;
        const float t = reach * float(step) / float(settings_.steps);
        const glm::vec3 S = P + dir * t;
        s.distanceM = t, s.sampleDepth = depthP + depthDir * t;
        if (!toPixel(clipP + clipDir * t, s.sampleDepth, s.pixel)) {
            return occluded ? MarchEnd::Occluded : MarchEnd::LeftScreen;
        }
        const size_t q = g_.index(int(s.pixel.x), int(s.pixel.y));
        s.bufferDepth = std::numeric_limits<float>::infinity();
        const glm::vec3 Nq = g_.normal[q];
        // The buffer's plane at q met by the camera ray through S: with h = (S - Pq).Nq and
        // a = (S - eye).Nq, the ray reaches the plane at the fraction 1 - h / a of the way
        // to S, so S lies h / a of its depth behind the plane when h, a < 0.
        const float h = glm::dot(S - g_.position[q], Nq), a = glm::dot(S - eye_, Nq);
        if (g_.hit[q] && a < 0.0f) {
            const float behind = s.sampleDepth * (h / a);
            s.bufferDepth = s.sampleDepth - behind;
            // A pixel's own plane never shadows it. Elsewhere a sample must lie behind the
            // plane by more than a pixel's footprint at its depth: a pixel on a silhouette
            // holds a plane that ends inside it, and extended past that edge it would
            // shadow the samples just above it; the margin also covers float rounding, so
            // a plane seen through its own pixels never shadows itself.
            s.occluded = q != k && behind > pixelFootprint_ * s.sampleDepth && behind <= settings_.thicknessM;
        }
        occluded = occluded || s.occluded;
        if (visit(s)) break;
    }
    return occluded ? MarchEnd::Occluded : MarchEnd::Lit;
}

}  // namespace shadowlab
