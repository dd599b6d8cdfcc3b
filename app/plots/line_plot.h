// A plot of a few series of points joined by lines (SVG, as the sweep and scaling plots):
// the figures of differential rendering (docs/differential-rendering.md): time against
// RMS per number of passes, the shadow's depth as the object is lifted, the 8-bit path's
// error against the share of sources occluded; and a fly-through's time, error and flicker
// per frame (docs/flythrough.md).
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

struct PlotSeries {
    std::string name;
    std::vector<double> x, y;
    std::vector<std::string> labels;   // one per point, or none
};

struct LinePlot {
    std::string title, xTitle, yTitle;
    std::vector<PlotSeries> series;
};

// Both axes from 0 to a whole number of ticks past the largest value. Throws
// std::invalid_argument for a plot with no point, a series whose x and y (or labels)
// differ in length, or a negative or non-finite value.
std::string formatLinePlotSvg(const LinePlot& plot);

}  // namespace shadowlab
