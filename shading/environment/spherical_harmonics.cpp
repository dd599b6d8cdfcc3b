#include "shading/environment/spherical_harmonics.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab {
namespace {

const double kC0 = 0.5 / std::sqrt(kPi), kC1 = std::sqrt(3.0 / (4.0 * kPi)), kC2 = std::sqrt(15.0 / (4.0 * kPi));
const double kC20 = std::sqrt(5.0 / (16.0 * kPi)), kC22 = std::sqrt(15.0 / (16.0 * kPi));

// The band of coefficient k, and the clamped cosine's A_l (Ramamoorthi and Hanrahan, eq. 8).
constexpr int kBand[kShCoefficients] = {0, 1, 1, 1, 2, 2, 2, 2, 2};
constexpr double kLobe[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};

// The row's integrals of the polar factors against sin(theta) d theta over [theta0, theta1]:
// 1, cos, 3 cos^2 - 1, sin, sin cos, sin^2 (the basis's functions of theta).
struct RowIntegrals {
    double one, cos, zonal2, sin, sinCos, sin2;
};

RowIntegrals rowIntegrals(double theta0, double theta1) {
    const double c0 = portable::cos(theta0), c1 = portable::cos(theta1);
    const double s0 = portable::sin(theta0), s1 = portable::sin(theta1);
    return {c0 - c1,
            0.5 * (c0 * c0 - c1 * c1),
            (c1 - c1 * c1 * c1) - (c0 - c0 * c0 * c0),
            0.5 * (theta1 - theta0) - 0.25 * (portable::sin(2.0 * theta1) - portable::sin(2.0 * theta0)),
            (s1 * s1 * s1 - s0 * s0 * s0) / 3.0,
            (c0 - c0 * c0 * c0 / 3.0) - (c1 - c1 * c1 * c1 / 3.0)};
}

// The column's integrals over [phi0, phi1] d phi: 1, sin, cos, sin cos, cos 2 phi.
struct ColumnIntegrals {
    double one, sin, cos, sinCos, cos2;
};

ColumnIntegrals columnIntegrals(double phi0, double phi1) {
    const double s0 = portable::sin(phi0), s1 = portable::sin(phi1);
    return {phi1 - phi0,
            portable::cos(phi0) - portable::cos(phi1),
            s1 - s0,
            0.5 * (s1 * s1 - s0 * s0),
            0.5 * (portable::sin(2.0 * phi1) - portable::sin(2.0 * phi0))};
}

// With x = sin(theta) sin(phi), y = cos(theta), z = -sin(theta) cos(phi) (environment_map.h):
// x^2 - z^2 = -sin^2(theta) cos(2 phi), x z = -sin^2(theta) sin(phi) cos(phi).
std::array<double, kShCoefficients> texelIntegrals(const RowIntegrals& r, const ColumnIntegrals& c) {
    return {kC0 * r.one * c.one,        kC1 * r.sin * c.sin,          kC1 * r.cos * c.one,
            -kC1 * r.sin * c.cos,       kC2 * r.sinCos * c.sin,       -kC2 * r.sinCos * c.cos,
            kC20 * r.zonal2 * c.one,    -kC2 * r.sin2 * c.sinCos,     -kC22 * r.sin2 * c.cos2};
}

}  // namespace

std::array<double, kShCoefficients> shBasis(const glm::dvec3& d) {
    return {kC0,
            kC1 * d.x,
            kC1 * d.y,
            kC1 * d.z,
            kC2 * d.x * d.y,
            kC2 * d.y * d.z,
            kC20 * (3.0 * d.y * d.y - 1.0),
            kC2 * d.x * d.z,
            kC22 * (d.x * d.x - d.z * d.z)};
}

ShCoefficients projectRadiance(const EnvironmentMap& map) {
    std::vector<ColumnIntegrals> columns(size_t(map.width));
    for (int i = 0; i < map.width; ++i) columns[i] = columnIntegrals(map.columnEdgePhi(i), map.columnEdgePhi(i + 1));
    std::vector<ShCoefficients> rows(size_t(map.height));
    tbb::parallel_for(0, map.height, [&](int j) {
        const RowIntegrals row = rowIntegrals(map.rowEdgeTheta(j), map.rowEdgeTheta(j + 1));
        ShCoefficients& sum = rows[j];
        for (int i = 0; i < map.width; ++i) {
            const std::array<double, kShCoefficients> integral = texelIntegrals(row, columns[i]);
            const glm::dvec3 L(map.at(i, j));
            for (int k = 0; k < kShCoefficients; ++k) sum.c[k] += integral[k] * L;
        }
    });
    ShCoefficients total;
    for (const ShCoefficients& row : rows) {
        for (int k = 0; k < kShCoefficients; ++k) total.c[k] += row.c[k];
    }
    return total;
}

void checkShWindow(double windowWidth) {
    if (windowWidth != 0.0 && !(windowWidth > 2.0 && std::isfinite(windowWidth))) {
        throw std::invalid_argument("spherical-harmonic window width must be 0 (off) or a number above 2, not " +
                                    std::to_string(windowWidth));
    }
}

ShCoefficients irradianceOf(const ShCoefficients& radiance, double windowWidth) {
    checkShWindow(windowWidth);
    ShCoefficients out;
    for (int k = 0; k < kShCoefficients; ++k) {
        const int l = kBand[k];
        double sigma = 1.0;
        if (windowWidth != 0.0 && l > 0) {
            const double x = kPi * l / windowWidth, sinc = portable::sin(x) / x;
            sigma = sinc * sinc * sinc * sinc;
        }
        out.c[k] = kLobe[l] * sigma * radiance.c[k];
    }
    return out;
}

glm::dvec3 evaluateSh(const ShCoefficients& coefficients, const glm::dvec3& direction) {
    const std::array<double, kShCoefficients> y = shBasis(direction);
    glm::dvec3 sum(0.0);
    for (int k = 0; k < kShCoefficients; ++k) sum += coefficients.c[k] * y[k];
    return sum;
}

}  // namespace shadowlab
