// The plots of a fly-through (docs/flythrough.md) over its path, one line per series: the
// technique's median time (ms), its RMS against the reference, and its flicker mean (from
// frame 1), drawn by formatLinePlotSvg().
#pragma once

#include <string>

#include "app/measure/flythrough.h"

namespace shadowlab {

// A non-finite value (a NaN image) leaves its point out; the CSV and JSON keep it.
enum class FlythroughPlot { Time, Error, Flicker };
std::string formatFlythroughSvg(const FlythroughResults& results, FlythroughPlot plot);

}  // namespace shadowlab
