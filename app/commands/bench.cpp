// `shadowlab bench`: the depth-only passes and the reference's rays timed on the built-in
// scenes (app/measure/bench_passes.h).
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/options.h"
#include "app/common/output_files.h"
#include "app/measure/bench_passes.h"
#include "raster/thread_count.h"
#include "scenes/write_file.h"

namespace shadowlab {
namespace {

struct BenchArgs {
    BenchOptions options;
    std::string simd = "auto", json;
    bool progress = false;
};

void runBenchCommand(BenchArgs a) {
    const MeasuringRun run(a.options, a.simd, a.progress);
    requireOutputDirectories({&a.json});   // before the runs, not after them
    const BenchResults results = runBench(a.options);
    std::cout << formatBenchText(results);
    if (!a.json.empty()) writeTextFile(a.json, formatBenchJson(results));
}

}  // namespace

void addBenchCommand(CLI::App& command) {
    BenchArgs& a = argumentsRunBy<BenchArgs>(command, runBenchCommand);
    CLI::App* b = command.description("time depth-only passes and reference rays on the built-in scenes");
    b->add_option("--scenes", a.options.scenes, "scenes to measure")->delimiter(',')->capture_default_str();
    b->add_option("--parts", a.options.parts, "tables to measure")
        ->delimiter(',')
        ->capture_default_str()
        ->check(CLI::IsMember({"passes", "front-end", "rays"}));
    b->add_option("--threads", a.options.threads, "thread counts")->delimiter(',')->capture_default_str()->check(CLI::Range(1, kMaxThreads));
    addTimingOptions(b, "runs per row", a.options.runs, a.options.warmupRuns, a.simd);
    b->add_option("--json", a.json, "also write the rows as JSON");
    addProgressFlag(b, a.progress);
}

}  // namespace shadowlab
