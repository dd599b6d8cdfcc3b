// `shadowlab compare`: the error figures of a test image against a reference, both EXR
// (docs/conventions.md), FLIP of their shaded images where both have R, G and B, and a heat
// map of their difference.
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/common/output_files.h"
#include "frame/score.h"
#include "scenes/write_file.h"
#include "shading/compare.h"
#include "shading/image_io.h"

namespace shadowlab {
namespace {

struct CompareArgs {
    std::string reference, test, channel = "V", heatmap, json;
};

void runCompare(const CompareArgs& a) {
    CompareOptions options;
    options.channel = a.channel;
    requireOutputDirectories({&a.heatmap, &a.json});
    const ImageChannels reference = readExr(a.reference), test = readExr(a.test);
    ErrorFigures figures = compareImages(reference, test, options);
    const auto referenceShaded = radianceOf(reference), testShaded = radianceOf(test);
    if (referenceShaded && testShaded)
        figures.flipMean =
            flipFigure(*referenceShaded, *testShaded, reference.width, reference.height, reference.at(channel::hit));
    std::cout << formatText(figures);
    const std::string heatmap = a.heatmap.empty() ? std::filesystem::path(a.test).replace_extension("").string() + "-diff.png" : a.heatmap;
    writePng(heatmap, reference.width, reference.height, errorHeatMap(reference, test, options));
    std::cout << "heat map: " << heatmap << "\n";
    if (!a.json.empty()) writeTextFile(a.json, formatJson(figures));
}

}  // namespace

void addCompareCommand(CLI::App& command) {
    CompareArgs& a = argumentsRunBy<CompareArgs>(command, runCompare);
    CLI::App* c = command.description("error figures of a test image against a reference (conventions.md)");
    c->add_option("reference", a.reference, "reference EXR (its hit channel selects the pixels)")->required()->check(CLI::ExistingFile);
    c->add_option("test", a.test, "EXR to score")->required()->check(CLI::ExistingFile);
    c->add_option("--channel", a.channel, "channel to compare")->capture_default_str();
    c->add_option("--heatmap", a.heatmap, "diff heat-map PNG (default: TEST-diff.png)");
    c->add_option("--json", a.json, "also write the figures as JSON");
}

}  // namespace shadowlab
