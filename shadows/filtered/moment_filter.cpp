#include "shadows/filtered/moment_filter.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

constexpr double kUnitRoundoff = 0x1p-53;   // u of double
constexpr size_t kColumnBand = 64;          // columns summed together down the rows
constexpr size_t kMomentRun = 1024;         // texels whose moments are taken together

// Neumaier's compensated running sum: the rounding error of every addition is kept in
// `compensation` (TwoSum, exact in IEEE arithmetic without contraction) and added back.
struct CompensatedSum {
    double sum = 0.0, compensation = 0.0;
    void add(double x) {
        const double t = sum + x;
        compensation += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
        sum = t;
    }
    double value() const { return sum + compensation; }
};

// out[i] += weight * in[i] for i < n; the first tap (first = true) starts the sum from 0
// instead of reading out, which is 0 + weight in[i]: the same bits (a -0 product becomes
// +0) without clearing the fresh output first.
void addWeighted(double* __restrict out, const double* __restrict in, double weight, size_t n, bool first) {
    if (first) {
        for (size_t i = 0; i < n; ++i) out[i] = 0.0 + weight * in[i];
    } else {
        for (size_t i = 0; i < n; ++i) out[i] += weight * in[i];
    }
}

// S at a continuous corner: bilinear between the four grid points around it.
void cornerSum(const SummedAreaTable& t, glm::dvec2 p, double* out) {
    p = glm::clamp(p, glm::dvec2(0.0), glm::dvec2(t.size));
    const int x = std::min(int(p.x), t.size - 1), y = std::min(int(p.y), t.size - 1);
    const double fx = p.x - x, fy = p.y - y;
    const size_t stride = size_t(t.size) + 1;
    const double* s00 = &t.sums[(size_t(y) * stride + size_t(x)) * t.channels];
    const double* s10 = s00 + t.channels;
    const double* s01 = s00 + stride * t.channels;
    const double* s11 = s01 + t.channels;
    for (int c = 0; c < t.channels; ++c) {
        out[c] = (1.0 - fy) * ((1.0 - fx) * s00[c] + fx * s10[c]) + fy * ((1.0 - fx) * s01[c] + fx * s11[c]);
    }
}

}  // namespace

const double* MomentMap::at(int x, int y) const {
    x = std::clamp(x, 0, size - 1), y = std::clamp(y, 0, size - 1);
    return &values[(size_t(y) * size_t(size) + size_t(x)) * size_t(channels)];
}

MomentMap momentMap(const SoftShadowMap& soft, const MomentSettings& settings, raster::SimdLevel simd) {
    MomentMap m{soft.map.size, momentCount(settings.kind), {}};
    m.values.resize(soft.linear.size() * size_t(m.channels));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, soft.linear.size(), kMomentRun), [&](const tbb::blocked_range<size_t>& r) {
        double z[kMomentRun];
        for (size_t first = r.begin(); first < r.end(); first += kMomentRun) {
            const size_t count = std::min(kMomentRun, r.end() - first);
            std::copy_n(&soft.linear[first], count, z);
            momentsOfRun(settings, z, count, &m.values[first * size_t(m.channels)], simd);
        }
    });
    return m;
}

std::vector<double> blurWeights(BlurKind kind, int width) {
    std::vector<double> w(size_t(width), 1.0);
    const double sigma = width / 6.0, centre = 0.5 * (width - 1);
    if (kind == BlurKind::Gaussian) {
        for (int k = 0; k < width; ++k) w[k] = portable::exp(-0.5 * (k - centre) * (k - centre) / (sigma * sigma));
    }
    double total = 0.0;
    for (double x : w) total += x;
    for (double& x : w) x /= total;
    return w;
}

MomentMap blurMoments(const MomentMap& in, const std::vector<double>& weights) {
    const int half = int(weights.size() / 2), size = in.size;
    const size_t channels = size_t(in.channels), rowValues = size_t(size) * channels;
    // out(x, y) = sum_k w_k in(x + (k - half) dx, y + (k - half) dy), the taps in order: each
    // pass adds one tap's weighted row to every output of a row before the next tap, so the
    // inner loops run over contiguous values (vectorised by the compiler) and every output
    // still sums its taps in order, as one texel at a time would.
    const auto pass = [&](const MomentMap& from, bool alongX) {
        MomentMap to{size, from.channels, {}};
        to.values.resize(from.values.size());
        tbb::parallel_for(0, size, [&](int y) {
            double* out = &to.values[size_t(y) * rowValues];
            for (int k = 0; k < int(weights.size()); ++k) {
                const int o = k - half;
                const double w = weights[k];
                if (!alongX) {
                    addWeighted(out, from.at(0, y + o), w, rowValues, k == 0);
                    continue;
                }
                // Along x: the taps inside the row are a shifted copy of it; those past an
                // edge read the border texel.
                const int first = std::clamp(-o, 0, size), last = std::clamp(size - o, first, size);
                for (int x = 0; x < first; ++x) addWeighted(out + size_t(x) * channels, from.at(x + o, y), w, channels, k == 0);
                addWeighted(out + size_t(first) * channels, from.at(first + o, y), w, size_t(last - first) * channels, k == 0);
                for (int x = last; x < size; ++x) addWeighted(out + size_t(x) * channels, from.at(x + o, y), w, channels, k == 0);
            }
        });
        return to;
    };
    return pass(pass(in, true), false);
}

