// The JSON `render --error-map MAP --json FILE` writes: a scored frame with its settings,
// conditions, figures and pictures, which `report` reads back (app/sweep_json.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "frame/frame_images.h"
#include "frame/render.h"
#include "frame/score.h"

namespace shadowlab {

// One JSON object: {"scene", "overrides": overridesJson(overrides), "technique", "reference",
// "settings": {name: value}, "technique_ms", "stats": {name: value}, "preparation": {name: ms},
// "errors": formatJson(figures)}, and "images": formatFrameImagesJson(images) unless `images`
// is empty; for a frame of several lights, "lights": [{"light": K, "technique_ms",
// "errors": formatJson(lightFigures[K])}] (scoreLights(); "errors" is then over every light,
// docs/many-lights.md).
std::string formatScoreJson(const std::string& sceneName, const std::string& technique, const std::string& reference,
                            const std::map<std::string, std::string>& settings, const Frame& frame,
                            const ErrorFigures& figures, const FrameImages& images = {},
                            const SceneOverrides& overrides = {}, const std::vector<ErrorFigures>& lightFigures = {});

}  // namespace shadowlab
