#include "app/sweep_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace shadowlab {
namespace {

// Canvas and plot area in SVG user units (pixels); the legend sits right of the plot.
constexpr double kWidth = 800, kHeight = 500;
constexpr double kLeft = 70, kRight = 600, kTop = 40, kBottom = 440;

// Times below a microsecond (a technique that does nothing) are drawn at 1 us: a log axis
// has no place for 0.
constexpr double kMinPlottedMs = 1e-3;

// Okabe and Ito's colour-blind-safe palette, in order of use.
constexpr const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};

struct Range {
    double lo, hi;
};

std::string format(const char* pattern, auto... values) {
    std::string text(size_t(std::snprintf(nullptr, 0, pattern, values...)), '\0');
    std::snprintf(text.data(), text.size() + 1, pattern, values...);
    return text;
}

std::string xmlEscape(const std::string& text) {
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

double plottedMs(const SweepRow& row) { return std::max(row.medianMs, kMinPlottedMs); }

// Whole decades around the times: log10 of the axis ends.
Range decadeRange(const std::vector<SweepRow>& rows) {
    Range r{INFINITY, -INFINITY};
    for (const SweepRow& row : rows) {
        r.lo = std::min(r.lo, std::floor(std::log10(plottedMs(row))));
        r.hi = std::max(r.hi, std::ceil(std::log10(plottedMs(row))));
    }
    if (r.hi <= r.lo) r.hi = r.lo + 1;
    return r;
}

// A tick step of 1, 2 or 5 times a power of ten giving about five ticks up to the largest error.
double errorTickStep(double largest) {
    if (!(largest > 0.0)) return 0.2;
    const double rough = largest / 5.0, decade = std::pow(10.0, std::floor(std::log10(rough)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= rough) return m * decade;
    return 10.0 * decade;
}

struct Axes {
    Range decades;
    double errorStep, errorTop;
    double x(double ms) const {
        return kLeft + (std::log10(std::max(ms, kMinPlottedMs)) - decades.lo) / (decades.hi - decades.lo) * (kRight - kLeft);
    }
    double y(double error) const { return kBottom - error / errorTop * (kBottom - kTop); }
};

Axes fitAxes(const std::vector<SweepRow>& rows, PlotErrorAxis axis) {
    double largest = 0.0;
    for (const SweepRow& row : rows) largest = std::max(largest, plottedError(row, axis));
    const double step = errorTickStep(largest);
    // A little headroom, so that the worst point does not sit on the frame.
    return {decadeRange(rows), step, std::max(step, std::ceil(1.05 * largest / step) * step)};
}

// Ticks at 1, 2 and 5 times each power of ten when the axis spans few decades, else at
// the powers only.
std::vector<double> timeTicks(const Range& decades) {
    const bool fine = decades.hi - decades.lo <= 3;
    std::vector<double> ticks;
    for (double d = decades.lo; d <= decades.hi; ++d)
        for (double m : {1.0, 2.0, 5.0})
            if ((m == 1.0 || fine) && d + std::log10(m) <= decades.hi) ticks.push_back(m * std::pow(10.0, d));
    return ticks;
}

std::string axesSvg(const Axes& a, PlotErrorAxis axis) {
    std::string svg = format(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="none" stroke="#444"/>)" "\n",
                             kLeft, kTop, kRight - kLeft, kBottom - kTop);
    for (double ms : timeTicks(a.decades)) {
        const double x = a.x(ms);
        svg += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", x, kTop, x, kBottom);
        svg += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">%g</text>)" "\n", x, kBottom + 16, ms);
    }
    for (double e = 0.0; e <= a.errorTop * (1 + 1e-9); e += a.errorStep) {
        const double y = a.y(e);
        svg += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", kLeft, y, kRight, y);
        svg += format(R"(<text x="%.1f" y="%.1f" text-anchor="end">%g</text>)" "\n", kLeft - 6, y + 4, e);
    }
    svg += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">technique median ms (log scale)</text>)" "\n",
                  (kLeft + kRight) / 2, kBottom + 40);
    svg += format(R"svg(<text transform="translate(18 %.1f) rotate(-90)" text-anchor="middle">%s</text>)svg" "\n",
                  (kTop + kBottom) / 2, axis == PlotErrorAxis::Rms ? "RMS error of V" : "misclassified pixels (%)");
    return svg;
}

