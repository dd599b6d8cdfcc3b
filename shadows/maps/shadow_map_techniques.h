// The shadow-map family: `shadow-map` (one map, or six cube faces for a point
// light among its receivers; optional LiSPSM warp for a directional light) and `csm`
// (cascaded shadow maps for a directional light; other lights get shadow-map's frame).
// See shadow_map.cpp and csm.cpp.
#pragma once

#include "shadows/maps/shadow_map_settings.h"
#include "shadows/technique.h"

namespace shadowlab {

// `shadow-map`'s settings: the map's, and how it covers a light.
struct ShadowMapTechniqueSettings {
    ShadowMapSettings map;
    bool alwaysCube = false;   // `cube=always`: six faces for a point light even where one frustum would do
    bool cullCubeFaces = true; // `cube-faces=all`: false, draw even the faces no visible receiver lies in
    bool lispsm = false;       // `warp=lispsm`: LiSPSM for a directional light
    bool fitWorld = false;     // `fit=scene`: the view fitted to the world's box, not the visible receivers
    bool cacheStatic = false;  // `cache=static`: the static casters' map kept across frames (static_map_cache.h)
};

// Its parameters: the map's, then `cube`, `cube-faces`, `warp`, `fit` and `cache`.
const SettingsTable<ShadowMapTechniqueSettings>& shadowMapTechniqueSettingsTable();

// `shadow-map` with typed settings, as another technique runs it per light (the environment
// techniques' LightVisibility); its `params` are not read. Throws std::invalid_argument for
// settings the light cannot take (lispsm but not directional, a cube but not a point light).
ShadowOutputs runShadowMap(const ShadowInputs& in, const ShadowMapTechniqueSettings& settings);

Technique shadowMapTechnique();
Technique cascadedShadowMapTechnique();

}  // namespace shadowlab
