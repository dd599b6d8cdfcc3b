// `shadowlab sweep`: speed against error over a grid of technique settings.
//
// Each --param axis gives one parameter several values; every technique runs the cross
// product of the axes it has (an axis a technique lacks does not multiply its runs), at
// every thread count. Protocol as in `bench`: warm-up frames, then `runs` measured frames,
// of which the median and minimum of Frame::techniqueMs (the technique alone, not the
// G-buffer or shading) are kept. Each reference the techniques name (Technique::
// referenceName: `reference` or `reference-soft`) is rendered once per sweep; every
// setting's visibility is scored against its technique's (conventions.md, "Figures and
// errors").
#pragma once

#include <map>
#include <string>
#include <vector>

#include "app/timing.h"
#include "frame/render.h"
#include "raster/rasterizer.h"
#include "shading/compare.h"
#include "shadows/progress.h"
#include "shadows/technique.h"

namespace shadowlab {

struct SweepAxis {
    std::string name;
    std::vector<std::string> values;
};

// "name=v1,v2,v3" -> axis; throws std::invalid_argument without a name or with an empty value.
SweepAxis parseSweepAxis(const std::string& text);

struct SweepOptions {
    std::string scene;                      // built-in name or .json path
    SceneOverrides overrides;               // e.g. the light's position and radius
    std::string reference;                  // scores every technique against it; empty: each its own referenceName
    std::vector<const Technique*> techniques;   // from findTechnique(), or a test's own
    std::vector<SweepAxis> axes;
    std::vector<int> threads;               // empty: all cores only
    int warmupRuns = 1;
    int runs = 5;
    raster::SimdLevel simd = raster::bestSimdLevel();
    Progress* progress = nullptr;           // reports the frames done (and the references' rows)
};

struct SweepRow {
    std::string technique;
    std::string reference;                         // the technique it was scored against
    std::map<std::string, std::string> settings;   // this row's axis values (not defaults)
    int threads = 1;
    double medianMs = 0.0, minMs = 0.0;
    ErrorFigures errors;
    std::vector<TechniqueStat> stats;              // of the last measured frame
    std::string settingsLabel() const;             // "a=1 b=2", or "defaults"
};

struct SweepResults {
    std::string scene;
    std::vector<std::string> techniques;   // in the order given
    std::vector<SweepRow> rows;   // per technique, settings in axis order (last axis fastest), threads
};

// The measurement protocol shared with `shadowlab scaling`: warm-up frames, then `runs`
// measured frames; the median and minimum of Frame::techniqueMs, and the last frame. Every
// frame, warm-up ones included, is counted in `frames`.
struct TimedFrames {
    Timing timing;
    Frame last;
};
TimedFrames timeFrames(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings,
                       int warmupRuns, int runs, const ProgressStage& frames);

// Checks the technique names and that every axis belongs to one of them, then renders one
// frame per setting (a value a technique rejects fails there, before any measurement);
// throws std::invalid_argument (or SceneError for the scene).
SweepResults runSweep(const SweepOptions& options);

// The output file stem: "<scene>-<technique>[+<technique>...]".
std::string sweepFileStem(const SweepResults& results);

// A table for the terminal: one line per row.
std::string formatSweepText(const SweepResults& results);
// One row per SweepRow. CSV columns: technique, settings, threads, median_ms, min_ms, rms,
// mean_abs, max_abs, misclassified_percent, false_shadow_percent, false_light_percent,
// umbra_lit_percent, umbra_over_percent, lit_shadowed_percent, reference, then one column per technique stat
// (empty where a row does not report it).
std::string formatSweepCsv(const SweepResults& results);
// CSV helpers shared with `shadowlab scaling`: one RFC 4180 line (fields with a comma,
// quote or line break quoted), and a number with 9 significant digits.
std::string csvLine(const std::vector<std::string>& fields);
std::string csvNumber(double value);

}  // namespace shadowlab
