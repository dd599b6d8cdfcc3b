#include "app/plots/scaling_plot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "app/plots/svg.h"

namespace shadowlab {
namespace {

using svg::Axis;
using svg::format;
using svg::kCanvasHeight, svg::kCanvasWidth, svg::kPlotBottom, svg::kPlotLeft, svg::kPlotTop;

constexpr double kScalingPlotRight = 760;   // no legend

struct ScalingAxes {
    Axis n, ms;
    double x(double triangles) const { return kPlotLeft + triangles / n.top * (kScalingPlotRight - kPlotLeft); }
    double y(double time) const { return kPlotBottom - time / ms.top * (kPlotBottom - kPlotTop); }
};

ScalingAxes fitAxes(const ScalingResults& results) {
    double largestN = 0.0, largestMs = 0.0;
    for (const ScalingPoint& p : results.points) {
        largestN = std::max(largestN, double(p.triangles));
        largestMs = std::max({largestMs, p.medianMs, results.fit.at(double(p.triangles))});
    }
    return {Axis(largestN), Axis(1.05 * largestMs)};   // headroom: the slowest point is not on the frame
}

std::string axesSvg(const ScalingAxes& a) {
    std::string text = format(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="none" stroke="#444"/>)" "\n",
                              kPlotLeft, kPlotTop, kScalingPlotRight - kPlotLeft, kPlotBottom - kPlotTop);
    for (double n = 0.0; n <= a.n.top * (1 + 1e-9); n += a.n.step) {
        text += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", a.x(n), kPlotTop, a.x(n), kPlotBottom);
        text += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">%g</text>)" "\n", a.x(n), kPlotBottom + 16, n);
    }
    for (double t = 0.0; t <= a.ms.top * (1 + 1e-9); t += a.ms.step) {
        text += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", kPlotLeft, a.y(t), kScalingPlotRight, a.y(t));
        text += format(R"(<text x="%.1f" y="%.1f" text-anchor="end">%g</text>)" "\n", kPlotLeft - 6, a.y(t) + 4, t);
    }
    text += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">triangles n</text>)" "\n", (kPlotLeft + kScalingPlotRight) / 2, kPlotBottom + 40);
    text += format(R"svg(<text transform="translate(18 %.1f) rotate(-90)" text-anchor="middle">technique median ms</text>)svg" "\n",
                   (kPlotTop + kPlotBottom) / 2);
    return text;
}

// The fitted line where it lies inside the plot: n in [0, n.top] and t in [0, ms.top].
std::string fitSvg(const ScalingResults& results, const ScalingAxes& a) {
    const LineFit& f = results.fit;
    double lo = 0.0, hi = a.n.top;
    if (f.b != 0.0) {
        const double atZero = -f.a / f.b, atTop = (a.ms.top - f.a) / f.b;
        lo = std::max(lo, std::min(atZero, atTop));
        hi = std::min(hi, std::max(atZero, atTop));
    } else if (f.a < 0.0 || f.a > a.ms.top) {
        return "";
    }
    if (!(lo < hi)) return "";
    return format(R"(<line class="fit" x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-width="1.5"/>)" "\n",
                  a.x(lo), a.y(f.at(lo)), a.x(hi), a.y(f.at(hi)), svg::kPalette[1]);
}

std::string pointsSvg(const ScalingResults& results, const ScalingAxes& a) {
    std::vector<svg::LabelBox> placed;   // labels must not cover any point
    for (const ScalingPoint& p : results.points) {
        const double x = a.x(double(p.triangles)), y = a.y(p.medianMs);
        placed.push_back({x - 4, y - 4, x + 4, y + 4});
    }
    std::string text;
    for (const ScalingPoint& p : results.points) {
        const double x = a.x(double(p.triangles)), y = a.y(p.medianMs);
        text += format(R"(<circle class="point" cx="%.1f" cy="%.1f" r="4" fill="%s"><title>%s: %llu triangles, %.4g ms</title></circle>)" "\n",
                       x, y, svg::kPalette[0], svg::escape(p.scene).c_str(), (unsigned long long)p.triangles, p.medianMs);
        text += svg::label(x, y, p.scene, placed, kPlotTop, kPlotBottom);
    }
    return text;
}

}  // namespace

std::string formatScalingSvg(const ScalingResults& results) {
    if (results.points.empty()) throw std::invalid_argument("scaling plot: no points");
    const ScalingAxes a = fitAxes(results);
    const LineFit& f = results.fit;
    std::string text = format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f" viewBox="0 0 %.0f %.0f" font-family="sans-serif" font-size="12">)" "\n",
                              kCanvasWidth, kCanvasHeight, kCanvasWidth, kCanvasHeight);
    text += format(R"(<rect width="%.0f" height="%.0f" fill="#fff"/>)" "\n", kCanvasWidth, kCanvasHeight);
    text += format(R"(<text x="%.1f" y="24" font-size="14">%s, %d thread(s): t = %.4g + n / %.4g ms, R&#178; = %.4f</text>)" "\n",
                   kPlotLeft, svg::escape(results.technique).c_str(), results.threads, f.a, 1.0 / f.b, f.r2);
    text += axesSvg(a);
    text += fitSvg(results, a);
    text += pointsSvg(results, a);
    return text + "</svg>\n";
}

}  // namespace shadowlab
