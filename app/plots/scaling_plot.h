// The plot of `shadowlab scaling`: median time against triangle count on linear axes, one
// labelled point per scene and the least-squares line t = a + b n, as a small SVG drawn
// with the helpers of the sweep plot (app/plots/svg.h).
#pragma once

#include <string>

#include "app/measure/scaling.h"

namespace shadowlab {

// Every scene is one <circle class="point">; the fit is one <line class="fit">.
std::string formatScalingSvg(const ScalingResults& results);

}  // namespace shadowlab