// Right, then down: the best error reachable within each time.
std::string frontSvg(const SweepResults& results, const std::vector<size_t>& front, const Axes& a, PlotErrorAxis axis) {
    std::string points;
    for (size_t k = 0; k < front.size(); ++k) {
        const SweepRow& row = results.rows[front[k]];
        if (k > 0) points += format(" %.1f,%.1f", a.x(row.medianMs), a.y(plottedError(results.rows[front[k - 1]], axis)));
        points += format(" %.1f,%.1f", a.x(row.medianMs), a.y(plottedError(row, axis)));
    }
    std::string svg = R"(<polyline class="pareto-front" fill="none" stroke="#888" stroke-dasharray="4 3" points=")" +
                      points.substr(1) + "\"/>\n";
    for (size_t index : front) {
        const SweepRow& row = results.rows[index];
        svg += format(R"(<circle class="pareto" cx="%.1f" cy="%.1f" r="7" fill="none" stroke="#000"/>)" "\n",
                      a.x(row.medianMs), a.y(plottedError(row, axis)));
    }
    return svg;
}

size_t techniqueIndex(const SweepResults& results, const std::string& technique) {
    return size_t(std::ranges::find(results.techniques, technique) - results.techniques.begin());
}

std::string rowLabel(const SweepRow& row, bool severalThreadCounts) {
    return row.settingsLabel() + (severalThreadCounts ? ", " + std::to_string(row.threads) + " thr" : "");
}

