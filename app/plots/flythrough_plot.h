// The plots of a fly-through (docs/flythrough.md) over its path, one line per series: the
// technique's median time (ms), its RMS against the reference, its FLIP (the mean of the
// shaded images' FLIP map, ErrorFigures::flipMean) beside it, its flicker mean (from
// frame 1), and for a technique that caches pages (virtual-shadow-map) the pages it drew and
// its cache hit rate per frame, drawn by formatLinePlotSvg().
#pragma once

#include <string>

#include "app/measure/flythrough.h"

namespace shadowlab {

// A non-finite value (a NaN image) leaves its point out; the CSV and JSON keep it. The
// cache plots draw only the series that report the stat (cache_drawn_pages,
// cache_hit_percent); hasFlythroughPlot says whether any does.
enum class FlythroughPlot { Time, Error, Flicker, DrawnPages, CacheHits, Flip };
bool hasFlythroughPlot(const FlythroughResults& results, FlythroughPlot plot);
std::string formatFlythroughSvg(const FlythroughResults& results, FlythroughPlot plot);

}  // namespace shadowlab
