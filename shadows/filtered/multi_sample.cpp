// The `multi-sample` technique (Heckbert and Herf 1997, "Simulating Soft Shadows with
// Graphics Hardware", section 2: the shadow of an area light as the average of hard
// shadows from points on it; Real-Time Rendering, 4th ed., 7.1 and 7.6): N ordinary shadow
// maps (shadow_map.cpp's machinery: a light view fitted to the receivers, depth_map.h,
// slope-scaled bias, the float nearest lookup of shadow_lookup.h), each from one point on
// the light, averaged.
//
// The points are stratified: sqrt(N) x sqrt(N) strata of the unit square, one jittered
// point each, mapped to the disk (concentric map) or rectangle by light_sampling.h, the
// reference's own sampling. Every pixel sees the same N points (Heckbert and Herf's
// scheme), unlike the reference's per-pixel jitter, so residual error shows as faint
// banding rather than noise. As N grows V converges to the visible fraction of the light,
// up to the maps' resolution (each hard shadow is off by up to about a texel at its edge).
//
// A point of the light on or behind the receiver's plane, dot(N, L - P) <= 0, counts as
// hidden, as in the reference. V = (lit count) / N with an integer count per pixel, so
// the sum is exact and the same for any thread count.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/light_sampling.h"
#include "shadows/debug_buffers.h"
#include "shadows/depth_map.h"
#include "shadows/filtered/soft_shadow_map.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/kept_raster.h"
#include "shadows/light_view.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

constexpr uint64_t kLightSampleSeed = 0x4eb3f1997ull;   // fixed: the same points every run
constexpr int kMaxSamples = 4096;                        // counts fit uint16_t
// Receivers stay this far inside each map's sides: a nearest lookup reaches half a
// texel, and the receiver's texel may differ by another from where the fit put it.
constexpr double kNearestFitMarginTexels = 1.5;

struct MultiSampleSettings {
    int resolution = kSoftMapResolution;
    int samples = 64;   // N, a square
};

const SettingsTable<MultiSampleSettings>& multiSampleSettingsTable() {
    using S = MultiSampleSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::resolution), mapResolutionTable("texels per side of each map"))
            .integer("samples", member(&S::samples), 1, kMaxSamples, "N light points, a square: the level of detail");
    return table;
}

// Adds the hard shadow of the point light `point` from `map` to every pixel's count: the
// shadow map's nearest lookup (shadow_lookup.h), in float through its vector kernel, with
// V = 0 where the point is behind the surface. `v` is working memory, one float a pixel.
void accumulateHardShadow(const GBuffer& g, const DepthMap& map, const Light& point, raster::SimdLevel simd,
                          std::vector<float>& v, std::vector<uint16_t>& lit) {
    // Slope-scaled bias: the offset is in the map, the receiver stays put.
    const LookupPass pass(std::span(&map, 1), point, BiasSettings{}, makePcfKernel({}), simd);
    lookUpEveryRow(g, pass, {v.data()});
    tbb::parallel_for(tbb::blocked_range<size_t>(0, lit.size(), 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) lit[k] = uint16_t(lit[k] + (v[k] > 0.5f ? 1 : 0));
    });
}

// The samples' map and the rasterizer that draws it, kept between frames.
struct SampleMap {
    DepthMap map;
    KeptRasterizer rasterizer;
};

ShadowOutputs runMultiSample(const ShadowInputs& in) {
    const auto [resolution, samples] = multiSampleSettingsTable().read(in.params);
    const int perAxis = int(std::lround(std::sqrt(double(samples))));
    if (perAxis * perAxis != samples) {
        throw std::invalid_argument("multi-sample: samples must be a square (n x n strata), not " + std::to_string(samples));
    }
    requireAreaLight(in.light, "multi-sample");
    const AreaLightFrame frame = areaLightFrame(in.light);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    const DebugBuffers debug(in.debugDir, "multi-sample");
    LightFitOptions fit;
    fit.resolution = resolution;
    fit.marginTexels = kNearestFitMarginTexels;
    fit.simd = in.simd;
    fit.scratch = &in.kept().state<LightViewScratch>();
    const DepthMapSettings depth{resolution, DepthLayer::First, polygonOffsetFor(BiasSettings{}), {}};
    std::vector<uint16_t> lit(in.gbuffer.pixelCount(), 0);
    std::vector<float> v(in.gbuffer.pixelCount());
    // Every sample's map drawn in one memory by one rasterizer, kept between frames
    // (technique_history.h, kept_raster.h).
    SampleMap& kept = in.kept().state<SampleMap>();
    DepthMap& map = kept.map;
    StageTimer timer;
    Pcg32 rng(kLightSampleSeed, 0);
    for (int b = 0; b < perAxis; ++b) {
        for (int a = 0; a < perAxis; ++a) {
            const glm::dvec2 u = jitteredSample(a, b, perAxis, rng);
            Light point = pointLightFor(in.light);
            point.position = glm::vec3(areaLightPoint(frame, u));
            const LightView view = fitLightView(point, in.gbuffer, in.casterWorld(), fit);
            timer.lap("light_view");
            map = renderDepthMap(in.casters(), view, depth, in.simd, std::move(map), &kept.rasterizer.at(in.simd));
            timer.lap("depth_map");
            accumulateHardShadow(in.gbuffer, map, point, in.simd, v, lit);
            timer.lap("lookup");
            if (a == 0 && b == 0 && debug.enabled()) {
                writeDepthMap(debug, "depth-sample0", map);
                timer.lap("debug_buffers");   // not the next sample's light view
            }
        }
    }
    ShadowOutputs out;
    out.visibility.resize(lit.size());
    for (size_t k = 0; k < lit.size(); ++k) out.visibility[k] = float(lit[k]) / float(samples);
    debug.write("lit-count", in.gbuffer.width, in.gbuffer.height, std::vector<float>(lit.begin(), lit.end()), 0.0f,
                float(samples));
    out.stats = {{"resolution_texels", double(resolution)}, {"light_samples_count", double(samples)},
                 {"maps_count", double(samples)}};
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

Technique multiSampleTechnique() {
    return {.name = "multi-sample",
            .description = "average of N hard shadow maps from stratified points on the area light (Heckbert "
                           "and Herf 1997)",
            .params = multiSampleSettingsTable().specs(),
            .run = runMultiSample,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