void sampleBilinear(const MomentMap& m, const glm::dvec2& texel, double* out) {
    const glm::dvec2 base = texel - 0.5;
    const int x = texelIndexOf(base.x), y = texelIndexOf(base.y);
    const double fx = base.x - x, fy = base.y - y;
    const double *a, *b, *c, *d;
    if (x >= 0 && y >= 0 && x + 1 < m.size && y + 1 < m.size) {
        // Inside the map (every receiver the fit keeps its margin from the sides): the four
        // texels are neighbours in storage, no clamping.
        const size_t channels = size_t(m.channels);
        a = &m.values[(size_t(y) * size_t(m.size) + size_t(x)) * channels];
        b = a + channels, c = a + size_t(m.size) * channels, d = c + channels;
    } else {
        a = m.at(x, y), b = m.at(x + 1, y), c = m.at(x, y + 1), d = m.at(x + 1, y + 1);
    }
    for (int k = 0; k < m.channels; ++k) out[k] = (1.0 - fy) * ((1.0 - fx) * a[k] + fx * b[k]) + fy * ((1.0 - fx) * c[k] + fx * d[k]);
}

SummedAreaTable summedAreaTable(const MomentMap& m) {
    SummedAreaTable t{m.size, m.channels, {}};
    const size_t stride = size_t(m.size) + 1, channels = size_t(m.channels);
    t.sums.assign(stride * stride * channels, 0.0);
    const auto entry = [&](size_t X, size_t Y, int c) -> double& { return t.sums[(Y * stride + X) * channels + size_t(c)]; };
    // Rows: S_row(X, y) = sum of texels x < X of row y, stored at grid row y + 1.
    tbb::parallel_for(0, m.size, [&](int y) {
        for (int c = 0; c < m.channels; ++c) {
            CompensatedSum s;
            for (int x = 0; x < m.size; ++x) s.add(m.at(x, y)[c]), entry(size_t(x) + 1, size_t(y) + 1, c) = s.value();
        }
    });
    // Columns: S(X, Y) = sum over grid rows 1..Y of the row prefixes. A band of columns
    // walks down the rows together, so each step reads a contiguous run of a row instead
    // of one value per cache line; every column's sum takes the same terms in the same order.
    tbb::parallel_for(tbb::blocked_range<size_t>(1, stride, kColumnBand), [&](const tbb::blocked_range<size_t>& band) {
        std::vector<CompensatedSum> column(band.size() * channels);
        for (size_t Y = 1; Y <= size_t(m.size); ++Y) {
            for (size_t X = band.begin(); X < band.end(); ++X) {
                for (int c = 0; c < m.channels; ++c) {
                    CompensatedSum& s = column[(X - band.begin()) * channels + size_t(c)];
                    s.add(entry(X, Y, c)), entry(X, Y, c) = s.value();
                }
            }
        }
    });
    return t;
}

void boxMean(const SummedAreaTable& t, glm::dvec2 lo, glm::dvec2 hi, double* out) {
    const glm::dvec2 centre = 0.5 * (lo + hi);
    lo = glm::min(lo, centre - 0.5), hi = glm::max(hi, centre + 0.5);
    // Clipped to the map, keeping at least one texel (a receiver at the border).
    lo = glm::clamp(lo, glm::dvec2(0.0), glm::dvec2(t.size - 1)), hi = glm::clamp(hi, lo + 1.0, glm::dvec2(t.size));
    double a[kMaxMoments], b[kMaxMoments], c[kMaxMoments], d[kMaxMoments];
    cornerSum(t, hi, a), cornerSum(t, glm::dvec2(lo.x, hi.y), b), cornerSum(t, glm::dvec2(hi.x, lo.y), c), cornerSum(t, lo, d);
    const double area = (hi.x - lo.x) * (hi.y - lo.y);
    for (int k = 0; k < t.channels; ++k) out[k] = ((a[k] - b[k]) - (c[k] - d[k])) / area;
}

double satRelativeError(const MomentSettings& settings, const MomentMap& m) {
    return kSatErrorUlps * kUnitRoundoff * double(m.size) * double(m.size) * momentDynamicRange(settings);
}

}  // namespace shadowlab
