#include "scenes/view_rules.h"

#include <cmath>

#include "scenes/camera.h"

namespace shadowlab {
namespace {

// Two vectors count as perpendicular when the cosine of their angle is below this; it
// allows for the rounding of hand-typed decimals such as 0.7071.
constexpr double kPerpendicularCosine = 1e-4;

std::optional<FieldProblem> numberProblem(const char* field, double x, const Interval& range) {
    if (range.contains(x)) return std::nullopt;
    return FieldProblem{field, "must be " + range.describe() + ", got " + formatNumber(x)};
}

std::optional<FieldProblem> vectorProblem(const char* field, const glm::vec3& v, const Interval& range) {
    for (int k = 0; k < 3; ++k)
        if (auto problem = numberProblem(field, v[k], range)) return problem;
    return std::nullopt;
}

std::optional<FieldProblem> directionProblem(const char* field, const glm::vec3& direction) {
    if (unitDirection(direction)) return std::nullopt;
    return FieldProblem{field, "must not be the zero vector"};
}

std::optional<FieldProblem> rectangleProblem(const Light& light) {
    if (auto problem = vectorProblem("halfEdgeU", light.halfEdgeU, kCoordinate)) return problem;
    if (auto problem = vectorProblem("halfEdgeV", light.halfEdgeV, kCoordinate)) return problem;
    const glm::dvec3 u(light.halfEdgeU), v(light.halfEdgeV);
    if (!(glm::length(glm::cross(u, v)) > 0.0))
        return FieldProblem{"halfEdgeV", "the rectangle has zero area (a half-edge is zero or they are parallel)"};
    if (std::abs(glm::dot(u, v)) > kPerpendicularCosine * glm::length(u) * glm::length(v))
        return FieldProblem{"halfEdgeV", "must be perpendicular to halfEdgeU"};
    return std::nullopt;
}

// A point or spot light's range (0: unbounded) and a spot's inner cone, below its cone.
std::optional<FieldProblem> punctualFalloffProblem(const Light& light) {
    if (auto problem = numberProblem("range", light.range, kNonNegative)) return problem;
    if (light.type == LightType::Spot && light.innerConeAngleDeg)
        return numberProblem("innerConeAngle", *light.innerConeAngleDeg,
                             Interval{0.0, double(light.coneAngleDeg), false, true});
    return std::nullopt;
}

std::optional<FieldProblem> shapeProblem(const Light& light) {
    switch (light.type) {
        case LightType::Point: return punctualFalloffProblem(light);
        case LightType::Spot:
            if (auto problem = directionProblem("direction", light.direction)) return problem;
            if (auto problem = numberProblem("coneAngle", light.coneAngleDeg, kConeAngleDeg)) return problem;
            return punctualFalloffProblem(light);
        case LightType::Directional:
            if (auto problem = directionProblem("direction", light.direction)) return problem;
            return numberProblem("angularDiameter", light.angularDiameterDeg, kAngularDiameterDeg);
        case LightType::Disk:
            if (auto problem = directionProblem("normal", light.direction)) return problem;
            return numberProblem("radius", light.radius, kPositive);
        case LightType::Rectangle: return rectangleProblem(light);
    }
    return std::nullopt;   // unreachable: every enumerator is handled above
}

}  // namespace

std::optional<glm::vec3> unitDirection(const glm::vec3& direction) {
    const glm::dvec3 v(direction);
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    return glm::vec3(v / length);
}

std::optional<FieldProblem> viewFrameFieldProblem(const Camera& camera) {
    switch (viewFrameProblem(camera)) {
        case ViewFrameProblem::EyeAtTarget: return FieldProblem{"target", "the camera's eye and target must differ"};
        case ViewFrameProblem::UpParallel:
            return FieldProblem{"up", "up must not be zero or parallel to the viewing direction"};
        case ViewFrameProblem::None: break;
    }
    return std::nullopt;
}

std::optional<FieldProblem> cameraProblem(const Camera& camera) {
    if (auto problem = vectorProblem("eye", camera.eye, kCoordinate)) return problem;
    if (auto problem = vectorProblem("target", camera.target, kCoordinate)) return problem;
    if (auto problem = numberProblem("fovy", camera.fovyDeg, kFovyDeg)) return problem;
    if (auto problem = numberProblem("width", camera.width, kImageSize)) return problem;
    if (auto problem = numberProblem("height", camera.height, kImageSize)) return problem;
    if (auto problem = numberProblem("near", camera.zNear, kPositive)) return problem;
    if (auto problem = numberProblem("far", camera.zFar, kPositive)) return problem;
    if (!(camera.zFar > camera.zNear))
        return FieldProblem{"far", "near must be less than far, got near " + std::to_string(camera.zNear) + ", far " +
                                       std::to_string(camera.zFar)};
    return viewFrameFieldProblem(camera);
}

std::optional<FieldProblem> lightProblem(const Light& light) {
    if (light.type != LightType::Directional)
        if (auto problem = vectorProblem("position", light.position, kCoordinate)) return problem;
    if (auto problem = shapeProblem(light)) return problem;
    for (int k = 0; k < 3; ++k) {
        if (std::isinf(light.intensity[k])) return FieldProblem{"power", "color * power overflows float"};
        if (!(light.intensity[k] >= 0.0f))
            return FieldProblem{"power", "color * power must be >= 0, got " + formatNumber(light.intensity[k])};
    }
    return std::nullopt;
}

}  // namespace shadowlab
