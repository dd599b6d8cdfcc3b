#include "app/measure/bench_passes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>

#include "app/common/timing.h"
#include "frame/render.h"
#include "raster/rasterizer.h"
#include "raster/thread_count.h"
#include "scenes/camera.h"
#include "scenes/scene_file.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/reference/reference.h"

namespace shadowlab {
namespace {

bool measures(const BenchOptions& options, const char* part) {
    return std::find(options.parts.begin(), options.parts.end(), part) != options.parts.end();
}

// Timed rows per scene and thread count: the light's pass culled and with both facings and
// the camera's pass; the front end's floor and four draws; the rays with the BVH built once
// and built in every run.
uint64_t rowsPerSceneAndThreads(const BenchOptions& options) {
    return (measures(options, "passes") ? 3 : 0) + (measures(options, "front-end") ? 5 : 0) + (measures(options, "rays") ? 2 : 0);
}

Timing timeRuns(const BenchOptions& options, const ProgressStage& runs, const std::function<void()>& run) {
    for (int k = 0; k < options.warmupRuns; ++k) {
        run();
        runs.advance();
    }
    std::vector<double> ms;
    for (int k = 0; k < options.runs; ++k) {
        const auto start = std::chrono::steady_clock::now();
        run();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        runs.advance();
    }
    return summarizeTimes(std::move(ms));
}

// The state of a pass: depth-only, less, back faces culled unless `shadowMapState`, which
// draws as the shadow-map technique draws its map: no culling, the default polygon offset.
raster::PipelineState depthPassState(bool shadowMapState) {
    raster::PipelineState state;
    if (shadowMapState) {
        state.cull = raster::CullMode::None;
        state.offset = polygonOffsetFor(BiasSettings{});
    }
    return state;
}

PassTiming timeDepthPass(const BenchOptions& options, const ProgressStage& runs, const WorldGeometry& world,
                         const glm::mat4& clipFromWorld, int width, int height, bool shadowMapState = false) {
    raster::Framebuffer fb(width, height);
    raster::Rasterizer rasterizer(options.simd);
    const raster::PipelineState state = depthPassState(shadowMapState);
    const raster::DrawCall call = raster::positionsDraw(world.positions, world.triangles, clipFromWorld);
    const Timing t = timeRuns(options, runs, [&] {
        fb.clearDepth(1.0f);
        rasterizer.draw(fb, state, call);
    });
    PassTiming row;
    rasterizer.resetStats();
    rasterizer.draw(fb, state, call);
    row.stats = rasterizer.stats();
    row.simd = raster::simdLevelName(options.simd);
    row.triangles = world.triangles.size();
    row.pixels = size_t(width) * size_t(height);
    row.medianMs = t.medianMs;
    row.minMs = t.minMs;
    return row;
}

// One shadow ray per G-buffer pixel to the first light, with the BVH built once before the
// runs or, with `buildEachRun`, in every run, as for geometry that changes every frame (the
// time is then the construction plus the rays).
RayTiming timeReference(const BenchOptions& options, const ProgressStage& runs, const Scene& scene,
                        const WorldGeometry& world, const GBuffer& gbuffer, bool buildEachRun) {
    const Light light = pointLightFor(scene.lights.at(0));
    const CasterTransmission transmission(scene, world);
    std::optional<ReferenceVisibility> once;
    if (!buildEachRun) once.emplace(world, &transmission);
    uint64_t raysPerRun = 0;
    const Timing t = timeRuns(options, runs, [&] {
        std::optional<ReferenceVisibility> perRun;
        const ReferenceVisibility& reference = buildEachRun ? perRun.emplace(world, &transmission) : *once;
        const uint64_t before = reference.raysCast();
        reference.visibility(gbuffer, light);
        raysPerRun = reference.raysCast() - before;
    });
    return {scene.name, buildEachRun ? "built per run" : "built once", 1, raysPerRun, t.medianMs, t.minMs};
}

FloorTiming timeFloor(const BenchOptions& options, const ProgressStage& runs) {
    constexpr int kSize = 2048;
    std::vector<float> buffer(size_t(kSize) * kSize);
    const Timing t = timeRuns(options, runs, [&] {
        tbb::parallel_for(0, kSize, [&](int row) {
            std::fill_n(buffer.begin() + ptrdiff_t(row) * kSize, kSize, 1.0f);
        });
    });
    return {1, t.medianMs, t.minMs};
}

// The floor of a row's thread count, 0 if it was not measured.
double floorMs(const BenchResults& r, int threads) {
    for (const FloorTiming& f : r.floors)
        if (f.threads == threads) return f.medianMs;
    return 0.0;
}

// The light's pass culled and with both facings, and the camera's pass.
void timePasses(const BenchOptions& options, const ProgressStage& runs, const Scene& scene, const WorldGeometry& world,
                int threads, BenchResults& results) {
    PassTiming light = timeDepthPass(options, runs, world, lightClipFromWorld(scene), 2048, 2048);
    light.scene = scene.name, light.pass = "light 2048x2048", light.threads = threads;
    results.passes.push_back(light);
    PassTiming both = timeDepthPass(options, runs, world, lightClipFromWorld(scene), 2048, 2048, true);
    both.scene = scene.name, both.pass = "light 2048x2048 both facings", both.threads = threads;
    results.passes.push_back(both);
    PassTiming camera = timeDepthPass(options, runs, world, clipFromWorld(scene.camera), scene.camera.width, scene.camera.height);
    camera.scene = scene.name, camera.threads = threads;
    camera.pass = "camera " + std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height);
    results.passes.push_back(camera);
}

// The front-end table: each stage's median, per core, and against the floor of its scene
// and thread count.
std::string formatFrontEndText(const BenchResults& r) {
    if (r.frontEnd.empty()) return "";
    std::string out = "\nfront end of the light pass 2048x2048 both facings; per core: triangles / (median s x threads),"
                      " and triangles / median CPU s\n";
    char line[256];
    std::snprintf(line, sizeof line, "%-11s %-18s %7s %10s %10s %13s %8s %10s %13s %8s\n", "scene", "stage", "threads",
                  "triangles", "median ms", "Mtris/s/core", "x floor", "CPU ms", "Mtris/CPU s", "x floor");
    out += line;
    const FrontEndTiming* floor = nullptr;
    for (const FrontEndTiming& f : r.frontEnd) {
        if (f.stage == "floor") floor = &f;
        std::snprintf(line, sizeof line, "%-11s %-18s %7d %10zu %10.2f %13.1f %8.1f %10.2f %13.1f %8.1f\n", f.scene.c_str(),
                      f.stage.c_str(), f.threads, f.triangles, f.medianMs, f.mtrisPerSecondPerCore(),
                      f.medianMs / floor->medianMs, f.cpuMs, f.mtrisPerCpuSecond(), f.cpuMs / floor->cpuMs);
        out += line;
    }
    return out;
}

}  // namespace

