// Helpers shared by the hand-written SVG plots (sweep_plot.cpp, scaling_plot.cpp,
// line_plot.cpp): text formatting (text::format, as svg::format) and escaping, tick steps
// and axes, the canvas and the colour palette.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/common/text_format.h"

namespace shadowlab::svg {

using text::format;   // printf into a std::string

// Okabe and Ito's colour-blind-safe palette (without its yellow, faint on white), then
// five of Paul Tol's muted colours, so that a dozen techniques get a colour each.
inline constexpr const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9",
                                           "#000000", "#882255", "#44AA99", "#999933", "#332288", "#AA4499"};

inline std::string escape(const std::string& text) {
    std::string escaped;
    for (char c : text) {
        if (c == '&') escaped += "&amp;";
        else if (c == '<') escaped += "&lt;";
        else if (c == '>') escaped += "&gt;";
        else if (c == '"') escaped += "&quot;";
        else escaped += c;
    }
    return escaped;
}

// A tick step of 1, 2 or 5 times a power of ten giving about five ticks from 0 up to
// `largest` (0.2 when there is nothing to show).
inline double niceTickStep(double largest) {
    if (!(largest > 0.0)) return 0.2;
    const double rough = largest / 5.0, decade = std::pow(10.0, std::floor(std::log10(rough)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= rough) return m * decade;
    return 10.0 * decade;
}

// A linear axis from 0 to a whole number of nice ticks past the largest value.
struct Axis {
    double step, top;
    explicit Axis(double largest) : step(niceTickStep(largest)), top(std::max(step, std::ceil(largest / step) * step)) {}
};

// The canvas of every plot and the left, top and bottom edges of its plot area, in SVG user
// units (pixels); each plot sets its right edge, beyond which a legend may sit.
inline constexpr double kCanvasWidth = 800, kCanvasHeight = 500;
inline constexpr double kPlotLeft = 70, kPlotTop = 40, kPlotBottom = 440;

// The box a point's label covers, in SVG user units.
struct LabelBox {
    double left, top, right, bottom;
    bool overlaps(const LabelBox& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
};

// Labels of nearby points would print over each other: each label takes the nearest
// baseline, alternately above and below its point (x, y), where it stays between the
// plot's top and bottom and overlaps no box placed before it (or the first one if all are
// taken). Returns the baseline and adds the label's box to `placed`.
inline double labelBaseline(double x, double y, const std::string& text, std::vector<LabelBox>& placed, double top,
                            double bottom) {
    constexpr double kCharWidth = 5.5, kAscent = 9, kDescent = 2, kLineStep = 11;   // 10-unit sans-serif text
    const auto boxAt = [&](double baseline) {
        return LabelBox{x + 6, baseline - kAscent, x + 6 + kCharWidth * double(text.size()), baseline + kDescent};
    };
    const auto isFree = [&](const LabelBox& box) {
        return box.top >= top && box.bottom <= bottom &&
               std::ranges::none_of(placed, [&](const LabelBox& b) { return b.overlaps(box); });
    };
    double chosen = y - 6;
    for (int step = 0; step < 64; ++step) {
        const double baseline = step % 2 == 0 ? y - 6 - kLineStep * (step / 2) : y + 14 + kLineStep * (step / 2);
        if (isFree(boxAt(baseline))) {
            chosen = baseline;
            break;
        }
    }
    placed.push_back(boxAt(chosen));
    return chosen;
}

// A <text class="label"> beside the point (x, y), placed by labelBaseline(), with a leader
// line back to the point when it had to move away.
inline std::string label(double x, double y, const std::string& text, std::vector<LabelBox>& placed, double top,
                         double bottom) {
    const double baseline = labelBaseline(x, y, text, placed, top, bottom);
    std::string svg;
    if (baseline != y - 6)
        svg += format(R"(<line class="leader" x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#bbb"/>)" "\n", x, y, x + 6,
                      baseline - 3);
    return svg + format(R"(<text class="label" x="%.1f" y="%.1f" font-size="10">%s</text>)" "\n", x + 6, baseline,
                        escape(text).c_str());
}

}  // namespace shadowlab::svg
