// The speed-against-error plot of a sweep, as a small hand-written SVG (no plotting
// dependency): x is the technique's median time on a log scale, y an error figure; one
// point per row, labelled with its settings, one colour per technique, and the Pareto
// front (the rows no other row beats in both time and error) ringed and joined by a
// staircase.
#pragma once

#include <string>
#include <vector>

#include "app/measure/sweep.h"

namespace shadowlab {

enum class PlotErrorAxis {
    Auto,            // the default: Rms if no row is scored against the hard `reference`, else Misclassified
    Misclassified,   // misclassified pixels, % of the reference's hit pixels
    Rms,             // RMS error of V, or of the luminance Y of a shaded image
    Umbra,           // umbra errors both ways (soft shadows), % of the hit pixels
    RmsDisplay,      // RMS error of a shaded image's displayed luminance (ErrorFigures::rmsDisplay)
    Flip,            // FLIP of the shaded images (ErrorFigures::flipMean)
};

// Throws std::invalid_argument for a name other than "auto", "misclassified", "rms", "umbra",
// "rms-display" or "flip".
PlotErrorAxis parsePlotErrorAxis(const std::string& name);

// The axis a plot of `rows` draws: `asked`, or for Auto, Rms when every row is scored against
// a soft reference (or on luminance), where a misclassified pixel is one whose V crosses 0.5
// and so ranks a blurred map above an accurate one (vsm at 1024 plotted better than pcss with
// twice pcss's RMS); Misclassified when some row is scored against hard shadows.
PlotErrorAxis resolvedPlotAxis(PlotErrorAxis asked, const std::vector<SweepRow>& rows);

// Throws std::invalid_argument naming a row the axis has no figure for (rms-display of a
// technique scored on V, flip of a row read from JSON written before FLIP), before anything
// is drawn.
void requirePlottable(const std::vector<SweepRow>& rows, PlotErrorAxis axis);

double plottedError(const SweepRow& row, PlotErrorAxis axis);

// Indices of the rows on the Pareto front (minimising both median ms and the error), in
// order of increasing time. Of rows with equal time and error, the first is kept.
std::vector<size_t> paretoFront(const std::vector<SweepRow>& rows, PlotErrorAxis axis);

// Every row is one <circle class="point">; front rows also get a <circle class="pareto">.
// With `links` (one URL per row, already escaped for an attribute), each point is an <a>
// to its row's URL, as the report's scene pages draw it.
std::string formatSweepSvg(const SweepResults& results, PlotErrorAxis axis, const std::vector<std::string>& links = {});

}  // namespace shadowlab
