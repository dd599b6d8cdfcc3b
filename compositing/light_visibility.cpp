#include "compositing/light_visibility.h"

#include <chrono>

#include "shadows/reference/reference.h"

namespace shadowlab {

struct LightVisibility::Exact {
    explicit Exact(const WorldGeometry& world) : rays(world) {}
    ReferenceVisibility rays;
};

std::vector<ParamSpec> visibilityParams(const std::string& defaultMethod) {
    return {choiceParam<VisibilityMethod>(
                "visibility", defaultMethod,
                {{"shadow-map", VisibilityMethod::ShadowMap, "a `shadow-map` per light, at its default settings"},
                 {"shadow-volume", VisibilityMethod::ShadowVolume, "a `shadow-volume` per light (the paper's)"},
                 {"exact", VisibilityMethod::Exact, "Embree rays, one BVH for the frame"}},
                "how each light's V is found"),
            integerParam("map-resolution", 2048, 16, 8192, "shadow-map: texels per side of each light's map")};
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

LightVisibility::LightVisibility(const ShadowInputs& in)
    : in_(in), method_(in.params.choice<VisibilityMethod>("visibility")) {
    switch (method_) {
        case VisibilityMethod::ShadowMap:
            technique_ = &findTechnique("shadow-map");
            settings_ = {{"resolution", std::to_string(in.params.integer("map-resolution"))}};
            break;
        case VisibilityMethod::ShadowVolume: technique_ = &findTechnique("shadow-volume"); break;
        case VisibilityMethod::Exact: {
            const auto start = std::chrono::steady_clock::now();
            exact_ = std::make_unique<Exact>(in.casterWorld());
            addStat(stats_, "visibility_bvh_ms",
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            break;
        }
    }
}

LightVisibility::~LightVisibility() = default;

std::vector<float> LightVisibility::of(const Light& light, const GBuffer& g, const Camera& camera) {
    if (exact_) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<float> V = exact_->rays.visibility(g, light);
        addStat(stats_, "visibility_rays_ms",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        return V;
    }
    const TechniqueParams params(technique_->name, technique_->params, settings_);
    ShadowOutputs out = technique_->run({in_.prepared, g, light, in_.simd, params, {}, nullptr, &camera, &in_.casters()});
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
