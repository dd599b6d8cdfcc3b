// The environment a scene is lit by, made ready once per prepared scene
// (PreparedScene::derived) so that no frame reads a file: the map the scene file names
// (`environment.map`, turned by `environment.rotation`; docs/scene-format.md), and, for the
// techniques that shade with fast local illumination, its tables for the scene's materials
// (shading/environment/local_illumination.h).
#pragma once

#include <optional>
#include <vector>

#include "scenes/prepared_scene.h"
#include "shading/environment/environment_map.h"
#include "shading/environment/environment_pyramid.h"
#include "shading/environment/local_illumination.h"
#include "shadows/technique.h"

namespace shadowlab {

// The scene's map. Throws std::invalid_argument if the scene names none, and the reader's
// std::runtime_error for a file it cannot read (environment_file.h).
const EnvironmentMap& sceneEnvironment(const PreparedScene& prepared, std::optional<double>* builtMs = nullptr);

// The local-illumination tables of the scene's map for those of its materials they can serve
// (tablesServe); unshadowedRadiance() refuses the others by name.
const LocalIllumination& sceneLocalIllumination(const PreparedScene& prepared, std::optional<double>* builtMs = nullptr);
bool tablesServe(const Material& material, const EnvironmentMap& map);

// The scene map's pyramid (the radiance cache integrates over it, structured sampling
// stratifies its cells), built once.
const EnvironmentPyramid& scenePyramid(const PreparedScene& prepared, std::optional<double>* builtMs = nullptr);

// Technique::prepare's part for every technique that reads the map: the map
// (`environment_ms`), read once per scene. The stages that build more from it prepare their
// own part (prepareLightSampling, prepareUnshadowedLight).
std::vector<TechniqueStat> prepareEnvironment(const PreparedScene& prepared);

}  // namespace shadowlab
