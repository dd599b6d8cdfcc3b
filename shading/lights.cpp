// Light arrival at a point: inverse-square falloff for positional lights, constant
// irradiance for directional ones, and the far-field approximation of area lights
// documented in lights.h. Geometry is evaluated in double and the result rounded once.
#include "shading/lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// Radiant intensity (W/sr) that a light sends towards a point at offset `fromLight`,
// treating area lights as point lights at their centre (lights.h).
glm::dvec3 intensityTowards(const Light& light, const glm::dvec3& fromLight) {
    const glm::dvec3 intensity(light.intensity);
    switch (light.type) {
        case LightType::Point:
        case LightType::Spot:
            return intensity;
        case LightType::Disk:
        case LightType::Rectangle: {
            const double cosAtLight =
                glm::dot(areaLightNormal(light), fromLight) / glm::length(fromLight);
            return cosAtLight > 0.0 ? intensity * (areaLightArea(light) * cosAtLight)
                                    : glm::dvec3(0.0);
        }
        case LightType::Directional:
            break;
    }
    return glm::dvec3(0.0);
}

// KHR_lights_punctual's recommended smooth spot falloff ("Inner and Outer Cone Angles"):
// s = 1 / max(0.001, cos(inner) - cos(outer)), the square of
// clamp((cos(angle to the axis) - cos(outer)) s, 0, 1). 1 for a hard cone (no inner angle).
double spotFalloff(const Light& light, const glm::dvec3& fromLight) {
    if (light.type != LightType::Spot || !light.innerConeAngleDeg) return 1.0;
    const double toRadians = std::numbers::pi / 180.0;
    const double cosOuter = portable::cos(double(light.coneAngleDeg) * toRadians);
    const double cosInner = portable::cos(double(*light.innerConeAngleDeg) * toRadians);
    const double scale = 1.0 / std::max(0.001, cosInner - cosOuter);
    const double cd = glm::dot(glm::normalize(glm::dvec3(light.direction)), fromLight / glm::length(fromLight));
    const double t = std::clamp((cd - cosOuter) * scale, 0.0, 1.0);
    return t * t;
}

// The extension's recommended range window ("Range Property"), the factor of the inverse
// square: clamp(1 - (d / range)^4, 0, 1). 1 for an unbounded light (range 0).
double rangeWindow(const Light& light, double distanceSquared) {
    if (light.range <= 0.0f) return 1.0;
    const double ratioSquared = distanceSquared / (double(light.range) * double(light.range));
    return std::clamp(1.0 - ratioSquared * ratioSquared, 0.0, 1.0);
}

}  // namespace

bool insideSpotCone(const Light& light, const glm::vec3& point) {
    const glm::dvec3 axis(light.direction);
    const glm::dvec3 fromLight = glm::dvec3(point) - glm::dvec3(light.position);
    // angle(axis, fromLight) <= half-angle  <=>  cos(angle) >= cos(half-angle).
    const double cosHalfAngle = portable::cos(double(light.coneAngleDeg) * std::numbers::pi / 180.0);
    return glm::dot(axis, fromLight) >= cosHalfAngle * glm::length(axis) * glm::length(fromLight);
}

glm::dvec2 cookieCoordinates(const Light& spot, const glm::vec3& point) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(spot.direction));
    // Within 1e-3 radians of vertical, +Y is too close to the axis to give a stable right.
    const bool vertical = d.x * d.x + d.z * d.z < 1e-6;
    const glm::dvec3 right = glm::normalize(glm::cross(d, vertical ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, d);
    const glm::dvec3 q = glm::dvec3(point) - glm::dvec3(spot.position);
    const double scale = 0.5 / (portable::tan(double(spot.coneAngleDeg) * std::numbers::pi / 180.0) * glm::dot(q, d));
    return {0.5 + glm::dot(q, right) * scale, 0.5 + glm::dot(q, up) * scale};
}

glm::vec3 cookieTransmission(const Light& light, const glm::vec3& point) {
    if (!light.cookie) return glm::vec3(1.0f);
    const LightCookie& cookie = *light.cookie;
    const glm::dvec2 uv = cookieCoordinates(light, point);
    // Clamped before the conversion to an integer, which is undefined out of range; NaN to 0.
    const auto clamped = [](double x, int size) { return x > 0.0 ? (x < size - 1 ? x : size - 1) : 0.0; };
    const double column = clamped(uv.x * cookie.width, cookie.width);
    const double row = clamped((1.0 - uv.y) * cookie.height, cookie.height);
    return cookie.texels[size_t(row) * size_t(cookie.width) + size_t(column)];
}

glm::dvec4 homogeneousLight(const Light& light) {
    if (light.type == LightType::Directional) return glm::dvec4(glm::dvec3(light.direction), 0.0);
    return glm::dvec4(glm::dvec3(light.position), 1.0);
}

glm::dvec3 areaLightNormal(const Light& light) {
    if (light.type == LightType::Rectangle) {
        return glm::normalize(glm::cross(glm::dvec3(light.halfEdgeU), glm::dvec3(light.halfEdgeV)));
    }
    return glm::normalize(glm::dvec3(light.direction));
}

double areaLightArea(const Light& light) {
    if (light.type == LightType::Rectangle) {
        return 4.0 * glm::length(glm::cross(glm::dvec3(light.halfEdgeU), glm::dvec3(light.halfEdgeV)));
    }
    return std::numbers::pi * double(light.radius) * double(light.radius);
}

LightArrival lightArrival(const Light& light, const glm::vec3& point) {
    if (light.type == LightType::Directional) {
        return {glm::normalize(light.direction), light.intensity};
    }
    const glm::dvec3 fromLight = glm::dvec3(point) - glm::dvec3(light.position);
    const double distanceSquared = glm::dot(fromLight, fromLight);
    // A point on the light itself (or outside a spot's cone) receives nothing.
    if (distanceSquared == 0.0 || (light.type == LightType::Spot && !insideSpotCone(light, point))) {
        return {};
    }
    // x * 1.0 is x exactly, so a light without falloff or range keeps the plain rule's bits.
    const double window = spotFalloff(light, fromLight) * rangeWindow(light, distanceSquared);
    const glm::dvec3 irradiance = intensityTowards(light, fromLight) / distanceSquared * window;
    const glm::vec3 toLight(-fromLight / std::sqrt(distanceSquared));
    return {toLight, glm::vec3(irradiance) * cookieTransmission(light, point)};
}

}  // namespace shadowlab
