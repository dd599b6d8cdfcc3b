// The visibility V of each of many lights at every pixel of a G-buffer, by the method a
// technique's `visibility` parameter names: a technique of the shadow-map or shadow-volume
// family at its own default settings (the map's resolution may be set), run once per light,
// or exact Embree rays from one BVH built for the frame (the references). The paper uses
// stenciled shadow volumes (DeCoro and Rusinkiewicz 2008, section 3.1); any of these fits.
//
// The per-light techniques' stage times and fill are summed over the lights and reported with
// the prefix `visibility_` (`visibility_lookup_ms`, `visibility_fill_fragments`).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "shadows/technique.h"

namespace shadowlab {

enum class VisibilityMethod { ShadowMap, ShadowVolume, Exact };

// The `visibility` and `map-resolution` parameters, for the techniques that use this.
std::vector<ParamSpec> visibilityParams(const std::string& defaultMethod);

class LightVisibility {
public:
    // Reads `visibility` and `map-resolution` from in.params; with exact visibility, builds
    // the BVH (its time is the stat `visibility_bvh_ms`).
    explicit LightVisibility(const ShadowInputs& in);
    ~LightVisibility();

    // V of `light` at every pixel of g, a G-buffer of the same view seen by `camera`.
    // Directional and point lights give hard shadows; an area light's V is its visible
    // fraction with exact rays and its centre's visibility otherwise.
    std::vector<float> of(const Light& light, const GBuffer& g, const Camera& camera);

    void appendStatsTo(std::vector<TechniqueStat>& stats) const;

private:
    struct Exact;
    const ShadowInputs& in_;
    VisibilityMethod method_;
    const Technique* technique_ = nullptr;              // shadow-map or shadow-volume
    std::map<std::string, std::string> settings_;       // its parameters
    std::unique_ptr<Exact> exact_;
    std::vector<TechniqueStat> stats_;                  // summed, in first-seen order
};

}  // namespace shadowlab
