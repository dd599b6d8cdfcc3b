// Rows: each row is copied with r repeated border pixels on either side, so that the inner
// loop over x has no branch and vectorises; the taps stay the outer loop, so every pixel
// adds them in the order k = 0 .. 2r whatever the vector width (-ffp-contract=off keeps the
// products and sums apart). Columns: the same, a whole row of the output at a time.
#include "shading/flip_filter.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab::flip {
namespace {

int radiusOf(const Kernel& kernel) {
    if (kernel.size() % 2 != 1) throw std::invalid_argument("FLIP filter: a kernel has an odd number of taps");
    return int(kernel.size() / 2);
}

void requireSize(const Plane& in, Plane& out) {
    if (out.width != in.width || out.height != in.height) out = Plane(in.width, in.height);
}

}  // namespace

void convolveRows(const Plane& in, const Kernel& kernel, Plane& out) {
    requireSize(in, out);
    const int r = radiusOf(kernel), w = in.width;
    tbb::parallel_for(tbb::blocked_range<int>(0, in.height), [&](const tbb::blocked_range<int>& rows) {
        std::vector<float> padded(size_t(w + 2 * r));
        for (int y = rows.begin(); y != rows.end(); ++y) {
            const float* row = in.values.data() + size_t(y) * size_t(w);
            for (int x = -r; x < w + r; ++x) padded[size_t(x + r)] = row[std::clamp(x, 0, w - 1)];
            float* o = out.values.data() + size_t(y) * size_t(w);
            std::fill(o, o + w, 0.0f);
            for (size_t k = 0; k < kernel.size(); ++k) {
                const float weight = kernel[k];
                const float* source = padded.data() + k;
                for (int x = 0; x < w; ++x) o[x] += weight * source[x];
            }
        }
    });
}

void convolveColumns(const Plane& in, const Kernel& kernel, Plane& out) {
    requireSize(in, out);
    const int r = radiusOf(kernel), w = in.width, h = in.height;
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
            float* o = out.values.data() + size_t(y) * size_t(w);
            std::fill(o, o + w, 0.0f);
            for (size_t k = 0; k < kernel.size(); ++k) {
                const float weight = kernel[k];
                const int source = std::clamp(y + int(k) - r, 0, h - 1);
                const float* s = in.values.data() + size_t(source) * size_t(w);
                for (int x = 0; x < w; ++x) o[x] += weight * s[x];
            }
        }
    });
}

}  // namespace shadowlab::flip
