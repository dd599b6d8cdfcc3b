// `shadowlab bench`: the speed of the depth-only passes every shadow technique is built
// from, on the built-in scenes, and of the exact reference's shadow rays.
//
// Protocol (style.md, "benchmarks are repeatable protocols"): fixed scenes and cameras,
// warm-up runs first, then `runs` measured runs; the median and the minimum are reported.
// A pass is a depth clear plus one depth-only draw of every triangle with back faces culled;
// the light's pass is also timed as the shadow-map technique draws its map: both facings
// (no culling) and the default slope-scaled polygon offset (shadows/maps/shadow_bias.h).
// The rays are timed with the Embree BVH built once, and built anew in every run. The
// front-end table (bench_front_end.h) times the light pass with both facings stage by stage
// against its floor.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/measure/bench_front_end.h"
#include "raster/rasterizer.h"
#include "scenes/scene.h"
#include "shadows/progress.h"

namespace shadowlab {

struct PassTiming {
    std::string scene, pass;   // pass: "light 2048x2048", "light 2048x2048 both facings" or "camera 1280x800"
    int threads = 1;
    std::string simd;
    size_t triangles = 0, pixels = 0;
    raster::RasterStats stats;   // of one run: how many triangles each stage kept
    double medianMs = 0.0, minMs = 0.0;
    double mtrisPerSecond() const { return double(triangles) / (medianMs * 1e3); }
    double mpixelsPerSecond() const { return double(pixels) / (medianMs * 1e3); }
};

struct RayTiming {
    std::string scene;
    std::string bvh = "built once";   // or "built per run": the BVH's construction is in the time
    int threads = 1;
    uint64_t rays = 0;
    double medianMs = 0.0, minMs = 0.0;
    double mraysPerSecond() const { return double(rays) / (medianMs * 1e3); }
};

struct BenchOptions {
    std::vector<std::string> scenes = {"sphere-box", "bunny", "throughput"};
    std::vector<int> threads = {1, 2};
    std::vector<std::string> parts = {"passes", "front-end", "rays"};   // the tables to measure
    int warmupRuns = 2;
    int runs = 15;
    raster::SimdLevel simd = raster::bestSimdLevel();
    Progress* progress = nullptr;   // reports the runs done, warm-up ones included
};

// The floor under a light pass: filling a 2048 x 2048 float buffer with one value, rows in
// parallel, the least any depth pass of that size writes (its clear alone).
struct FloorTiming {
    int threads = 1;
    double medianMs = 0.0, minMs = 0.0;
};

struct BenchResults {
    std::vector<PassTiming> passes;
    std::vector<RayTiming> rays;
    std::vector<FloorTiming> floors;   // one per thread count
    std::vector<FrontEndTiming> frontEnd;
};

// The light pass's matrix: the scene's first light looking at the origin, perspective with
// fovy 90 degrees, near 0.5, far 50: one fixed protocol, so rows compare across scenes and
// runs (and with the peer benchmark, bench/peers).
glm::mat4 lightClipFromWorld(const Scene& scene);

BenchResults runBench(const BenchOptions& options);
std::string formatBenchText(const BenchResults& results);
std::string formatBenchJson(const BenchResults& results);

}  // namespace shadowlab
