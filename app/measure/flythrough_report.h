// A fly-through's files (docs/flythrough.md): the per-frame table as CSV and JSON, and the
// summary for the terminal; its plots are app/plots/flythrough_plot.h.
#pragma once

#include <string>

#include "app/measure/flythrough.h"

namespace shadowlab {

// Per series: its label and PathFigures (mean RMS, mean FLIP, ...).
std::string formatFlythroughText(const FlythroughResults& results);

// One row per series and frame. Columns: technique, settings, frame, time, eye_x, eye_y,
// eye_z, target_x, target_y, target_z, light_x, light_y, light_z (empty if the path does
// not move the light), median_ms, min_ms, rms, max_abs, misclassified_percent,
// false_shadow_percent, false_light_percent, flip_mean (ErrorFigures::flipMean), flicker_mean, flicker_p99,
// flicker_stable_percent (the three empty on frame 0), moved (1 where the camera, the light or
// an instance differs from the frame before), then the techniques' stats.
std::string formatFlythroughCsv(const FlythroughResults& results);

// {"scene", "path", "frames", "threads", "warmup", "runs", "stable_tolerance", "series":
//  [{"technique", "reference", "settings", "path_figures": {"median_ms", "mean_rms",
//  "mean_flip", "mean_misclassified_percent", "flicker_mean", "flicker_p99", "settle_frames",
//  "settled", "ghosting_rms_frames" (PathFigures; null where the path does not end still)}, "frames":
//  [{"frame", "time", "eye", "target", "light" (if moved), "median_ms", "min_ms", "moved", "errors":
//  formatJson(...), "flicker": {"mean", "p99", "pixels", "stable_pixels"} or null}]}]}.
// NaN is written as null.
std::string formatFlythroughJson(const FlythroughResults& results);

}  // namespace shadowlab
