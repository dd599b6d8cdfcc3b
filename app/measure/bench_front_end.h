// `shadowlab bench`'s front-end table: the rasterizer's set-up and binning timed against a
// floor of our own making, in triangles per second per core: no one publishes a per-core
// set-up and binning figure to compare with.
//
// The floor is the least a front end can do on this machine: per triangle, read its three
// window vertices (the vertex stage's output) and write one 8-byte bin entry, split into
// chunks across the threads exactly as the rasterizer splits a draw
// (Rasterizer::kChunkTriangles, kChunksPerBatch). The stages are the rasterizer's own draw
// stopped after a stage (DrawStage), so they run the same chunks on the same threads; a
// stage's time is the difference of two such draws' medians (set-up: through set-up minus
// through the vertex stage), and the light pass is the whole draw. Per core, two ways:
// triangles / (median seconds x threads), so perfect scaling keeps the figure; and
// triangles / the process's median CPU seconds per run (CLOCK_PROCESS_CPUTIME_ID), which a
// machine shared with other work does not inflate by the time the scheduler gave away
// (idle TBB workers spinning between a draw's parallel loops count as CPU).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/common/timing.h"
#include "raster/pipeline_state.h"
#include "raster/tile_kernels.h"
#include "scenes/scene.h"

namespace shadowlab {

struct FrontEndTiming {
    std::string scene, stage;   // "floor", "vertex stage", "set-up", "binning", "set-up + binning", "light pass"
    int threads = 1;
    size_t triangles = 0;
    double medianMs = 0.0;
    double cpuMs = 0.0;   // median process CPU time of a run, every thread's summed
    double mtrisPerSecondPerCore() const { return double(triangles) / (medianMs * 1e3 * threads); }
    double mtrisPerCpuSecond() const { return double(triangles) / (cpuMs * 1e3); }
};

// Times the time-able pieces with `time` (warm-up and measured runs, the caller's protocol)
// on the current thread count and returns the table's rows, floor first; the caller sets
// each row's scene and thread count.
std::vector<FrontEndTiming> timeFrontEnd(const WorldGeometry& world, const glm::mat4& clipFromWorld, int size,
                                         const raster::PipelineState& state, raster::SimdLevel simd,
                                         const std::function<Timing(const std::function<void()>&)>& time);

}  // namespace shadowlab
