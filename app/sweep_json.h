// A sweep's results as JSON: the file `shadowlab sweep` writes beside its CSV and plot.
#pragma once

#include <string>

#include "app/sweep.h"

namespace shadowlab {

// {"scene", "rows": [{"technique", "reference", "settings": {...}, "threads", "median_ms",
//  "min_ms", "errors": formatJson(...), "stats": {...}}]}
std::string formatSweepJson(const SweepResults& results);

}  // namespace shadowlab
