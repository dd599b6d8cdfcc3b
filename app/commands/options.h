// The options several commands share, written once so that they read alike everywhere:
// vectors as X,Y,Z, the image size and the first light, --simd, --progress, the timing
// protocol's --runs and --warmup, and the finite-number check on every floating-point
// option; and how a measuring command turns --progress and --simd into its settings.
#pragma once

#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "frame/render.h"
#include "raster/tile_kernels.h"
#include "shadows/progress.h"

namespace shadowlab {

void addVec3Option(CLI::App* cmd, const std::string& name, std::optional<glm::vec3>& target, const std::string& help);

// An option whose text is checked by what reads it: given, even as '', or not given, so that
// an empty value reaches the check instead of being taken for a missing one.
void addOptionalText(CLI::App* cmd, const std::string& name, std::optional<std::string>& target, const std::string& help);

// --width and --height of render, sweep and flythrough; applyOverrides() applies them.
void addSizeOptions(CLI::App* cmd, SceneOverrides& overrides);

// --light N, the one light of the scene a frame shadows and shades (render, sweep,
// flythrough); applyOverrides() checks it.
void addLightSelection(CLI::App* cmd, SceneOverrides& overrides);

// --light, --light-pos and --light-radius, shared by render and sweep; applyOverrides() checks them.
void addLightOptions(CLI::App* cmd, SceneOverrides& overrides);

void addSimdOption(CLI::App* cmd, std::string& simd);

// On every command whose work can take long: render (the exact references), sweep,
// scaling and bench.
void addProgressFlag(CLI::App* cmd, bool& progress);

// --runs, --warmup and --simd of the timing commands (sweep, scaling, bench); `unit` says
// what is repeated, e.g. "frames per row". Their --threads differ (a list, or one count).
void addTimingOptions(CLI::App* cmd, const std::string& unit, int& runs, int& warmupRuns, std::string& simd);

// Every floating-point option of every command must be a finite number: CLI11's Range lets
// NaN through (it compares false both ways) and an infinity past a one-sided bound, and a NaN
// exposure or rotation became a black image or a crash. The check goes on each option CLI11
// reads as FLOAT (one value or a list, each value checked), so a new option cannot miss it.
void requireFiniteFloats(CLI::App& app);

// The progress line is for a person watching: it goes to stderr (tools read stdout), and
// only if stderr is a terminal or --progress asks for it.
Progress* progressIfWanted(Progress& progress, bool asked);

// What every measuring command (sweep, flythrough, scaling, bench) sets alike on its
// options, for as long as this lives: the progress line, if wanted, and the SIMD level.
// Made after the techniques are looked up, so that a wrong name is reported before a
// wrong --simd.
class MeasuringRun {
public:
    template <class Options>
    MeasuringRun(Options& options, const std::string& simd, bool progressAsked) : progress_(std::cerr) {
        options.progress = progressIfWanted(progress_, progressAsked);
        options.simd = raster::parseSimdLevel(simd);
    }

private:
    Progress progress_;
};

}  // namespace shadowlab
