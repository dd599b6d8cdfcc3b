#include "shading/environment/environment_distribution.h"

#include <algorithm>
#include <cmath>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// The index k with cdf[k] <= x < cdf[k + 1] among entries of positive width.
int pick(const double* cdf, int count, double x) {
    const int k = int(std::upper_bound(cdf, cdf + count + 1, x) - cdf) - 1;
    return std::clamp(k, 0, count - 1);
}

}  // namespace

EnvironmentDistribution::EnvironmentDistribution(const EnvironmentMap& map)
    : map_(map),
      rowCdf_(size_t(map.height) + 1, 0.0),
      columnCdf_(size_t(map.height) * size_t(map.width + 1), 0.0),
      weight_(size_t(map.width) * size_t(map.height)) {
    for (int j = 0; j < map.height; ++j) {
        double* row = &columnCdf_[size_t(j) * size_t(map.width + 1)];
        for (int i = 0; i < map.width; ++i) {
            const double w = luminance(glm::dvec3(map.at(i, j))) * map.texelSolidAngle(j);
            weight_[size_t(j) * size_t(map.width) + size_t(i)] = w;
            row[i + 1] = row[i] + w;
        }
        rowCdf_[size_t(j) + 1] = rowCdf_[size_t(j)] + row[map.width];
    }
    total_ = rowCdf_.back();
}

EnvironmentSample EnvironmentDistribution::sample(const glm::dvec4& u) const {
    const int j = pick(rowCdf_.data(), map_.height, u.x * total_);
    const double* row = &columnCdf_[size_t(j) * size_t(map_.width + 1)];
    const int i = pick(row, map_.width, u.y * row[map_.width]);
    // Uniform over the texel's region: azimuth between its edges, cos theta between its rows'.
    const double phi = map_.columnEdgePhi(i) + u.z * (map_.columnEdgePhi(i + 1) - map_.columnEdgePhi(i));
    const double cosTop = portable::cos(map_.rowEdgeTheta(j)), cosBottom = portable::cos(map_.rowEdgeTheta(j + 1));
    const double cosTheta = cosTop + u.w * (cosBottom - cosTop);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    EnvironmentSample s;
    s.direction = {sinTheta * portable::sin(phi), cosTheta, -sinTheta * portable::cos(phi)};
    s.pdf = weight_[size_t(j) * size_t(map_.width) + size_t(i)] / total_ / map_.texelSolidAngle(j);
    return s;
}

double EnvironmentDistribution::pdf(const glm::dvec3& direction) const {
    const glm::ivec2 t = map_.texelToward(direction);
    return weight_[size_t(t.y) * size_t(map_.width) + size_t(t.x)] / total_ / map_.texelSolidAngle(t.y);
}

}  // namespace shadowlab
