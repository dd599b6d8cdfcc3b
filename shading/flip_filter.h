// The separable convolution both stages of FLIP filter with (shading/flip_colour.h,
// shading/flip_features.h): a 1D kernel along the rows, then one along the columns, with the
// image's border pixels repeated beyond it (Andersson et al. 2020 filter this way; their
// kernels are Gaussians and sums of Gaussians, separable as products of 1D ones).
#pragma once

#include <cstddef>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab::flip {

// One channel of an image, row-major, row 0 at the top.
struct Plane {
    int width = 0, height = 0;
    std::vector<float> values;
    Plane() = default;
    Plane(int w, int h) : width(w), height(h), values(size_t(w) * size_t(h)) {}
};

// An odd number of taps, 2r + 1; tap k weighs the pixel k - r away. Even (kernel[k] =
// kernel[2r - k]) or odd (kernel[k] = -kernel[2r - k]), as Gaussians and their derivatives
// are: the convolutions throw std::invalid_argument for another.
using Kernel = std::vector<float>;

// out(x, y) = sum over k of kernel[k] in(clamp(x + k - r), y), rows in parallel: each pixel's
// sum runs in the same order on every thread count and vector width.
void convolveRows(const Plane& in, const Kernel& kernel, Plane& out);
// The same down the columns: out(x, y) = sum over k of kernel[k] in(x, clamp(y + k - r)).
void convolveColumns(const Plane& in, const Kernel& kernel, Plane& out);

// Calls f(p) for every pixel index p of a width x height image, rows in parallel: for the
// stages' per-pixel steps, each of which writes pixel p alone.
template <class F>
void forEachPixel(int width, int height, const F& f) {
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        for (size_t p = size_t(rows.begin()) * size_t(width); p < size_t(rows.end()) * size_t(width); ++p) f(p);
    });
}

}  // namespace shadowlab::flip
