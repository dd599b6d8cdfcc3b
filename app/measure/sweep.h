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
//
// A sweep may run as shards on many machines (--shard i/n, docs/commands.md, "A sweep on a cluster"): shard i
// runs the settings whose index k in the sweep's fixed order has k mod n == i - 1, each at
// every thread count, and renders the references itself; sweep_merge.h joins the
// shards' JSON into the results of the unsharded run.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/measure/sweep_plan.h"
#include "frame/frame_images.h"
#include "frame/render.h"
#include "raster/rasterizer.h"
#include "shading/compare.h"
#include "shading/image_io.h"
#include "shadows/progress.h"
#include "shadows/technique.h"

namespace shadowlab {

// One of `count` parts of a sweep. index counts from 1, as SLURM_ARRAY_TASK_ID does for
// a job array submitted with --array=1-count; 1 of 1 is the whole sweep.
struct SweepShard {
    int index = 1, count = 1;
    bool valid() const { return count >= 1 && index >= 1 && index <= count; }
    std::string name() const { return std::to_string(index) + "/" + std::to_string(count); }
    bool holds(uint64_t setting) const { return setting % uint64_t(count) == uint64_t(index - 1); }
    // How many of a sweep's `settings` this shard holds.
    uint64_t heldOf(uint64_t settings) const {
        return settings / uint64_t(count) + (uint64_t(index - 1) < settings % uint64_t(count) ? 1 : 0);
    }
};

// "i/n" with 1 <= i <= n -> shard; throws std::invalid_argument for anything else.
SweepShard parseSweepShard(const std::string& text);

// Throws std::invalid_argument unless a sweep of `settings` settings splits into `count`
// shards that each hold one (1 <= count <= settings): a shard without any is a mistake in
// the count, and merge-sweep would wait for its file.
void checkShardCount(int64_t count, uint64_t settings);

// The most measured and warm-up frames per row: the bounds of `--runs` and `--warmup`, to
// which a sweep's JSON is held when read back.
inline constexpr int kMaxRuns = 10000, kMaxWarmupRuns = 1000;

// The thread counts and runs a sweep takes (`--threads`, `--runs`, `--warmup`), to which its
// JSON is held when read back: each count within 1..kMaxThreads and given once, runs within
// 1..kMaxRuns, warm-up runs within 0..kMaxWarmupRuns. The first count that breaks the rule
// (out of range, or a repeat), if any.
std::optional<int> badThreadCount(const std::vector<int>& threads);
bool runsInRange(int runs, int warmupRuns);

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
    SweepShard shard;                       // the settings to run: all, by default
    Progress* progress = nullptr;           // reports the frames done (and the references' rows)
    // Non-empty: the directory the sweep's files go to; each setting's pictures (FrameImages,
    // from one more untimed frame that also writes the debug buffers) and each reference's
    // are written into its folder STEM-images (sweepImagesFolder()), and the rows name them
    // relative to the directory.
    std::filesystem::path imagesOutDir;
};

// What a sweep was asked for, besides its scene, techniques and shard: the shards of one
// sweep agree on all of it, which their merge checks.
struct SweepGrid {
    std::vector<SweepAxis> axes;
    SceneOverrides overrides;
    std::string reference;                  // SweepOptions::reference
    std::map<std::string, std::string> referenceFingerprints;   // each reference rendered: referenceFingerprint()
    std::vector<int> threads;               // as run: the default resolved to the machine's cores
    int warmupRuns = 0, runs = 0;
    uint64_t settings = 0;                  // of the whole sweep, all techniques
};

struct SweepRow {
    uint64_t setting = 0;                          // index in the sweep's fixed order (SweepResults::rows)
    std::string technique;
    std::string reference;                         // the technique it was scored against
    std::map<std::string, std::string> settings;   // this row's axis values (not defaults)
    int threads = 1;
    double medianMs = 0.0, minMs = 0.0;
    ErrorFigures errors;                           // over every light of the scene (frame/score.h)
    // Each light's own figures (scoreLights(), in the scene's order) for a scene of several
    // lights; empty for one light, whose figures are `errors`.
    std::vector<ErrorFigures> lightErrors;
    std::vector<TechniqueStat> stats;              // of the last measured frame, stage times medians
    FrameImages images;                            // with SweepOptions::imagesOutDir: the same at every thread count
    std::string settingsLabel() const;             // "a=1 b=2", or "defaults"
};

struct SweepResults {
    std::string scene;
    std::vector<std::string> techniques;   // in the order given
    SweepGrid grid;
    SweepShard shard;             // the settings the rows cover
    std::vector<SweepRow> rows;   // per technique, settings in axis order (last axis fastest), threads
    // The most lights any row has figures for (SweepRow::lightErrors): the CSV's and the
    // report's per-light columns.
    size_t lightCount() const;
};

// Checks the technique names, that every axis belongs to one of them and that the shard
// holds a setting, then renders one frame per setting of the shard (a value a technique
// rejects fails there, before any measurement); throws std::invalid_argument (or
// SceneError for the scene).
SweepResults runSweep(const SweepOptions& options);
// The same on a scene already loaded, e.g. one a program built (the Python module's);
// SweepOptions::scene is not read.
SweepResults runSweep(Scene scene, const SweepOptions& options);

// FNV-1a (64 bit) of a reference's scored channels, names and float bytes, as 16 hex
// digits: shards whose references differ (another scene file, light or build) are not
// parts of one sweep.
std::string referenceFingerprint(const ImageChannels& reference);

// The output file stem: "<scene>-<technique>[+<technique>...]", and "-shard-<i>-of-<n>"
// after it for a shard, so that shards writing to one directory keep their files apart.
std::string sweepFileStem(const SweepResults& results);

// The folder of a sweep's pictures, beside its other files: "<sweepFileStem()>-images".
std::string sweepImagesFolder(const SweepResults& results);

// A table for the terminal: one line per row, and under a row of several lights a line per
// light with its error figures (SweepRow::lightErrors).
std::string formatSweepText(const SweepResults& results);
// One row per SweepRow. CSV columns: technique, settings, threads, median_ms, min_ms, rms,
// rms_display, mean_abs, max_abs, misclassified_percent, false_shadow_percent,
// false_light_percent, umbra_lit_percent, full_umbra_lit_percent, umbra_over_percent,
// lit_shadowed_percent, reference, flip_mean (FLIP of the shaded images, ErrorFigures::flipMean;
// empty in a row read from JSON written before it); for a sweep of several lights then each light's
// headline figures, lightK_misclassified_percent, lightK_rms and lightK_umbra_lit_percent
// for K from 0 (empty where a row has none); then one column per
// technique stat (empty where a row does not report it).
std::string formatSweepCsv(const SweepResults& results);

}  // namespace shadowlab
