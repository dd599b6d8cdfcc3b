#include "app/measure/scaling.h"

#include <cstdio>
#include <memory>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <tbb/info.h>

#include "app/common/csv.h"
#include "app/common/timing.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"

namespace shadowlab {
namespace {

double mean(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    return sum / double(values.size());
}

using Scenes = std::vector<std::unique_ptr<const PreparedScene>>;

// Every scene loaded and rendered once first: a bad file or setting fails before the long part.
Scenes loadScenes(const ScalingOptions& options, const FrameSettings& settings) {
    Scenes scenes;
    const ProgressStage loaded(options.progress, "scaling: loading scene", options.scenes.size());
    for (const std::string& name : options.scenes) {
        scenes.push_back(std::make_unique<const PreparedScene>(loadScene(name)));
        renderFrame(*scenes.back(), *options.technique, settings);
        loaded.advance();
    }
    return scenes;
}

// Each scene's median and minimum time, in the order given.
std::vector<ScalingPoint> measurePoints(const Scenes& scenes, const ScalingOptions& options, const FrameSettings& settings) {
    const ProgressStage frames(options.progress, "scaling: frame", scenes.size() * uint64_t(options.warmupRuns + options.runs));
    std::vector<ScalingPoint> points;
    for (const auto& s : scenes) {
        const Timing t = timeFrames(*s, *options.technique, settings, options.warmupRuns, options.runs, frames).timing;
        points.push_back({s->scene().name, uint64_t(s->world().triangles.size()), t.medianMs, t.minMs});
    }
    return points;
}

}  // namespace

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) throw std::invalid_argument("line fit: x and y differ in length");
    if (std::set<double>(x.begin(), x.end()).size() < 2) throw std::invalid_argument("line fit: needs at least two distinct x");
    // Centred sums: the textbook normal equations in a form that does not cancel badly
    // when x is large (polygon counts of 10^5 and more).
    const double xMean = mean(x), yMean = mean(y);
    double sxx = 0.0, sxy = 0.0, syy = 0.0;
    for (size_t k = 0; k < x.size(); ++k) {
        const double dx = x[k] - xMean, dy = y[k] - yMean;
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    LineFit fit;
    fit.b = sxy / sxx;
    fit.a = yMean - fit.b * xMean;
    double residuals = 0.0;
    for (size_t k = 0; k < x.size(); ++k) residuals += (y[k] - fit.at(x[k])) * (y[k] - fit.at(x[k]));
    fit.r2 = syy > 0.0 ? 1.0 - residuals / syy : 1.0;
    return fit;
}

ScalingResults runScaling(const ScalingOptions& options) {
    if (options.technique == nullptr) throw std::invalid_argument("scaling: give a technique");
    if (options.scenes.size() < 2) throw std::invalid_argument("scaling: give at least two scenes");
    if (options.runs < 1 || options.warmupRuns < 0) throw std::invalid_argument("scaling: runs must be >= 1, warm-up runs >= 0");
    const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    return withThreads(threads, [&] {
        const FrameSettings settings{options.simd, options.params, {}};
        const Scenes scenes = loadScenes(options, settings);
        std::vector<double> triangles;
        for (const auto& s : scenes) triangles.push_back(double(s->world().triangles.size()));
        if (std::set<double>(triangles.begin(), triangles.end()).size() < 2)
            throw std::invalid_argument("scaling: the scenes need at least two different triangle counts");
        ScalingResults results{options.technique->name, threads, measurePoints(scenes, options, settings), {}};
        std::vector<double> ms;
        for (const ScalingPoint& point : results.points) ms.push_back(point.medianMs);
        results.fit = fitLine(triangles, ms);
        return results;
    });
}

std::string scalingFileStem(const ScalingResults& results) { return "scaling-" + results.technique; }

std::string formatScalingText(const ScalingResults& results) {
    char line[256];
    std::string text = results.technique + ", " + std::to_string(results.threads) + " thread(s)\n";
    std::snprintf(line, sizeof line, "%-24s %10s %10s %10s %10s\n", "scene", "triangles", "median ms", "min ms", "fitted ms");
    text += line;
    for (const ScalingPoint& p : results.points) {
        std::snprintf(line, sizeof line, "%-24s %10llu %10.3f %10.3f %10.3f\n", p.scene.c_str(),
                      (unsigned long long)p.triangles, p.medianMs, p.minMs, results.fit.at(double(p.triangles)));
        text += line;
    }
    const LineFit& f = results.fit;
    // n / (1 / b) reads as a triangle rate; it means nothing unless b > 0 (noisy timings
    // of a technique whose cost hardly grows with n can fit a slope <= 0).
    if (f.b > 0.0) {
        std::snprintf(line, sizeof line, "fit: t = %.4g + %.4g n ms = %.4g + n / %.6g ms, R^2 = %.6f\n", f.a, f.b, f.a,
                      1.0 / f.b, f.r2);
    } else {
        std::snprintf(line, sizeof line, "fit: t = %.4g + %.4g n ms (no positive slope), R^2 = %.6f\n", f.a, f.b, f.r2);
    }
    return text + line;
}

std::string formatScalingCsv(const ScalingResults& results) {
    std::string csv = csvLine({"scene", "triangles", "median_ms", "min_ms", "fitted_ms"});
    for (const ScalingPoint& p : results.points) {
        csv += csvLine({p.scene, std::to_string(p.triangles), csvNumber(p.medianMs), csvNumber(p.minMs),
                        csvNumber(results.fit.at(double(p.triangles)))});
    }
    return csv;
}

std::string formatScalingJson(const ScalingResults& results) {
    nlohmann::ordered_json points = nlohmann::ordered_json::array();
    for (const ScalingPoint& p : results.points) {
        points.push_back({{"scene", p.scene},
                          {"triangles", p.triangles},
                          {"median_ms", p.medianMs},
                          {"min_ms", p.minMs},
                          {"fitted_ms", results.fit.at(double(p.triangles))}});
    }
    nlohmann::ordered_json j;
    j["technique"] = results.technique;
    j["threads"] = results.threads;
    j["fit"] = {{"a_ms", results.fit.a},
                {"b_ms_per_triangle", results.fit.b},
                {"triangles_per_ms", results.fit.b > 0.0 ? nlohmann::json(1.0 / results.fit.b) : nlohmann::json(nullptr)},
                {"r2", results.fit.r2}};
    j["points"] = points;
    return j.dump(2) + "\n";
}

}  // namespace shadowlab
