// What sweep and merge-sweep share, as they write the same files: --out and --plot-y, and
// the sweep's table on stdout with STEM.csv, .json and .svg in the folder.
#pragma once

#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "app/measure/sweep.h"
#include "app/plots/sweep_plot.h"

namespace shadowlab {

void addSweepFileOptions(CLI::App* cmd, std::string& outDir, std::string& plotY);

void writeSweepFiles(const SweepResults& results, const std::filesystem::path& outDir, PlotErrorAxis plotY);

}  // namespace shadowlab
