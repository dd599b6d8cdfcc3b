// FLIP's colour pipeline. Constants are the paper's (sec. "Spatial filtering", Table of the
// CSF Gaussians' a_i, b_i); the colour matrices are those of the sRGB primaries and D65 white
// (IEC 61966-2-1: x, y of R 0.64 0.33, G 0.30 0.60, B 0.15 0.06, white 0.3127 0.3290), so
// that linear RGB (1, 1, 1) is the white point and Yy of white is 100.
#include "shading/flip_colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab::flip {
namespace {

// The CSF's two Gaussians per channel (sec. "Spatial filtering"): a_1, b_1, a_2, b_2.
struct CsfGaussians {
    float a1, b1, a2, b2;
};
constexpr std::array<CsfGaussians, 3> kCsf{{
    {1.0f, 0.0047f, 0.0f, 1e-5f},     // Yy
    {1.0f, 0.0053f, 0.0f, 1e-5f},     // Cx
    {34.1f, 0.04f, 13.5f, 0.025f},    // Cz
}};

using Matrix3 = std::array<std::array<float, 3>, 3>;   // rows
constexpr Matrix3 kRgbToXyz{{{0.412390799f, 0.357584339f, 0.180480788f},
                             {0.212639006f, 0.715168679f, 0.072192315f},
                             {0.019330819f, 0.119194780f, 0.950532152f}}};
constexpr Matrix3 kXyzToRgb{{{3.240969942f, -1.537383178f, -0.498610760f},
                             {-0.969243636f, 1.875967502f, 0.041555057f},
                             {0.055630080f, -0.203976959f, 1.056971514f}}};

glm::vec3 operator*(const Matrix3& m, const glm::vec3& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}
// The rows of kRgbToXyz summed: XYZ of the display's white.
constexpr glm::vec3 kWhite{0.950455927f, 1.0f, 1.089057751f};

// t^(1/3) for a normal t > 0: a first guess from the bits (the exponent divided by 3, Kahan's
// constant for the mantissa; within 4 %), then Halley's steps y <- y (y^3 + 2t) / (2y^3 + t),
// each cubing the relative error: two reach 1e-12, far below float's. Integer and IEEE
// arithmetic only, so the bits are the same on every CPU.
double cubeRoot(double t) {
    const uint64_t bits = __builtin_bit_cast(uint64_t, t);
    double y = __builtin_bit_cast(double, bits / 3 + 0x2a9f789300000000ull);
    for (int step = 0; step < 2; ++step) {
        const double y3 = y * y * y;
        y *= (y3 + 2.0 * t) / (2.0 * y3 + t);
    }
    return y;
}

// CIELab's f(t): the cube root above (6/29)^3, its tangent line below.
float labF(float t) {
    constexpr double delta = 6.0 / 29.0;
    return float(t > delta * delta * delta ? cubeRoot(t) : t / (3.0 * delta * delta) + 4.0 / 29.0);
}

// The 1D factor of one Gaussian of the 2D CSF, sqrt(a sqrt(pi / b)) exp(-pi^2 x^2 / b), so that
// the product of two is a sqrt(pi / b) exp(-pi^2 (x^2 + y^2) / b).
Kernel gaussianFactor(float a, float b, int radius, float pixelsPerDegree) {
    Kernel kernel(size_t(2 * radius + 1));
    const double scale = std::sqrt(double(a) * std::sqrt(kPi / double(b)));
    for (int k = -radius; k <= radius; ++k) {
        const double x = double(k) / double(pixelsPerDegree);   // degrees
        kernel[size_t(k + radius)] = float(scale * portable::exp(-kPi * kPi * x * x / double(b)));
    }
    return kernel;
}

int csfRadius(float pixelsPerDegree) {
    float widest = 0.0f;
    for (const CsfGaussians& g : kCsf) widest = std::max({widest, g.b1, g.b2});
    // A Gaussian exp(-pi^2 x^2 / b) has sigma = sqrt(b / (2 pi^2)) degrees.
    return int(std::ceil(3.0 * std::sqrt(double(widest) / (2.0 * kPi * kPi)) * double(pixelsPerDegree)));
}

struct OpponentPlanes {
    Plane yy, cx, cz;
};

OpponentPlanes toOpponent(const std::vector<glm::vec3>& rgb, int width, int height) {
    OpponentPlanes planes{Plane(width, height), Plane(width, height), Plane(width, height)};
    forEachPixel(width, height, [&](size_t p) {
        const glm::vec3 c = linearRgbToYyCxCz(rgb[p]);
        planes.yy.values[p] = c.x;
        planes.cx.values[p] = c.y;
        planes.cz.values[p] = c.z;
    });
    return planes;
}

// One channel filtered by its CSF: each Gaussian's product of 1D kernels, summed in order.
Plane filtered(const Plane& channel, const CsfFilter& filter) {
    Plane rows, sum, term;
    convolveRows(channel, filter.terms[0], rows);
    convolveColumns(rows, filter.terms[0], sum);
    for (size_t i = 1; i < filter.terms.size(); ++i) {
        convolveRows(channel, filter.terms[i], rows);
        convolveColumns(rows, filter.terms[i], term);
        for (size_t p = 0; p < sum.values.size(); ++p) sum.values[p] += term.values[p];
    }
    return sum;
}

OpponentPlanes filteredOpponent(const std::vector<glm::vec3>& rgb, int width, int height,
                                const std::array<CsfFilter, 3>& filters) {
    const OpponentPlanes planes = toOpponent(rgb, width, height);
    return {filtered(planes.yy, filters[0]), filtered(planes.cx, filters[1]), filtered(planes.cz, filters[2])};
}

// The filtered opponent colour back on the display: linear RGB clamped to its gamut.
glm::vec3 displayed(const OpponentPlanes& planes, size_t p) {
    const glm::vec3 c{planes.yy.values[p], planes.cx.values[p], planes.cz.values[p]};
    return glm::clamp(yyCxCzToLinearRgb(c), 0.0f, 1.0f);
}

}  // namespace

