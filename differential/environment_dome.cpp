#include "differential/environment_dome.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// How texel k of an axis cut into `texels` shares [0, end) cut into `blocks` equal blocks:
// the measure of each texel's part in each block it reaches.
struct AxisShare {
    int texel, block;
    double measure;
};
template <class Measure>
std::vector<AxisShare> axisShares(int texels, int blocks, double end, const Measure& measure) {
    std::vector<AxisShare> shares;
    for (int k = 0; k < texels; ++k) {
        const double t0 = double(k) / texels, t1 = double(k + 1) / texels;
        for (int b = int(t0 / end * blocks); b < blocks && end * b / blocks < t1; ++b) {
            const double lo = std::max(t0, end * b / blocks), hi = std::min(t1, end * (b + 1) / blocks);
            if (hi > lo) shares.push_back({k, b, measure(lo, hi)});
        }
    }
    return shares;
}

// The map's mean radiance over each block of the upper hemisphere, rows from the zenith,
// columns in the map's order: each texel weighted by the solid angle it shares with the
// block, so the blocks hold the map's light above the horizon exactly however many there
// are (blocks finer than the texels share them rather than stay dark).
std::vector<glm::dvec3> domeRadiance(const EnvironmentMap& map, int columns, int rows) {
    const std::vector<AxisShare> across = axisShares(map.width, columns, 1.0, [](double u0, double u1) {
        return 2.0 * kPi * (u1 - u0);
    });
    const std::vector<AxisShare> down = axisShares(map.height, rows, 0.5, [](double v0, double v1) {
        return portable::cos(kPi * v0) - portable::cos(kPi * v1);   // theta = pi v
    });
    std::vector<glm::dvec3> sum(size_t(columns * rows), glm::dvec3(0.0));
    std::vector<double> weight(sum.size(), 0.0);
    for (const AxisShare& row : down) {
        for (const AxisShare& column : across) {
            const size_t cell = size_t(row.block * columns + column.block);
            const double omega = row.measure * column.measure;
            sum[cell] += glm::dvec3(map.at(column.texel, row.texel)) * omega, weight[cell] += omega;
        }
    }
    for (size_t c = 0; c < sum.size(); ++c) sum[c] /= weight[c];   // every block holds some texel
    return sum;
}

// Block (a, b) as a rectangle tangent to the dome at its centre direction, facing in, of
// exactly the block's solid angle at the dome's radius.
PatchSurface domeCell(const EnvironmentMap& map, int a, int b, int columns, int rows, double R,
                      const glm::dvec3& radiance) {
    const double u0 = double(a) / columns, u1 = double(a + 1) / columns;
    const double v0 = 0.5 * double(b) / rows, v1 = 0.5 * double(b + 1) / rows;
    const double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
    const glm::dvec3 centre = map.direction(u, v);
    const glm::dvec3 along = glm::normalize(map.direction(u1, v) - map.direction(u0, v));
    const glm::dvec3 down = glm::normalize(map.direction(u, v1) - map.direction(u, v0));
    const double theta0 = kPi * v0, theta1 = kPi * v1, sine = std::sqrt(std::max(0.0, 1.0 - centre.y * centre.y));
    const double width = R * 2.0 * kPi * (u1 - u0) * sine;
    const double height = R * (portable::cos(theta0) - portable::cos(theta1)) / std::max(sine, 1e-6);
    glm::dvec3 U = width * along, V = height * down;
    if (glm::dot(glm::cross(U, V), centre) > 0.0) std::swap(U, V);   // the front faces the centre
    return {"sky", R * centre - 0.5 * (U + V), U, V, 1, 1, glm::dvec3(0.0), {radiance}};
}

}  // namespace

std::vector<PatchSurface> environmentDome(const EnvironmentMap& map, int columns, int rows, double radiusM) {
    if (columns < 4 || rows < 1) throw std::invalid_argument("environment dome: needs 4 columns and 1 row or more");
    if (!(radiusM > 0.0)) throw std::invalid_argument("environment dome: the radius must be positive");
    if (size_t(columns) * size_t(rows) > kMaxCompositingPatches)   // before the map is summed into cells
        throw std::invalid_argument("environment dome: " + std::to_string(size_t(columns) * size_t(rows)) +
                                    " patches, more than " + std::to_string(kMaxCompositingPatches));
    const std::vector<glm::dvec3> radiance = domeRadiance(map, columns, rows);
    std::vector<PatchSurface> dome;
    for (int b = 0; b < rows; ++b) {
        for (int a = 0; a < columns; ++a) {
            dome.push_back(domeCell(map, a, b, columns, rows, radiusM, radiance[size_t(b * columns + a)]));
        }
    }
    return dome;
}

}  // namespace shadowlab
