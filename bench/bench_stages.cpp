// Micro-benchmarks of the rasterizer's stages on the `bunny` scene seen from its light
// (the depth-only shadow-map pass): vertex stage, setup, binning, and per-tile
// rasterization for each SIMD level; and a fill-rate sweep by triangle size (as Masked
// Occlusion Culling's FillrateTest). Run: build/bench/bench_stages (Google Benchmark flags
// apply, e.g. --benchmark_repetitions=10 --benchmark_report_aggregates_only=true).
#include <malloc.h>

#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/global_control.h>

#include "raster/bin.h"
#include "raster/rasterizer.h"
#include "raster/setup.h"
#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "scenes/scene_file.h"
#include "shading/lights.h"
#include "shadows/izb/izb.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/ray_offset.h"
#include "shadows/technique.h"

using namespace shadowlab;
using namespace shadowlab::raster;

namespace {

constexpr int kMapSize = 2048;

struct LightPass {
    WorldGeometry world;
    glm::mat4 clipFromWorld;
    PipelineState state;   // depth-only, back faces culled
    Viewport viewport{kMapSize, kMapSize, clipVolumeFor(kMapSize, kMapSize, true)};

    LightPass() : world(flatten(loadScene("bunny"))) {
        const glm::vec3 light(4, 8, 3);
        clipFromWorld = glm::perspective(glm::radians(90.0f), 1.0f, 0.5f, 50.0f) * glm::lookAt(light, glm::vec3(0), glm::vec3(0, 1, 0));
    }
};

const LightPass& lightPass() {
    static const LightPass pass;
    return pass;
}

// The front end up to setup, on one thread, for triangles that need no clipping.
SetupChunk setUp(const LightPass& p, const TransformedVertices& v, SimdLevel level = bestSimdLevel()) {
    SetupChunk chunk;
    SetupQueue queue(rasterKernels(level).setup, setupConstants(kMapSize, kMapSize, p.state, 0), chunk);
    for (const glm::uvec3& t : p.world.triangles) {
        if ((v.clipCode[t.x] | v.clipCode[t.y] | v.clipCode[t.z]) != 0) continue;
        queue.push({{v.window[t.x], nullptr}, {v.window[t.y], nullptr}, {v.window[t.z], nullptr}}, {0, 1.0});
    }
    queue.flush();
    return chunk;
}

void BM_VertexStage(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const LightPass& p = lightPass();
    TransformedVertices v;
    for (auto _ : state) {
        transformVertices(std::span<const glm::vec3>(p.world.positions), p.clipFromWorld, p.viewport, v);
        benchmark::DoNotOptimize(v.window.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(p.world.positions.size()));
}

// Setup on one thread; argument: SIMD level.
void BM_Setup(benchmark::State& state) {
    const auto level = SimdLevel(state.range(0));
    if (!simdLevelSupported(level)) {
        state.SkipWithError("SIMD level not supported on this CPU");
        return;
    }
    const LightPass& p = lightPass();
    TransformedVertices v;
    transformVertices(std::span<const glm::vec3>(p.world.positions), p.clipFromWorld, p.viewport, v);
    for (auto _ : state) {
        SetupChunk chunk = setUp(p, v, level);
        benchmark::DoNotOptimize(chunk.triangles.data());
    }
    state.SetLabel(simdLevelName(level));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(p.world.triangles.size()));
}

void BM_Binning(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const LightPass& p = lightPass();
    TransformedVertices v;
    transformVertices(std::span<const glm::vec3>(p.world.positions), p.clipFromWorld, p.viewport, v);
    std::vector<SetupChunk> chunks = {setUp(p, v)};
    const int tiles = kMapSize / kTileSize;
    TileBins bins;
    for (auto _ : state) {
        countTiles(chunks[0], tiles, tiles);
        fillBins(chunks, 0, 1, tiles, tiles, bins);
        benchmark::DoNotOptimize(bins.entries.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(chunks[0].triangles.size()));
}

// Per-tile rasterization of the binned triangles, one thread; argument: SIMD level.
void BM_RasterTiles(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto level = SimdLevel(state.range(0));
    if (!simdLevelSupported(level)) {
        state.SkipWithError("SIMD level not supported on this CPU");
        return;
    }
    const LightPass& p = lightPass();
    TransformedVertices v;
    transformVertices(std::span<const glm::vec3>(p.world.positions), p.clipFromWorld, p.viewport, v);
    std::vector<SetupChunk> chunks = {setUp(p, v)};
    const int tiles = kMapSize / kTileSize;
    countTiles(chunks[0], tiles, tiles);
    TileBins bins;
    fillBins(chunks, 0, 1, tiles, tiles, bins);
    Framebuffer fb(kMapSize, kMapSize);
    const DrawConstants constants = {p.state, {1, 1, 1, 1}, 0};
    const TileKernel kernel = rasterKernels(level).kernel[int(FragmentOutput::DepthOnly)][0][0];
    uint64_t fragments = 0;
    for (auto _ : state) {
        fb.clearDepth(1.0f);
        const FramebufferView view = fb.view();   // fills the whole map, as a full clear
        for (int tile = 0; tile < tiles * tiles; ++tile) {
            const Tile at = tileAt(tile, tiles);
            for (size_t e = bins.start[size_t(tile)]; e < bins.start[size_t(tile) + 1]; ++e)
                kernel(*bins.entries[e], at, constants, view, fragments);
        }
        benchmark::DoNotOptimize(view.depth);
    }
    benchmark::DoNotOptimize(fragments);
    state.SetLabel(simdLevelName(level));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(bins.entries.size()));
}

// Fill rate by triangle size: a grid of right triangles of the given leg in pixels
// covering a 1024x1024 target twice (two layers, the second behind the first), depth-only.
void BM_FillRate(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const int leg = int(state.range(0));
    const auto level = SimdLevel(state.range(1));
    if (!simdLevelSupported(level)) {
        state.SkipWithError("SIMD level not supported on this CPU");
        return;
    }
    constexpr int kSize = 1024;
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;
    for (float z : {0.25f, 0.75f}) {
        for (int y = 0; y + leg <= kSize; y += leg) {
            for (int x = 0; x + leg <= kSize; x += leg) {
                const auto base = uint32_t(positions.size());
                for (glm::vec2 c : {glm::vec2(x, y), glm::vec2(x, y + leg), glm::vec2(x + leg, y + leg), glm::vec2(x + leg, y)}) {
                    positions.push_back(glm::vec3(2.0f * c.x / kSize - 1.0f, 1.0f - 2.0f * c.y / kSize, 2.0f * z - 1.0f));
                }
                triangles.push_back({base, base + 1, base + 2});
                triangles.push_back({base, base + 2, base + 3});
            }
        }
    }
    Framebuffer fb(kSize, kSize);
    Rasterizer r(level);
    PipelineState s;
    const DrawCall call = positionsDraw(positions, triangles, glm::mat4(1.0f));
    for (auto _ : state) {
        fb.clearDepth(1.0f);
        r.draw(fb, s, call);
    }
    state.SetLabel(simdLevelName(level));
    state.counters["Mtris/s"] = benchmark::Counter(double(triangles.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["Mpix/s"] = benchmark::Counter(2.0 * kSize * kSize * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// sphere-box seen by its camera: the receivers of the benchmarks below (the G-buffer is the
// same bytes at every SIMD level).
struct CameraView {
    Scene scene = loadScene("sphere-box");
    WorldGeometry world = flatten(scene);
    GBuffer g = renderGBuffer(world, scene.camera, bestSimdLevel());
    Light light = pointLightFor(scene.lights[0]);
};

const CameraView& cameraView() {
    static const CameraView view;
    return view;
}

// The shadow-map lookup (the receiver pass of `shadow-map`, filter nearest or 3x3 grid) on
// sphere-box's camera G-buffer, one thread, for a map of range(1) texels per side.
void BM_ShadowLookup(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto level = SimdLevel(state.range(0));
    if (!simdLevelSupported(level)) {
        state.SkipWithError("SIMD level not supported on this CPU");
        return;
    }
    const auto& [scene, world, g, light] = cameraView();
    LightFitOptions fit;
    fit.resolution = int(state.range(1));
    DepthMapSettings settings;
    settings.size = fit.resolution;
    settings.offset = polygonOffsetFor(BiasSettings{});
    const std::vector<DepthMap> maps = {renderDepthMap(world, fitLightView(light, g, world, fit), settings, level)};
    FilterSettings filter;
    filter.kind = state.range(2) == 1 ? FilterKind::Nearest : FilterKind::Grid;
    filter.gridSize = int(state.range(2));
    const PcfKernel kernel = makePcfKernel(filter);
    for (auto _ : state) {
        const ShadowLookup lookup = lookUpShadows(g, scene.camera, light, maps, OneMap{}, BiasSettings{}, kernel, level);
        benchmark::DoNotOptimize(lookup.visibility.data());
    }
    state.SetLabel(std::string(simdLevelName(level)) + (filter.kind == FilterKind::Nearest ? ", nearest" : ", 3x3 grid"));
    state.counters["ns/pixel"] = benchmark::Counter(double(g.pixelCount()) * 1e-9,
                                                    benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Fitting the light's frustum to sphere-box's receivers (fitLightView: the receivers'
// bounding box, their bounds in the light's view, the nearest occluder), one thread.
void BM_LightView(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto& [scene, world, g, light] = cameraView();
    LightFitOptions options;
    options.simd = SimdLevel(state.range(0));
    if (!simdLevelSupported(options.simd)) {
        state.SkipWithError("SIMD level not supported on this CPU");
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(fitLightView(light, g, world, options));
    state.SetLabel(simdLevelName(options.simd));
}

// The irregular z-buffer's stages (shadows/izb/izb.h) on sphere-box's camera G-buffer, one
// thread, each timed alone on the previous stages' results: range(0) is the stage, 1 to 5.
void BM_IrregularZBuffer(benchmark::State& state) {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const CameraView& view = cameraView();
    const WorldGeometry& world = view.world;
    const GBuffer& g = view.g;
    const Light& light = view.light;
    const double diagonal = sceneDiagonal(world);
    std::vector<float> visibility;
    const izb::Receivers receivers = izb::gatherReceivers(g, light, diagonal, visibility, bestSimdLevel());
    const auto makeGrid = [&] {
        std::vector<LightView> views = izb::fitViews(light, g, world, bestSimdLevel());
        const izb::ReceiverPlaces places = izb::placeReceivers(views, receivers);
        const int resolution = izb::chooseResolution(views.size(), places, 2.0);
        return std::make_pair(izb::makeLightGrid(std::move(views), resolution, diagonal), places);
    };
    const auto [grid, places] = makeGrid();
    const izb::TexelLists lists = izb::buildTexelLists(izb::receiverTexels(grid.resolution, places), grid.texelCount());
    const izb::ListedReceivers listed = izb::listReceivers(receivers, lists);
    const izb::ProjectedOccluders occluders = izb::projectOccluders(grid, world);
    const izb::TileBins bins = izb::binOccluders(grid, lists, occluders);
    const int stage = int(state.range(0));
    for (auto _ : state) {
        if (stage == 1) benchmark::DoNotOptimize(izb::gatherReceivers(g, light, diagonal, visibility, bestSimdLevel()));
        if (stage == 2) benchmark::DoNotOptimize(makeGrid());
        if (stage == 3) {
            const izb::TexelLists texelLists = izb::buildTexelLists(izb::receiverTexels(grid.resolution, places), grid.texelCount());
            benchmark::DoNotOptimize(izb::listReceivers(receivers, texelLists));
        }
        if (stage == 4) benchmark::DoNotOptimize(izb::binOccluders(grid, lists, izb::projectOccluders(grid, world)));
        if (stage == 5) benchmark::DoNotOptimize(izb::traverseOccluders(grid, homogeneousLight(light), listed, lists, bins, occluders, nullptr, bestSimdLevel()));
    }
    static const char* const names[] = {"", "receivers", "light grid", "lists", "binning", "traversal"};
    state.SetLabel(names[stage]);
}

void lookupCases(benchmark::internal::Benchmark* b) {
    for (int taps : {1, 3}) {
        for (int size : {256, 2048}) {
            for (SimdLevel l : {SimdLevel::Scalar, SimdLevel::Avx2, SimdLevel::Avx512}) b->Args({int(l), size, taps});
        }
    }
}

void simdLevels(benchmark::internal::Benchmark* b) {
    for (SimdLevel l : {SimdLevel::Scalar, SimdLevel::Avx2, SimdLevel::Avx512}) b->Arg(int(l));
}

void fillRateSizes(benchmark::internal::Benchmark* b) {
    for (int leg : {2, 4, 8, 16, 32, 64, 128, 256}) {
        for (SimdLevel l : {SimdLevel::Scalar, SimdLevel::Avx2, SimdLevel::Avx512}) b->Args({leg, int(l)});
    }
}

}  // namespace

// sphere-box at 640 x 400, prepared once: the scene FLIP is timed on and its frame beside it.
const PreparedScene& smallSphereBox() {
    static const PreparedScene prepared = [] {
        Scene scene = loadScene("sphere-box");
        SceneOverrides size;
        size.width = 640, size.height = 400;
        applyOverrides(scene, size);
        return PreparedScene(std::move(scene));
    }();
    return prepared;
}

// A whole `shadow-map` frame of it (G-buffer, technique, shading) on range(0) threads: what
// BM_Flip's cost is a share of.
void BM_ShadowMapFrame(benchmark::State& state) {
    const PreparedScene& prepared = smallSphereBox();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(renderFrame(prepared, findTechnique("shadow-map"), {}).radiance.data());
    state.SetLabel(std::to_string(state.range(0)) + " threads, 640 x 400");
}

// FLIP (frame/score.h, flipFigure: both shaded images tone mapped, the map, its mean over the
// hit pixels) of that frame against the reference's, on range(0) threads: the cost of scoring
// a frame perceptually.
void BM_Flip(benchmark::State& state) {
    static const Frame reference = renderFrame(smallSphereBox(), findTechnique("reference"), {});
    static const Frame test = renderFrame(smallSphereBox(), findTechnique("shadow-map"), {});
    const ImageChannels scored = scoredImage(reference);
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(flipFigure(reference.radiance, test.radiance, reference.gbuffer.width,
                                            reference.gbuffer.height, scored.at(channel::hit)));
    state.SetLabel(std::to_string(state.range(0)) + " threads, 640 x 400");
}

BENCHMARK(BM_VertexStage)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Setup)->Apply(simdLevels)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Binning)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterTiles)->Apply(simdLevels)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillRate)->Apply(fillRateSizes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShadowLookup)->Apply(lookupCases)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LightView)->Apply(simdLevels)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IrregularZBuffer)->DenseRange(1, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShadowMapFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Flip)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
// As the shadowlab program (app/main.cpp): freed memory is kept for reuse, so a frame's
// fresh buffers do not pay page faults in every timed run.
int main(int argc, char** argv) {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, -1);
    mallopt(M_MMAP_MAX, 0);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