glm::mat4 lightClipFromWorld(const Scene& scene) {
    const glm::vec3 light = scene.lights.at(0).position;
    const glm::vec3 toOrigin = glm::normalize(-light);
    const glm::vec3 up = std::abs(toOrigin.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::perspective(glm::radians(90.0f), 1.0f, 0.5f, 50.0f) * glm::lookAt(light, glm::vec3(0.0f), up);
}

BenchResults runBench(const BenchOptions& options) {
    BenchResults results;
    const bool passes = measures(options, "passes");
    const uint64_t rows = (options.scenes.size() * rowsPerSceneAndThreads(options) + (passes ? 1 : 0)) * options.threads.size();
    const ProgressStage runs(options.progress, "bench: run", rows * uint64_t(options.warmupRuns + options.runs));
    for (int threads : options.threads) {
        if (!passes) break;
        FloorTiming floor = withThreads(threads, [&] { return timeFloor(options, runs); });
        floor.threads = threads;
        results.floors.push_back(floor);
    }
    for (const std::string& name : options.scenes) {
        const Scene scene = loadScene(name);
        const WorldGeometry world = flatten(scene);
        for (int threads : options.threads) {
            withThreads(threads, [&] {
                if (passes) timePasses(options, runs, scene, world, threads, results);
                if (measures(options, "front-end")) {
                    const auto time = [&](const std::function<void()>& run) { return timeRuns(options, runs, run); };
                    for (FrontEndTiming row : timeFrontEnd(world, lightClipFromWorld(scene), 2048, depthPassState(true),
                                                           options.simd, time)) {
                        row.scene = name, row.threads = threads;
                        results.frontEnd.push_back(row);
                    }
                }
                if (!measures(options, "rays")) return;
                const GBuffer gbuffer = renderGBuffer(world, scene.camera, options.simd);
                for (bool buildEachRun : {false, true}) {
                    RayTiming rays = timeReference(options, runs, scene, world, gbuffer, buildEachRun);
                    rays.threads = threads;
                    results.rays.push_back(rays);
                }
            });
        }
    }
    return results;
}

std::string formatBenchText(const BenchResults& r) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-11s %-30s %7s %6s %10s %10s %9s %9s %9s %10s %10s\n", "scene", "pass", "threads",
                  "simd", "triangles", "median ms", "min ms", "Mtris/s", "Mpix/s", "set up", "tile pairs");
    if (!r.passes.empty()) out += line;
    for (const PassTiming& p : r.passes) {
        std::snprintf(line, sizeof line, "%-11s %-30s %7d %6s %10zu %10.2f %9.2f %9.1f %9.1f %10llu %10llu\n",
                      p.scene.c_str(), p.pass.c_str(), p.threads, p.simd.c_str(), p.triangles, p.medianMs, p.minMs,
                      p.mtrisPerSecond(), p.mpixelsPerSecond(), static_cast<unsigned long long>(p.stats.trianglesSetUp),
                      static_cast<unsigned long long>(p.stats.binEntries));
        out += line;
    }
    for (const PassTiming& p : r.passes) {
        if (p.pass.rfind("light", 0) != 0 || floorMs(r, p.threads) <= 0.0) continue;
        std::snprintf(line, sizeof line, "%-11s %-30s %7d  %.1f x the floor\n", p.scene.c_str(), p.pass.c_str(), p.threads,
                      p.medianMs / floorMs(r, p.threads));
        out += line;
    }
    for (const FloorTiming& f : r.floors) {
        std::snprintf(line, sizeof line, "floor: fill 2048x2048 floats, %d threads: %.2f ms (min %.2f)\n", f.threads,
                      f.medianMs, f.minMs);
        out += line;
    }
    out += formatFrontEndText(r);
    if (r.rays.empty()) return out;
    std::snprintf(line, sizeof line, "\n%-11s %-14s %7s %10s %10s %9s %9s\n", "scene", "bvh", "threads", "rays", "median ms", "min ms",
                  "Mrays/s");
    out += line;
    for (const RayTiming& t : r.rays) {
        std::snprintf(line, sizeof line, "%-11s %-14s %7d %10llu %10.2f %9.2f %9.2f\n", t.scene.c_str(), t.bvh.c_str(), t.threads,
                      static_cast<unsigned long long>(t.rays), t.medianMs, t.minMs, t.mraysPerSecond());
        out += line;
    }
    return out;
}

