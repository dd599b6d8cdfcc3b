// `shadowlab scaling`: a technique's time against the polygon count over a series of
// scenes, fitted as t = a + b n by least squares. Cai et al. (2006), "Rendering soft
// shadows using multi-layered shadow fins", section 7.4, eq. 8, fit their fins' time this
// way (n: polygons of the model, 16 layers); docs/performance.md ("Scaling with the polygon
// count") compares their fit with ours.
//
// n is every triangle of the scene (flatten()); the scenes of assets/scenes/scaling/ stand their
// models on a two-triangle ground, so n is the model's count plus 2. Times are measured as
// in `sweep` (warm-up frames, then the median of `runs` frames of the technique alone), at
// one thread count.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "raster/rasterizer.h"
#include "shadows/progress.h"
#include "shadows/technique.h"

namespace shadowlab {

// y = a + b x, and the coefficient of determination R^2 = 1 - SS_res / SS_tot (1 when the
// points are exactly on the line, including when all y are equal).
struct LineFit {
    double a = 0.0, b = 0.0, r2 = 0.0;
    double at(double x) const { return a + b * x; }
};

// Ordinary least squares in double, with the sums taken in the order given, so the result
// is the same bytes on every run. Throws std::invalid_argument if the sizes differ or
// fewer than two distinct x are given.
LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y);

struct ScalingOptions {
    std::vector<std::string> scenes;             // built-in names or .json paths
    const Technique* technique = nullptr;
    std::map<std::string, std::string> params;   // the technique's --param settings
    int threads = 0;                             // 0: all cores
    int warmupRuns = 1;
    int runs = 5;
    raster::SimdLevel simd = raster::bestSimdLevel();
    Progress* progress = nullptr;                // reports the scenes loaded and the frames done
};

struct ScalingPoint {
    std::string scene;
    uint64_t triangles = 0;
    double medianMs = 0.0, minMs = 0.0;
};

struct ScalingResults {
    std::string technique;
    int threads = 1;
    std::vector<ScalingPoint> points;   // in the order the scenes were given
    LineFit fit;                        // median ms against triangles
};

// Throws std::invalid_argument (SceneError for a scene) before measuring anything if a
// scene does not load or a setting is rejected, and if the scenes have fewer than two
// distinct triangle counts.
ScalingResults runScaling(const ScalingOptions& options);

// "scaling-<technique>".
std::string scalingFileStem(const ScalingResults& results);

// The table and the fit, also in the paper's form t = a + n / (1/b) ms.
std::string formatScalingText(const ScalingResults& results);
// Columns: scene, triangles, median_ms, min_ms, fitted_ms.
std::string formatScalingCsv(const ScalingResults& results);
// {"technique", "threads", "fit": {"a_ms", "b_ms_per_triangle", "triangles_per_ms", "r2"},
//  "points": [{"scene", "triangles", "median_ms", "min_ms", "fitted_ms"}]}
std::string formatScalingJson(const ScalingResults& results);

}  // namespace shadowlab
