// A pixel's samples that move on from frame to frame (pixel_sequence.h):
//  - a frame's N = 2^m samples, the pixel's shift taken off (mod 1), are points fN..fN+N-1
//    of the (0, 2)-sequence: one in each of the N rows and each of the N columns of the
//    unit square, and the next frame's are the next block;
//  - interleaved gradient noise lies in [0, 1) on multiples of 2^-32, and every 3 x 3 block
//    of pixels covers [0, 1) nearly evenly: no gap between its 9 values (cyclically) wider
//    than 0.14, where evenly spaced values leave 1/9 = 0.111 and 9 independent uniform ones
//    leave one wider than 0.3 more often than not;
//  - the samples are a function of (seed, x, y, frame, s) alone.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "shading/light_sampling.h"
#include "shading/pixel_sequence.h"

using namespace shadowlab;

TEST_CASE("pixel sequence: a frame's 2^m samples are one block of the (0,2)-sequence, shifted per pixel") {
    for (int count : {1, 4, 16, 64}) {
        for (uint32_t frame : {0u, 1u, 7u, 1000u}) {
            const PixelSequence sequence{.count = count, .frame = frame};
            const int x = 37, y = 11;
            const uint64_t pixel = 11 * 640 + 37;
            std::vector<glm::dvec2> u;
            pixelSamples(sequence, x, y, pixel, u);
            REQUIRE(u.size() == size_t(count));
            const glm::dvec2 shift = pixelShift(sequence, x, y, pixel);
            std::set<int> rows, columns;
            for (int s = 0; s < count; ++s) {
                CAPTURE(count);
                CAPTURE(s);
                CHECK(u[s] == shiftedSobol02(frame * uint32_t(count) + uint32_t(s), shift));
                const glm::dvec2 unshifted = u[s] - shift - glm::floor(u[s] - shift);
                columns.insert(int(std::floor(unshifted.x * count))), rows.insert(int(std::floor(unshifted.y * count)));
                CHECK((u[s].x >= 0.0 && u[s].x < 1.0 && u[s].y >= 0.0 && u[s].y < 1.0));
            }
            CHECK(rows.size() == size_t(count));
            CHECK(columns.size() == size_t(count));
        }
    }
}

TEST_CASE("pixel sequence: interleaved gradient noise covers every 3 x 3 block of pixels nearly evenly") {
    double widest = 0.0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            std::vector<double> v;
            for (int j = 0; j < 3; ++j) {
                for (int i = 0; i < 3; ++i) {
                    const double n = interleavedGradientNoise(x + i, y + j);
                    REQUIRE((n >= 0.0 && n < 1.0));
                    REQUIRE(n * 0x1p32 == std::floor(n * 0x1p32));
                    v.push_back(n);
                }
            }
            std::ranges::sort(v);
            double gap = v.front() + 1.0 - v.back();
            for (size_t k = 1; k < v.size(); ++k) gap = std::max(gap, v[k] - v[k - 1]);
            widest = std::max(widest, gap);
        }
    }
    INFO("widest gap " << widest);
    CHECK(widest < 0.14);
}

TEST_CASE("pixel sequence: the samples depend on the pixel, the frame and the seed alone") {
    std::vector<glm::dvec2> a, b, c;
    const PixelSequence sequence{.count = 8, .frame = 3};
    pixelSamples(sequence, 5, 9, 12345, a);
    pixelSamples({.count = 8, .frame = 4}, 5, 9, 12345, c);
    pixelSamples(sequence, 5, 9, 12345, b);
    CHECK(a == b);
    CHECK(a != c);
    pixelSamples({.count = 8, .frame = 3, .seed = 7}, 5, 9, 12345, c);
    CHECK(a != c);
}