std::string formatBenchJson(const BenchResults& r) {
    nlohmann::json j;
    j["passes"] = nlohmann::json::array();
    for (const PassTiming& p : r.passes) {
        j["passes"].push_back({{"scene", p.scene}, {"pass", p.pass}, {"threads", p.threads}, {"simd", p.simd},
                               {"triangles", p.triangles}, {"pixels", p.pixels}, {"median_ms", p.medianMs},
                               {"min_ms", p.minMs}, {"mtris_per_s", p.mtrisPerSecond()},
                               {"mpixels_per_s", p.mpixelsPerSecond()},
                               {"triangles_set_up", p.stats.trianglesSetUp}, {"triangles_clipped", p.stats.trianglesClipped},
                               {"tile_pairs", p.stats.binEntries}});
    }
    j["reference"] = nlohmann::json::array();
    for (const RayTiming& t : r.rays) {
        j["reference"].push_back({{"scene", t.scene}, {"bvh", t.bvh}, {"threads", t.threads}, {"rays", t.rays},
                                  {"median_ms", t.medianMs}, {"min_ms", t.minMs}, {"mrays_per_s", t.mraysPerSecond()}});
    }
    j["front_end"] = nlohmann::json::array();
    for (const FrontEndTiming& f : r.frontEnd) {
        j["front_end"].push_back({{"scene", f.scene}, {"stage", f.stage}, {"threads", f.threads}, {"triangles", f.triangles},
                                  {"median_ms", f.medianMs}, {"mtris_per_s_per_core", f.mtrisPerSecondPerCore()},
                                  {"cpu_ms", f.cpuMs}, {"mtris_per_cpu_s", f.mtrisPerCpuSecond()}});
    }
    j["floor"] = nlohmann::json::array();
    for (const FloorTiming& f : r.floors) j["floor"].push_back({{"threads", f.threads}, {"median_ms", f.medianMs}, {"min_ms", f.minMs}});
    return j.dump(2) + "\n";
}

}  // namespace shadowlab
