// The conditions a result was measured under, as JSON: the overrides of the scene's image
// size, view and light (SceneOverrides, frame/render.h) that a sweep's grid and a render's
// score record ("overrides"), so that a report files each result under its conditions.
#pragma once

#include <array>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "frame/render.h"

namespace shadowlab {

// A position as its JSON array [x, y, z], as the overrides and a fly-through's frames write it.
inline std::array<float, 3> xyz(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Only the overrides given, so that none writes {}: "light", "width", "height", "eye", "target",
// "fovy", "light_position", "light_radius".
nlohmann::ordered_json overridesJson(const SceneOverrides& overrides);
// Throws nlohmann's exceptions for a field of the wrong type.
SceneOverrides readOverrides(const nlohmann::ordered_json& json);

// The conditions in words, for people: "the scene's own view and light" for none, else
// e.g. "320 x 200 pixels, light at (-5, 5, 2)".
std::string describeOverrides(const SceneOverrides& overrides);

}  // namespace shadowlab
