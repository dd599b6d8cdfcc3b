// Rows: each row is copied with r repeated border pixels on either side, so that the inner
// loop over x has no branch and vectorises; the taps stay the outer loop, so every pixel
// adds them in one order whatever the vector width (-ffp-contract=off keeps the products and
// sums apart). Columns: the same, a whole row of the output at a time. FLIP's kernels are
// Gaussians and their derivatives, even or odd about the centre, so taps k and 2r - k are
// summed (or subtracted) first and weighed once: half the multiplications. Each pixel's sum
// runs: the centre tap, then the pairs k = 0 .. r - 1.
#include "shading/flip_filter.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab::flip {
namespace {

// +1 for an even kernel, -1 for an odd one (its centre tap 0); throws for another.
float parityOf(const Kernel& kernel) {
    if (kernel.size() % 2 != 1) throw std::invalid_argument("FLIP filter: a kernel has an odd number of taps");
    const size_t last = kernel.size() - 1;
    const auto mirrored = [&](float sign) {
        for (size_t k = 0; k <= last; ++k)
            if (kernel[k] != sign * kernel[last - k]) return false;
        return true;
    };
    if (mirrored(1.0f)) return 1.0f;
    if (mirrored(-1.0f)) return -1.0f;
    throw std::invalid_argument("FLIP filter: a kernel is neither even nor odd about its centre");
}

// o[x] = sum of kernel[k] source[x + k] over k, the mirrored taps paired.
void weighPairs(const Kernel& kernel, float parity, const float* const* sources, float* o, int w) {
    const size_t r = kernel.size() / 2;
    const float centre = kernel[r];
    for (int x = 0; x < w; ++x) o[x] = centre * sources[r][x];
    for (size_t k = 0; k < r; ++k) {
        const float weight = kernel[k];
        const float* near = sources[k];
        const float* far = sources[2 * r - k];
        for (int x = 0; x < w; ++x) o[x] += weight * (near[x] + parity * far[x]);
    }
}

void requireSize(const Plane& in, Plane& out) {
    if (out.width != in.width || out.height != in.height) out = Plane(in.width, in.height);
}

}  // namespace

void convolveRows(const Plane& in, const Kernel& kernel, Plane& out) {
    requireSize(in, out);
    const float parity = parityOf(kernel);
    const int r = int(kernel.size() / 2), w = in.width;
    tbb::parallel_for(tbb::blocked_range<int>(0, in.height), [&](const tbb::blocked_range<int>& rows) {
        std::vector<float> padded(size_t(w + 2 * r));
        std::vector<const float*> sources(kernel.size());
        for (size_t k = 0; k < kernel.size(); ++k) sources[k] = padded.data() + k;
        for (int y = rows.begin(); y != rows.end(); ++y) {
            const float* row = in.values.data() + size_t(y) * size_t(w);
            for (int x = -r; x < w + r; ++x) padded[size_t(x + r)] = row[std::clamp(x, 0, w - 1)];
            weighPairs(kernel, parity, sources.data(), out.values.data() + size_t(y) * size_t(w), w);
        }
    });
}

void convolveColumns(const Plane& in, const Kernel& kernel, Plane& out) {
    requireSize(in, out);
    const float parity = parityOf(kernel);
    const int r = int(kernel.size() / 2), w = in.width, h = in.height;
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
        std::vector<const float*> sources(kernel.size());
        for (int y = rows.begin(); y != rows.end(); ++y) {
            for (size_t k = 0; k < kernel.size(); ++k)
                sources[k] = in.values.data() + size_t(std::clamp(y + int(k) - r, 0, h - 1)) * size_t(w);
            weighPairs(kernel, parity, sources.data(), out.values.data() + size_t(y) * size_t(w), w);
        }
    });
}

}  // namespace shadowlab::flip
