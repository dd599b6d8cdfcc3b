// shadowlab_peers: the workloads of `shadowlab bench` and of the shadow-map and
// shadow-volume techniques, rendered by Mesa's llvmpipe (OpenGL 3.3 core, EGL surfaceless)
// from the same world-space triangles and the same matrices, so that shadowlab's times
// have a peer measured on the same machine. docs/peers.md defines each workload.
//
// Every workload is timed as the median (and minimum) wall time of `runs` frames after
// `warmup` frames; a frame ends with glFinish, so the time is the GPU work done, not queued.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench/peers/egl_context.h"
#include "bench/peers/workloads.h"
#include "scenes/scene_file.h"
#include "scenes/write_file.h"

namespace shadowlab::peers {
namespace {

std::string formatText(const std::vector<Row>& rows) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-11s %-24s %-9s %11s %10s %10s %9s\n", "scene", "workload", "peer", "size",
                  "triangles", "median ms", "min ms");
    out += line;
    for (const Row& r : rows) {
        const std::string size = r.width ? std::to_string(r.width) + "x" + std::to_string(r.height) : "-";
        std::snprintf(line, sizeof line, "%-11s %-24s %-9s %11s %10zu %10.2f %9.2f\n", r.scene.c_str(),
                      r.workload.c_str(), r.peer.c_str(), size.c_str(), r.triangles, r.medianMs, r.minMs);
        out += line;
    }
    return out;
}

std::string formatJson(const std::vector<Row>& rows, const Options& o, const EglContext& gl) {
    nlohmann::json j;
    j["renderer"] = gl.renderer();
    j["gl_version"] = gl.version();
    j["threads"] = o.threads;
    j["runs"] = o.runs;
    j["warmup"] = o.warmupRuns;
    j["rows"] = nlohmann::json::array();
    for (const Row& r : rows) {
        j["rows"].push_back({{"scene", r.scene}, {"workload", r.workload}, {"peer", r.peer}, {"width", r.width},
                             {"height", r.height}, {"triangles", r.triangles}, {"median_ms", r.medianMs},
                             {"min_ms", r.minMs}});
    }
    return j.dump(2) + "\n";
}

int run(const Options& o) {
    const EglContext gl(o.threads);   // sets LP_NUM_THREADS first
    std::fprintf(stderr, "shadowlab_peers: %s, %s, LP_NUM_THREADS=%d\n", gl.renderer().c_str(), gl.version().c_str(),
                 o.threads);
    const Programs programs;
    checkGl("programs");
    std::vector<Row> rows;
    for (const std::string& name : o.scenes) {
        Scene scene = loadScene(name);
        if (o.width > 0) scene.camera.width = o.width;
        if (o.height > 0) scene.camera.height = o.height;
        const PreparedScene prepared(std::move(scene));
        Workloads workloads(o, programs, prepared);
        for (Row& r : workloads.run()) rows.push_back(std::move(r));
    }
    std::fputs(formatText(rows).c_str(), stdout);
    if (!o.json.empty()) writeTextFile(o.json, formatJson(rows, o, gl));
    return 0;
}

}  // namespace
}  // namespace shadowlab::peers

int main(int argc, char** argv) {
    using namespace shadowlab::peers;
    Options o;
    CLI::App app("shadowlab's workloads on Mesa's llvmpipe (OpenGL 3.3 core, EGL surfaceless); docs/peers.md");
    app.add_option("--scenes", o.scenes, "scenes to render")->delimiter(',')->capture_default_str();
    app.add_option("--threads", o.threads, "llvmpipe threads (LP_NUM_THREADS)")->capture_default_str()->check(CLI::Range(1, 1024));
    app.add_option("--runs", o.runs, "measured frames per workload")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--warmup", o.warmupRuns, "warm-up frames per workload")->capture_default_str()->check(CLI::Range(0, 1000));
    app.add_option("--light-size", o.lightSize, "texels per side of the light's pass and map")->capture_default_str()->check(CLI::Range(16, 16384));
    app.add_option("--width", o.width, "camera width (default: the scene's)")->check(CLI::Range(1, 16384));
    app.add_option("--height", o.height, "camera height (default: the scene's)")->check(CLI::Range(1, 16384));
    app.add_option("--png", o.png, "PNG of the first scene's shadowed frame (1 tap); NAME-volumes.png for the volumes");
    app.add_option("--json", o.json, "also write the rows as JSON");
    app.add_flag("--check", o.check, "fail unless every pass's depth or colour holds more than one value");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shadowlab_peers: %s\n", e.what());
        return 1;
    }
}

