#include "shadows/environment/light_visibility.h"

#include <chrono>

#include "shadows/reference/scene_rays.h"
#include "shadows/volumes/shadow_volume.h"

namespace shadowlab {

const SettingsTable<LightVisibilitySettings>& lightVisibilitySettingsTable() {
    using S = LightVisibilitySettings;
    static const auto table =
        SettingsTable<S>()
            .choice("visibility", member(&S::method),
                    {{"shadow-map", VisibilityMethod::ShadowMap, "a `shadow-map` per light, at its default settings"},
                     {"shadow-volume", VisibilityMethod::ShadowVolume, "a `shadow-volume` per light (the paper's)"},
                     {"exact", VisibilityMethod::Exact, "Embree rays, the scene's one BVH"}},
                    "how each light's V is found")
            .include(member(&S::resolution), mapResolutionTable("shadow-map: texels per side of each light's map"));
    return table;
}

std::vector<TechniqueStat> prepareLightVisibility(const PreparedScene& casters, const LightVisibilitySettings& settings) {
    if (settings.method != VisibilityMethod::ShadowVolume) return {};
    return prepareCasterEdgeAdjacency(casters);
}

namespace {

bool endsWith(const std::string& name, const std::string& suffix) {
    return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Adds to the stat of that name, or appends it.
void addStat(std::vector<TechniqueStat>& stats, const std::string& name, double value) {
    for (TechniqueStat& s : stats) {
        if (s.name == name) return void(s.value += value);
    }
    stats.push_back({name, value});
}

}  // namespace

LightVisibility::LightVisibility(const ShadowInputs& in, const LightVisibilitySettings& settings)
    : in_(in), method_(settings.method) {
    map_.map.resolution = settings.resolution;
    if (method_ == VisibilityMethod::Exact) {
        const auto start = std::chrono::steady_clock::now();
        exact_ = &sceneRays(in.casters());
        addStat(stats_, "visibility_bvh_ms",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
}

LightVisibility::~LightVisibility() = default;

std::vector<float> LightVisibility::of(const Light& light, const GBuffer& g, const Camera& camera) {
    if (exact_) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<float> V = exact_->visibility(g, light);
        addStat(stats_, "visibility_rays_ms",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        return V;
    }
    const ShadowInputs lightInputs{.prepared = in_.prepared,
                                   .gbuffer = g,
                                   .light = light,
                                   .simd = in_.simd,
                                   .params = in_.params,   // read by neither run below
                                   .gbufferCamera = &camera,
                                   .casterScene = &in_.casters()};
    ShadowOutputs out = method_ == VisibilityMethod::ShadowMap ? runShadowMap(lightInputs, map_)
                                                               : runShadowVolume(lightInputs, StencilPassSettings{});
    // Times and fill add up over the lights; a per-light figure (a light's near plane) does not.
    for (const TechniqueStat& s : out.stats) {
        if (endsWith(s.name, "_ms") || endsWith(s.name, "_fragments")) addStat(stats_, "visibility_" + s.name, s.value);
    }
    return std::move(out.visibility);
}

void LightVisibility::appendStatsTo(std::vector<TechniqueStat>& stats) const {
    stats.insert(stats.end(), stats_.begin(), stats_.end());
}

}  // namespace shadowlab
