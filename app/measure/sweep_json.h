// A sweep's results as JSON: the file `shadowlab sweep` writes beside its CSV and plot,
// and its reader, with which `shadowlab merge-sweep` joins the files of a sweep's shards.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>

#include <glm/glm.hpp>

#include "app/measure/sweep.h"
#include "frame/overrides_json.h"

namespace shadowlab {

// {"scene", "grid": {"techniques", "axes": [{"name", "values"}], "overrides": {the given
//  ones of "width", "height", "eye", "target", "fovy", "light_position", "light_radius"},
//  "reference" ("": each technique against its own), "reference_fingerprints": {name:
//  hex}, "threads", "warmup", "runs", "settings"}, "shard": {"index", "count"},
//  "rows": [{"setting", "technique", "reference", "settings": {...}, "threads",
//  "median_ms", "min_ms", "errors": formatJson(...), "stats": {...}}]}; a row of several
//  lights also has "lights": [{"light": K, "errors": formatJson(...)}] (SweepRow::
//  lightErrors, the same fields as render --json's "lights" but for its time, which is the
//  row's stat lightK_technique_ms), and a row with pictures "images".
// A NaN (an error figure of a NaN image) is written as null.
std::string formatSweepJson(const SweepResults& results);

// formatSweepJson's text back into the results it was written from, so that writing them
// again gives the same bytes (stats in their order, doubles exact, null read as NaN).
// Throws std::runtime_error naming `file` and the problem: text that is not JSON, nested
// deeper than a sweep's, or lacking or mistyping a field.
SweepResults parseSweepJson(const std::string& text, const std::string& file);

// The JSON of `render --error-map E --json J` (frame/score.h, formatScoreJson) as the one
// row a report shows of it: technique_ms is its median and minimum time, threads 0 (the
// file does not say).
struct ScoreRecord {
    std::string scene;
    SweepRow row;
    // Empty in a file written before render --json recorded them: not the scene's own view
    // and light, but conditions unknown.
    std::optional<SceneOverrides> overrides;
};

// A report's input, parsed once: a sweep's JSON (as parseSweepJson) or a render's, told
// apart by their fields ("grid" and "rows", or "technique_ms" and "errors"). Throws
// std::runtime_error naming `file` and the problem, also for a file that is neither.
std::variant<SweepResults, ScoreRecord> parseResultsJson(const std::string& text, const std::string& file);

// "" if a and b are parts of one sweep: the same scene and SweepResults::techniques and
// the same SweepGrid. Otherwise the first field that differs and both values, a's first:
// "runs: 5 against 3".
std::string sweepDifference(const SweepResults& a, const SweepResults& b);

}  // namespace shadowlab
