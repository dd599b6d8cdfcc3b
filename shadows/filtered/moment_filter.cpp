#include "shadows/filtered/moment_filter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

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

// out[i] = sum_k weights[k] sources[k][i] for i < n, the taps added in order to a sum that
// starts from 0 (as a cleared output would). A chunk of outputs stays in registers across
// all the taps, so each is stored once instead of read and written back per tap.
void weightedSum(double* __restrict out, const double* const* sources, const double* weights, size_t taps, size_t n) {
    constexpr size_t kChunk = 8;
    size_t i = 0;
    for (; i + kChunk <= n; i += kChunk) {
        double sum[kChunk];
        for (size_t j = 0; j < kChunk; ++j) sum[j] = 0.0 + weights[0] * sources[0][i + j];
        for (size_t k = 1; k < taps; ++k) {
            for (size_t j = 0; j < kChunk; ++j) sum[j] += weights[k] * sources[k][i + j];
        }
        for (size_t j = 0; j < kChunk; ++j) out[i + j] = sum[j];
    }
    for (; i < n; ++i) {
        double sum = 0.0 + weights[0] * sources[0][i];
        for (size_t k = 1; k < taps; ++k) sum += weights[k] * sources[k][i];
        out[i] = sum;
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

MomentMap momentMap(const SoftShadowMap& soft, const MomentSettings& settings, raster::SimdLevel simd, MomentMap memory) {
    MomentMap m{soft.map.size, momentCount(settings.kind), std::move(memory.values)};
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
    MomentMap rows, out;
    blurMoments(in, weights, rows, out);
    return out;
}

void blurMoments(const MomentMap& in, const std::vector<double>& weights, MomentMap& rows, MomentMap& out) {
    if (weights.empty() || weights.size() > kMaxBlurTaps) {
        throw std::invalid_argument("blur of " + std::to_string(weights.size()) + " taps; 1 to " +
                                    std::to_string(kMaxBlurTaps) + " are possible");
    }
    const int half = int(weights.size() / 2), size = in.size;
    const size_t channels = size_t(in.channels), rowValues = size_t(size) * channels;
    // out(x, y) = sum_k w_k in(x + (k - half) dx, y + (k - half) dy), the taps in order.
    // Where every tap lies inside the map, tap k's inputs for a run of outputs are a
    // contiguous run too (the rows above and below, or the row shifted), so the run is one
    // weightedSum over them; a texel with taps past an edge reads the border texel.
    const size_t taps = weights.size();   // at most kMaxBlurTaps (filter-width's range)
    const auto pass = [&](const MomentMap& from, bool alongX, MomentMap& to) {
        to.size = size, to.channels = from.channels;
        to.values.resize(from.values.size());
        tbb::parallel_for(0, size, [&](int y) {
            std::array<const double*, kMaxBlurTaps> sources;
            double* out = &to.values[size_t(y) * rowValues];
            if (!alongX) {
                for (size_t k = 0; k < taps; ++k) sources[k] = from.at(0, y + int(k) - half);
                weightedSum(out, sources.data(), weights.data(), taps, rowValues);
            } else {
                // Texels [x0, x1) of the row: one run where every tap is inside the map,
                // else a single texel whose taps past an edge read the border texel.
                const auto blurRun = [&](int x0, int x1) {
                    const bool inside = x0 - half >= 0 && x1 - 1 + half < size;
                    for (size_t k = 0; k < taps; ++k) {
                        const int x = x0 + int(k) - half;
                        sources[k] = inside ? &from.values[size_t(y) * rowValues + size_t(x) * channels] : from.at(x, y);
                    }
                    weightedSum(out + size_t(x0) * channels, sources.data(), weights.data(), taps, size_t(x1 - x0) * channels);
                };
                const int first = std::min(half, size), last = std::max(first, size - half);
                for (int x = 0; x < first; ++x) blurRun(x, x + 1);
                if (first < last) blurRun(first, last);
                for (int x = last; x < size; ++x) blurRun(x, x + 1);
            }
        });
    };
    pass(in, true, rows);
    pass(rows, false, out);
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

void sampleBilinearRun(const MomentMap& m, const glm::dvec2* texels, size_t count, double* out) {
    // The receivers of a camera row wander across the map, so most lookups miss the cache:
    // the rows of texels a few receivers ahead are requested while this one is read.
    constexpr size_t kAhead = 8;
    for (size_t r = 0; r < count; ++r) {
        if (r + kAhead < count) {
            const glm::dvec2 ahead = texels[r + kAhead] - 0.5;   // any value: texelIndexOf and at() clamp
            const int x = texelIndexOf(ahead.x), y = texelIndexOf(ahead.y);
            __builtin_prefetch(m.at(x, y)), __builtin_prefetch(m.at(x, y + 1));
        }
        sampleBilinear(m, texels[r], out + size_t(m.channels) * r);
    }
}

SummedAreaTable summedAreaTable(const MomentMap& m, SummedAreaTable memory) {
    SummedAreaTable t{m.size, m.channels, std::move(memory.sums)};
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
