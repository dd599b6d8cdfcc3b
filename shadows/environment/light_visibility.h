// The visibility V of each of many lights at every pixel of a G-buffer, by one of three
// methods: a `shadow-map` per light (at its default settings but for the map's resolution),
// a `shadow-volume` per light (at its defaults), each run with typed settings through its
// family's entry point, or exact Embree rays through the scene's one BVH (the references,
// shadows/reference/scene_rays.h). The paper uses stenciled shadow volumes (DeCoro and Rusinkiewicz 2008,
// section 3.1); any of these fits.
//
// The per-light techniques' stage times and fill are summed over the lights and reported with
// the prefix `visibility_` (`visibility_lookup_ms`, `visibility_fill_fragments`).
#pragma once

#include <vector>

#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/settings_table.h"
#include "shadows/technique.h"

namespace shadowlab {

class ReferenceVisibility;

enum class VisibilityMethod { ShadowMap, ShadowVolume, Exact };

struct LightVisibilitySettings {
    VisibilityMethod method = VisibilityMethod::ShadowMap;
    int resolution = 2048;   // shadow-map: texels per side of each light's map
};

// The parameters `visibility` and `resolution`.
const SettingsTable<LightVisibilitySettings>& lightVisibilitySettingsTable();

// Technique::prepare's part: the casters' edge adjacency for shadow volumes.
std::vector<TechniqueStat> prepareLightVisibility(const PreparedScene& casters, const LightVisibilitySettings& settings);

class LightVisibility {
public:
    // With exact visibility, finds the scene's BVH, built on its first frame (the time is the
    // stat `visibility_bvh_ms`).
    LightVisibility(const ShadowInputs& in, const LightVisibilitySettings& settings);
    ~LightVisibility();

    // V of `light` at every pixel of g, a G-buffer of the same view seen by `camera`.
    // Directional and point lights give hard shadows; an area light's V is its visible
    // fraction with exact rays and its centre's visibility otherwise.
    std::vector<float> of(const Light& light, const GBuffer& g, const Camera& camera);

    void appendStatsTo(std::vector<TechniqueStat>& stats) const;

private:
    const ShadowInputs& in_;
    VisibilityMethod method_;
    ShadowMapTechniqueSettings map_;      // with the settings' resolution
    const ReferenceVisibility* exact_ = nullptr;   // the scene's (scene_rays.h); null: not exact
    std::vector<TechniqueStat> stats_;    // summed, in first-seen order
};

}  // namespace shadowlab
