#include "app/measure/bench_front_end.h"

#include <algorithm>
#include <cstdint>
#include <ctime>

#include <tbb/parallel_for.h>

#include "raster/fixed_point.h"
#include "raster/rasterizer.h"
#include "raster/vertex_stage.h"

namespace shadowlab {
namespace {

using raster::Rasterizer;

// The floor's bin entry: the tile of the triangle's smallest corner coordinates beside its
// index, so each of the three window vertices is read and the entry depends on them all.
uint64_t floorEntry(const raster::WindowVertex& a, const raster::WindowVertex& b, const raster::WindowVertex& c,
                    size_t index) {
    constexpr int shift = raster::kSubpixelBits + raster::kTileShift;
    const uint64_t tileX = uint32_t(std::min({a.x, b.x, c.x}) >> shift) & 0xffffu;
    const uint64_t tileY = uint32_t(std::min({a.y, b.y, c.y}) >> shift) & 0xffffu;
    return tileY << 48 | tileX << 32 | uint32_t(index);
}

// One floor run: the draw's batches, each batch's chunks in parallel, one entry per triangle.
void runFloor(const WorldGeometry& world, const raster::TransformedVertices& v, std::vector<uint64_t>& entries) {
    constexpr size_t batch = Rasterizer::kChunkTriangles * Rasterizer::kChunksPerBatch;
    const size_t n = world.triangles.size();
    for (size_t first = 0; first < n; first += batch) {
        const size_t count = std::min(batch, n - first);
        const size_t chunks = (count + Rasterizer::kChunkTriangles - 1) / Rasterizer::kChunkTriangles;
        tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
            const size_t begin = first + c * Rasterizer::kChunkTriangles;
            const size_t end = std::min(begin + Rasterizer::kChunkTriangles, first + count);
            for (size_t i = begin; i < end; ++i) {
                const glm::uvec3& t = world.triangles[i];
                entries[i - first] = floorEntry(v.window[t.x], v.window[t.y], v.window[t.z], i);
            }
        });
    }
}

double cpuMsNow() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// What one piece costs: `time`'s median wall time, and the median CPU time of its runs
// (warm-up runs included).
struct Cost {
    double wallMs = 0.0, cpuMs = 0.0;
};

Cost costOf(const std::function<Timing(const std::function<void()>&)>& time,
           const std::function<void()>& run) {
    std::vector<double> cpu;
    const double wall = time([&] {
                            const double start = cpuMsNow();
                            run();
                            cpu.push_back(cpuMsNow() - start);
                        }).medianMs;
    return {wall, summarizeTimes(std::move(cpu)).medianMs};
}

}  // namespace

std::vector<FrontEndTiming> timeFrontEnd(const WorldGeometry& world, const glm::mat4& clipFromWorld, int size,
                                         const raster::PipelineState& state, raster::SimdLevel simd,
                                         const std::function<Timing(const std::function<void()>&)>& time) {
    const raster::Viewport viewport{size, size, raster::clipVolumeFor(size, size, state.clipFar)};
    raster::TransformedVertices vertices;
    raster::transformVertices(std::span<const glm::vec3>(world.positions), clipFromWorld, viewport, vertices);
    std::vector<uint64_t> entries(Rasterizer::kChunkTriangles * Rasterizer::kChunksPerBatch);
    const Cost floor = costOf(time, [&] { runFloor(world, vertices, entries); });

    raster::Framebuffer fb(size, size);
    Rasterizer rasterizer(simd);
    const raster::DrawCall call = raster::positionsDraw(world.positions, world.triangles, clipFromWorld);
    Cost through[4];   // of the draw through each DrawStage
    for (raster::DrawStage stage : {raster::DrawStage::Vertices, raster::DrawStage::Setup, raster::DrawStage::Binning,
                                    raster::DrawStage::Tiles}) {
        through[int(stage)] = costOf(time, [&] {
            if (stage == raster::DrawStage::Tiles) fb.clearDepth(1.0f);
            rasterizer.draw(fb, state, call, stage);
        });
    }
    std::vector<FrontEndTiming> rows;
    // A stage costs the draw through it less the draw through the stage before.
    const auto row = [&](const char* stage, const Cost& to, const Cost& from) {
        rows.push_back({"", stage, 1, world.triangles.size(), to.wallMs - from.wallMs, to.cpuMs - from.cpuMs});
    };
    row("floor", floor, {});
    row("vertex stage", through[0], {});
    row("set-up", through[1], through[0]);
    row("binning", through[2], through[1]);
    row("set-up + binning", through[2], through[0]);
    row("light pass", through[3], {});
    return rows;
}

}  // namespace shadowlab
