// The rules a camera and a light obey wherever they are made: the scene file's loader
// (scene_file.cpp, scene_lights.cpp) and the Python module's Camera and Light
// (python/view_bindings.cpp) check them here, one rule in one place. A problem names the
// scene format's field (docs/scene-format.md) and words what is wrong as a scene file's
// error does: "must be in (0, 90], got 95".
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "raster/fixed_point.h"
#include "scenes/json_fields.h"
#include "scenes/scene.h"
#include "scenes/scene_limits.h"

namespace shadowlab {

// The light types as the scene format names them ("type").
inline constexpr std::array<std::pair<std::string_view, LightType>, 5> kLightTypes{{
    {"point", LightType::Point},
    {"spot", LightType::Spot},
    {"directional", LightType::Directional},
    {"disk", LightType::Disk},
    {"rectangle", LightType::Rectangle}}};

struct FieldProblem {
    const char* field;     // the scene format's key: "coneAngle", "far"
    std::string problem;   // what is wrong with it
};

// A world-space position (scene_limits.h, kMaxCoordinate).
inline constexpr Interval kCoordinate{-kMaxCoordinate, kMaxCoordinate, false, false};
inline bool withinWorld(const glm::vec3& p) {
    return kCoordinate.contains(p.x) && kCoordinate.contains(p.y) && kCoordinate.contains(p.z);
}

inline constexpr Interval kFovyDeg{0.0, 180.0, true, true};
// The rasterizer's viewport limit: a camera that passes can be rendered.
inline constexpr Interval kImageSize{1.0, double(raster::kMaxViewport), false, false};

// A spot's half-angle: beyond 90 degrees it would no longer be a cone in front of it.
inline constexpr Interval kConeAngleDeg{0.0, 90.0, true, false};
// A sun's angular diameter: below 180 degrees its disk on the sky is a cap smaller than a
// hemisphere, whose directions the soft reference samples (shading/light_sampling.h, sunCap).
inline constexpr Interval kAngularDiameterDeg{0.0, 180.0, false, true};

// The camera's view frame's problem (camera.h, viewFrameProblem) on "target" or "up", or none.
std::optional<FieldProblem> viewFrameFieldProblem(const Camera& camera);

// The camera's problem, or none: its eye and target within the world, its field of view and
// image size, 0 < near < far, and a view frame (camera.h, viewFrameProblem).
std::optional<FieldProblem> cameraProblem(const Camera& camera);

// The light's problem, or none, for the fields its type reads (scene.h, Light): a position
// within the world, a direction that is not zero, the cone, range, radius, rectangle and
// sun's own rules, and an intensity that is finite and not negative.
std::optional<FieldProblem> lightProblem(const Light& light);

// direction / |direction|, normalised in double (a tiny but non-zero vector would underflow
// in float); none for a zero or non-finite vector.
std::optional<glm::vec3> unitDirection(const glm::vec3& direction);

}  // namespace shadowlab
