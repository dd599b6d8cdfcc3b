#include "compositing/differential/environment_dome.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// The map's mean radiance over each block of the upper hemisphere (weighted by the texels'
// solid angles), rows from the zenith, columns in the map's order.
std::vector<glm::dvec3> domeRadiance(const EnvironmentMap& map, int columns, int rows) {
    std::vector<glm::dvec3> sum(size_t(columns * rows), glm::dvec3(0.0));
    std::vector<double> weight(sum.size(), 0.0);
    for (int j = 0; j < map.height / 2; ++j) {
        const double omega = map.texelSolidAngle(j);
        const int row = std::min(rows - 1, j * rows / (map.height / 2));
        for (int i = 0; i < map.width; ++i) {
            const size_t cell = size_t(row * columns + std::min(columns - 1, i * columns / map.width));
            sum[cell] += glm::dvec3(map.at(i, j)) * omega, weight[cell] += omega;
        }
    }
    for (size_t c = 0; c < sum.size(); ++c) sum[c] = weight[c] > 0.0 ? sum[c] / weight[c] : glm::dvec3(0.0);
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