struct LabelBox {
    double left, top, right, bottom;
    bool overlaps(const LabelBox& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
};

// Labels of nearby points would print over each other: each label takes the nearest
// baseline, alternately above and below its point, where it stays inside the plot's
// height and overlaps no label placed before it (or the first one if all are taken).
double labelBaseline(double x, double y, const std::string& text, std::vector<LabelBox>& placed) {
    constexpr double kCharWidth = 5.5, kAscent = 9, kDescent = 2, kLineStep = 11;   // 10-unit sans-serif text
    const auto boxAt = [&](double baseline) {
        return LabelBox{x + 6, baseline - kAscent, x + 6 + kCharWidth * double(text.size()), baseline + kDescent};
    };
    const auto isFree = [&](const LabelBox& box) {
        return box.top >= kTop && box.bottom <= kBottom &&
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

// Labels must not cover the legend or any point.
std::vector<LabelBox> takenBoxes(const SweepResults& results, const Axes& a, PlotErrorAxis axis) {
    std::vector<LabelBox> taken = {{kRight + 10, kTop, kWidth, kTop + 20.0 * double(results.techniques.size() + 1)}};
    for (const SweepRow& row : results.rows) {
        const double x = a.x(row.medianMs), y = a.y(plottedError(row, axis));
        taken.push_back({x - 4, y - 4, x + 4, y + 4});
    }
    return taken;
}

std::string pointsSvg(const SweepResults& results, const Axes& a, PlotErrorAxis axis) {
    std::set<int> threadCounts;
    for (const SweepRow& row : results.rows) threadCounts.insert(row.threads);
    std::string svg;
    std::vector<LabelBox> placed = takenBoxes(results, a, axis);
    for (const SweepRow& row : results.rows) {
        const double x = a.x(row.medianMs), y = a.y(plottedError(row, axis));
        const std::string label = rowLabel(row, threadCounts.size() > 1);
        svg += format(R"(<circle class="point" cx="%.1f" cy="%.1f" r="4" fill="%s"><title>%s %s: %.4g ms, %.4g</title></circle>)" "\n",
                      x, y, kPalette[techniqueIndex(results, row.technique) % std::size(kPalette)],
                      xmlEscape(row.technique).c_str(), xmlEscape(label).c_str(), row.medianMs, plottedError(row, axis));
        const double baseline = labelBaseline(x, y, label, placed);
        if (baseline != y - 6)   // moved away from its point: a leader line shows whose it is
            svg += format(R"(<line class="leader" x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#bbb"/>)" "\n", x, y,
                          x + 6, baseline - 3);
        svg += format(R"(<text class="label" x="%.1f" y="%.1f" font-size="10">%s</text>)" "\n", x + 6, baseline,
                      xmlEscape(label).c_str());
    }
    return svg;
}

std::string legendSvg(const SweepResults& results) {
    std::string svg;
    double y = kTop + 10;
    for (size_t k = 0; k < results.techniques.size(); ++k, y += 20) {
        svg += format(R"(<circle cx="%.1f" cy="%.1f" r="4" fill="%s"/>)" "\n", kRight + 20, y, kPalette[k % std::size(kPalette)]);
        svg += format(R"(<text x="%.1f" y="%.1f">%s</text>)" "\n", kRight + 30, y + 4, xmlEscape(results.techniques[k]).c_str());
    }
    svg += format(R"(<circle cx="%.1f" cy="%.1f" r="7" fill="none" stroke="#000"/>)" "\n", kRight + 20, y);
    svg += format(R"(<text x="%.1f" y="%.1f">Pareto front</text>)" "\n", kRight + 30, y + 4);
    return svg;
}

}  // namespace

PlotErrorAxis parsePlotErrorAxis(const std::string& name) {
    if (name == "misclassified") return PlotErrorAxis::Misclassified;
    if (name == "rms") return PlotErrorAxis::Rms;
    throw std::invalid_argument("plot axis must be misclassified or rms, got '" + name + "'");
}

double plottedError(const SweepRow& row, PlotErrorAxis axis) {
    return axis == PlotErrorAxis::Rms ? row.errors.rms : row.errors.percentOfPixels(row.errors.misclassified());
}

std::vector<size_t> paretoFront(const std::vector<SweepRow>& rows, PlotErrorAxis axis) {
    std::vector<size_t> order(rows.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    // Faster first, then lower error, then earlier row: each row is on the front exactly
    // when its error is below that of every row before it in this order.
    std::ranges::stable_sort(order, [&](size_t a, size_t b) {
        if (rows[a].medianMs != rows[b].medianMs) return rows[a].medianMs < rows[b].medianMs;
        return plottedError(rows[a], axis) < plottedError(rows[b], axis);
    });
    std::vector<size_t> front;
    for (size_t index : order)
        if (front.empty() || plottedError(rows[index], axis) < plottedError(rows[front.back()], axis)) front.push_back(index);
    return front;
}

std::string formatSweepSvg(const SweepResults& results, PlotErrorAxis axis) {
    if (results.rows.empty()) throw std::invalid_argument("sweep plot: no rows");
    const Axes a = fitAxes(results.rows, axis);
    std::string svg = format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f" viewBox="0 0 %.0f %.0f" font-family="sans-serif" font-size="12">)" "\n",
                             kWidth, kHeight, kWidth, kHeight);
    svg += format(R"(<rect width="%.0f" height="%.0f" fill="#fff"/>)" "\n", kWidth, kHeight);
    svg += format(R"(<text x="%.1f" y="24" font-size="14">%s: speed against error</text>)" "\n", kLeft,
                  xmlEscape(results.scene).c_str());
    svg += axesSvg(a, axis);
    svg += frontSvg(results, paretoFront(results.rows, axis), a, axis);
    svg += pointsSvg(results, a, axis);
    svg += legendSvg(results);
    return svg + "</svg>\n";
}

}  // namespace shadowlab