CsfFilter csfFilter(Opponent channel, float pixelsPerDegree) {
    if (!(pixelsPerDegree > 0.0f)) throw std::invalid_argument("FLIP: pixels per degree must be positive");
    const CsfGaussians& g = kCsf[size_t(channel)];
    const int radius = csfRadius(pixelsPerDegree);
    CsfFilter filter;
    filter.terms.push_back(gaussianFactor(g.a1, g.b1, radius, pixelsPerDegree));
    if (g.a2 != 0.0f) filter.terms.push_back(gaussianFactor(g.a2, g.b2, radius, pixelsPerDegree));
    // The 2D filter's sum is sum_i (sum of terms[i])^2: dividing every 1D kernel by its
    // square root makes it 1.
    double total = 0.0;
    for (const Kernel& kernel : filter.terms) {
        double sum = 0.0;
        for (float w : kernel) sum += w;
        total += sum * sum;
    }
    const float norm = float(1.0 / std::sqrt(total));
    for (Kernel& kernel : filter.terms)
        for (float& w : kernel) w *= norm;
    return filter;
}

glm::vec3 linearRgbToYyCxCz(const glm::vec3& rgb) {
    const glm::vec3 xyz = kRgbToXyz * rgb / kWhite;
    return {116.0f * xyz.y - 16.0f, 500.0f * (xyz.x - xyz.y), 200.0f * (xyz.y - xyz.z)};
}

glm::vec3 yyCxCzToLinearRgb(const glm::vec3& c) {
    const float y = (c.x + 16.0f) / 116.0f;
    const glm::vec3 xyz = glm::vec3(y + c.y / 500.0f, y, y - c.z / 200.0f) * kWhite;
    return kXyzToRgb * xyz;
}

glm::vec3 huntLab(const glm::vec3& rgb) {
    const glm::vec3 xyz = kRgbToXyz * rgb / kWhite;
    const float fx = labF(xyz.x), fy = labF(xyz.y), fz = labF(xyz.z);
    const float L = 116.0f * fy - 16.0f;
    return {L, 0.01f * L * (500.0f * (fx - fy)), 0.01f * L * (200.0f * (fy - fz))};
}

float hyab(const glm::vec3& lab1, const glm::vec3& lab2) {
    const float da = lab1.y - lab2.y, db = lab1.z - lab2.z;
    return std::abs(lab1.x - lab2.x) + std::sqrt(da * da + db * db);
}

float maxColourDifference() {
    return portable::powFloat(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), kColourExponent);
}

float redistributeColourDifference(float compressed, float cmax) {
    static_assert(kColourRangeSplit > 0.0f && kColourRangeSplit < 1.0f);
    const float split = kColourRangeSplit * cmax;
    if (compressed < split) return compressed * (kColourRangeTarget / split);
    return kColourRangeTarget + (compressed - split) / (cmax - split) * (1.0f - kColourRangeTarget);
}

Plane colourDifference(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, int width,
                       int height, float pixelsPerDegree) {
    const size_t n = size_t(width) * size_t(height);
    if (reference.size() != n || test.size() != n)
        throw std::invalid_argument("FLIP: the reference and the test image must both be width x height");
    const std::array<CsfFilter, 3> filters{csfFilter(Opponent::Yy, pixelsPerDegree),
                                           csfFilter(Opponent::Cx, pixelsPerDegree),
                                           csfFilter(Opponent::Cz, pixelsPerDegree)};
    const OpponentPlanes r = filteredOpponent(reference, width, height, filters);
    const OpponentPlanes t = filteredOpponent(test, width, height, filters);
    const float cmax = maxColourDifference();
    Plane difference(width, height);
    forEachPixel(width, height, [&](size_t p) {
        const float distance = hyab(huntLab(displayed(r, p)), huntLab(displayed(t, p)));
        difference.values[p] = redistributeColourDifference(portable::powFloat(distance, kColourExponent), cmax);
    });
    return difference;
}

}  // namespace shadowlab::flip
