#include "shading/environment/split_sum_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"
#include "shading/microfacet_ggx.h"

namespace shadowlab {
namespace {

// Midpoint samples of s (u = sin^2(pi s / 2), below) and of the half vector's azimuth over
// [0, pi] (the integrand is symmetric about the plane of n and v). Against a brute-force
// integral over l: within 5e-4 for n . v >= 1/64 (tests/shading/environment).
constexpr int kAngleSamples = 512, kAzimuthSamples = 32;

// (A, B) for one view angle and roughness (the quadrature of split_sum_table.h).
glm::dvec2 integrateSplitSum(double cosV, double alpha) {
    const glm::dvec3 v(std::sqrt(1.0 - cosV * cosV), 0.0, cosV);
    const double alpha2 = alpha * alpha;
    double cosPhi[kAzimuthSamples];   // h's y does not meet v, whose y is 0
    for (int b = 0; b < kAzimuthSamples; ++b) cosPhi[b] = portable::cos(kPi * (b + 0.5) / kAzimuthSamples);
    double scale = 0.0, bias = 0.0;
    for (int a = 0; a < kAngleSamples; ++a) {
        // u = sin^2(pi s / 2), du = (pi / 2) sin(pi s) ds: tan theta_h = alpha tan(pi s / 2) is
        // smooth in s at both ends, where it is not in u (a grazing view's integrand is sharp
        // near u = 1, and the midpoint rule in u converged as N^-0.6 there).
        const double s = (a + 0.5) / kAngleSamples, sinHalf = portable::sin(0.5 * kPi * s);
        const double u = sinHalf * sinHalf, du = 0.5 * kPi * portable::sin(kPi * s);
        const double cos2 = (1.0 - u) / (1.0 + (alpha2 - 1.0) * u);
        const double cosH = std::sqrt(cos2), sinH = std::sqrt(1.0 - cos2);
        for (int b = 0; b < kAzimuthSamples; ++b) {
            const double cosVH = v.x * sinH * cosPhi[b] + v.z * cosH;
            const double cosL = 2.0 * cosVH * cosH - cosV;   // (2 (v . h) h - v) . n
            if (cosL <= 0.0 || cosVH <= 0.0) continue;
            const double integrand = 4.0 * smithVisibility(cosL, cosV, alpha) * cosL * cosVH / cosH;
            const double w = schlickWeight(cosVH);
            scale += du * integrand * (1.0 - w);
            bias += du * integrand * w;
        }
    }
    const double samples = double(kAngleSamples) * kAzimuthSamples;
    return {scale / samples, bias / samples};
}

}  // namespace

SplitSumTable buildSplitSumTable(int size) {
    if (size < 2 || size > 1024) {
        throw std::invalid_argument("the split-sum table's size must be in [2, 1024], not " + std::to_string(size));
    }
    SplitSumTable table;
    table.size = size;
    table.scale.resize(size_t(size) * size_t(size));
    table.bias.resize(table.scale.size());
    tbb::parallel_for(0, size, [&](int j) {
        for (int i = 0; i < size; ++i) {
            const glm::dvec2 ab = integrateSplitSum((i + 0.5) / size, (j + 0.5) / size);
            table.scale[table.index(i, j)] = float(ab.x);
            table.bias[table.index(i, j)] = float(ab.y);
        }
    });
    return table;
}

glm::dvec2 lookupSplitSum(const SplitSumTable& table, double cosV, double alpha) {
    const auto cell = [&](double t, int& k0, int& k1, double& f) {
        // 0.0 first, so a NaN takes the first cell.
        const double x = std::min(std::max(0.0, t * table.size - 0.5), table.size - 1.0);
        k0 = std::min(int(x), table.size - 2);
        k1 = k0 + 1;
        f = x - k0;
    };
    int i0, i1, j0, j1;
    double fx, fy;
    cell(cosV, i0, i1, fx);
    cell(alpha, j0, j1, fy);
    const auto at = [&](int i, int j) { return glm::dvec2(table.scale[table.index(i, j)], table.bias[table.index(i, j)]); };
    return (1.0 - fy) * ((1.0 - fx) * at(i0, j0) + fx * at(i1, j0)) + fy * ((1.0 - fx) * at(i0, j1) + fx * at(i1, j1));
}

}  // namespace shadowlab
