// `shadowlab merge-sweep`: the JSON files of a sweep's shards (sweep --shard) joined into
// the files of the whole sweep (app/measure/sweep_merge.h).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/sweep_files.h"
#include "app/common/output_files.h"
#include "app/measure/sweep_json.h"
#include "app/measure/sweep_merge.h"
#include "frame/frame_images.h"
#include "scenes/read_file.h"

namespace shadowlab {
namespace {

struct MergeSweepArgs {
    std::vector<std::string> shards;
    std::string outDir = "out", plotY = "auto";
};

void runMergeSweepCommand(const MergeSweepArgs& a) {
    const PlotErrorAxis plotY = parsePlotErrorAxis(a.plotY);
    std::vector<SweepShardFile> files;
    for (const std::string& path : a.shards) {
        SweepResults shard = parseSweepJson(readWholeFile(path), path);
        // The pictures' paths are relative to each shard's JSON; the merged JSON goes to --out.
        const std::filesystem::path directory = std::filesystem::path(path).parent_path();
        for (SweepRow& row : shard.rows) row.images = rebased(row.images, directory, a.outDir);
        files.push_back({path, std::move(shard)});
    }
    const SweepResults merged = mergeSweepShards(files);
    StagedOutputs outputs(a.outDir);
    writeSweepFiles(merged, outputs.folder(), plotY);
    commitAndList(outputs);
}

}  // namespace

void addMergeSweepCommand(CLI::App& command) {
    MergeSweepArgs& a = argumentsRunBy<MergeSweepArgs>(command, runMergeSweepCommand);
    CLI::App* m = command.description("join the JSON files of a sweep's shards (sweep --shard) into the sweep's CSV, JSON and SVG plot");
    m->add_option("shards", a.shards, "the JSON file of every shard, SCENE-TECHNIQUES-shard-I-of-N.json")->required();
    addSweepFileOptions(m, a.outDir, a.plotY);
}

}  // namespace shadowlab
