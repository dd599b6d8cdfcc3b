#include "app/commands/sweep_files.h"

#include <iostream>

#include "app/common/output_files.h"
#include "app/measure/sweep_json.h"

namespace shadowlab {

void addSweepFileOptions(CLI::App* cmd, std::string& outDir, std::string& plotY) {
    cmd->add_option("--out", outDir, "directory for SCENE-TECHNIQUES.csv, .json and .svg")->capture_default_str();
    cmd->add_option("--plot-y", plotY,
                    "plot's error axis: auto (rms if every row is scored against a soft reference or on luminance, "
                    "else misclassified), misclassified (%), rms, umbra (umbra errors, %), rms-display (shaded "
                    "images as displayed) or flip (FLIP of the shaded images)")->capture_default_str();
}

void writeSweepFiles(const SweepResults& results, const std::filesystem::path& outDir, PlotErrorAxis plotY) {
    requirePlottable(results.rows, plotY);
    std::cout << formatSweepText(results);
    writeCsvJsonSvg(outDir / sweepFileStem(results), formatSweepCsv(results), formatSweepJson(results),
                    formatSweepSvg(results, plotY));
}

}  // namespace shadowlab
