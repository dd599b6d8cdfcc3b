// A sweep's results as JSON: the file `shadowlab sweep` writes beside its CSV and plot.
#pragma once

#include <string>

#include "app/sweep.h"

namespace shadowlab {

// {"scene", "grid": {"techniques", "axes": [{"name", "values"}], "overrides": {the given
//  ones of "width", "height", "eye", "target", "fovy", "light_position", "light_radius"},
//  "reference" ("": each technique against its own), "reference_fingerprints": {name:
//  hex}, "threads", "warmup", "runs", "settings"}, "shard": {"index", "count"},
//  "rows": [{"setting", "technique", "reference", "settings": {...}, "threads",
//  "median_ms", "min_ms", "errors": formatJson(...), "stats": {...}}]}
// A NaN (an error figure of a NaN image) is written as null.
std::string formatSweepJson(const SweepResults& results);

}  // namespace shadowlab
