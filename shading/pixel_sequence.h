// Light samples that change from frame to frame and spread well within a pixel and across
// its neighbours: what a real-time tracer with a few rays per pixel casts, and what temporal
// accumulation then averages (docs/ray-traced-shadows.md).
//
// Sample s of the `count` a pixel casts in frame f is point f * count + s of the
// (0, 2)-sequence in base 2 (light_sampling.h, sobol02), Cranley-Patterson shifted by the
// pixel's own offset. So a pixel's samples of one frame are consecutive points of the
// sequence (a block of 2^m of them puts one in each elementary rectangle), and the next
// frame takes the next ones: over frames a pixel sees the sequence itself, and its mean
// converges as the sequence's does. The offset's first coordinate is Jimenez's interleaved
// gradient noise (Next Generation Post Processing in Call of Duty: Advanced Warfare,
// SIGGRAPH 2014 course, slide 123), whose every 3 x 3 block of pixels covers [0, 1) nearly
// evenly, so neighbouring pixels sample different parts of the light; the second is a
// hash of the pixel (PCG32 stream of its index), so the shift is uniform on the square
// and each pixel's estimate stays unbiased. Each value depends only on (seed, x, y, frame,
// s): the same bits on any thread.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

// Interleaved gradient noise at the point (x, y) of the image, pixel units: fract(52.9829189
// fract(0.06711056 x + 0.00583715 y)), in double and cut to a multiple of 2^-32 in [0, 1).
// The ray samples' shift reads it at a pixel's corner (x, y); the shadow maps' rotated disks
// at its centre moved on with the frame (shadows/maps/pcf.h).
double interleavedGradientNoise(double x, double y);

// Which points a pixel's samples are: `count` per frame, frame `frame` of a sequence.
struct PixelSequence {
    int count = 1;
    uint32_t frame = 0;
    uint64_t seed = 0x5eed5eed5eedull;   // the shift's hash
};

// The pixel's Cranley-Patterson shift (see the top of the file); `pixel` is its index in the
// image, (x, y) its column and row.
glm::dvec2 pixelShift(const PixelSequence& sequence, int x, int y, uint64_t pixel);

// The pixel's `count` samples in [0, 1)^2 for its frame, in order, into `out` (resized:
// reused from call to call, a steady state allocates nothing).
void pixelSamples(const PixelSequence& sequence, int x, int y, uint64_t pixel, std::vector<glm::dvec2>& out);

}  // namespace shadowlab
