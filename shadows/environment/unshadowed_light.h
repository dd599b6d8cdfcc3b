// C, the unshadowed light every pixel reflects towards the camera (DeCoro and Rusinkiewicz
// 2008, section 2, step 3), by fast local illumination, either
//
//   tables          SH irradiance and prefiltered lobes built once per scene
//                   (shading/environment/local_illumination.h): Lambert, Phong, GGX; or
//   radiance-cache  a per-frame table over normals for each material, for any BRDF
//                   (shading/environment/radiance_cache.h; the paper's section 3.1, 128^2):
//                   Blinn-Phong too, under the distant-viewer approximation.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shadows/settings_table.h"
#include "shadows/technique.h"

namespace shadowlab {

enum class UnshadowedMethod { Tables, RadianceCache };

struct UnshadowedSettings {
    UnshadowedMethod method = UnshadowedMethod::Tables;
    int cacheSize = 128;   // radiance-cache: texels a side of each material's table (the paper's 128^2)
};

// The parameters `unshadowed` and `cache-size`.
const SettingsTable<UnshadowedSettings>& unshadowedSettingsTable();

// Technique::prepare's part: with the tables, the scene's (`local_illumination_ms`).
std::vector<TechniqueStat> prepareUnshadowedLight(const PreparedScene& prepared, const UnshadowedSettings& settings);

// Throws std::invalid_argument naming a visible material the method cannot serve: with the
// tables, Blinn-Phong or a lobe too sharp for the map; with the radiance cache, an albedo
// texture (a table over normals holds one albedo per material). A technique calls it before
// any other work.
void refuseUnservedMaterials(const ShadowInputs& in, const UnshadowedSettings& settings);

// C at every hit pixel of in.gbuffer, about its shading normal. Call refuseUnservedMaterials
// first: a material the tables do not serve otherwise throws here, mid-frame
// (unshadowedRadiance). Adds `radiance_caches_count` with the radiance cache.
std::vector<glm::vec3> unshadowedLight(const ShadowInputs& in, const UnshadowedSettings& settings,
                                       std::vector<TechniqueStat>& stats);

}  // namespace shadowlab
