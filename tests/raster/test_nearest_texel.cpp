// The texel rule (raster/nearest_texel.inl) at chosen coordinates: negative, integer and
// beyond 1, for each wrap mode, against texel indices computed by hand.
#include <doctest/doctest.h>

#include <limits>

#include "raster/nearest_texel.h"

using namespace shadowlab;

namespace {

constexpr TextureWrap kClamp = TextureWrap::ClampToEdge, kRepeat = TextureWrap::Repeat,
                      kMirror = TextureWrap::MirroredRepeat;

// The column (u) in a 4 x 1 texture and the row (v) in a 1 x 4 one.
int column(TextureWrap wrap, float u) { return nearestTexelIndex(4, 1, {wrap, kClamp}, {u, 0.5f}); }
int row(TextureWrap wrap, float v) { return nearestTexelIndex(1, 4, {kClamp, wrap}, {0.5f, v}); }

}  // namespace

TEST_CASE("clamp-to-edge reads the edge texel outside [0, 1]") {
    CHECK(column(kClamp, -0.25f) == 0);
    CHECK(column(kClamp, 0.6f) == 2);
    CHECK(column(kClamp, 1.0f) == 3);
    CHECK(column(kClamp, 2.6f) == 3);
    CHECK(row(kClamp, -0.25f) == 3);  // row 0 is the top, v = 1
    CHECK(row(kClamp, 1.0f) == 0);
}

TEST_CASE("repeat reads the fraction: integers at texel 0, negative values from the end") {
    CHECK(column(kRepeat, -0.25f) == 3);   // 0.75
    CHECK(column(kRepeat, -1.0f) == 0);
    CHECK(column(kRepeat, 1.0f) == 0);
    CHECK(column(kRepeat, 3.0f) == 0);
    CHECK(column(kRepeat, 2.6f) == 2);     // 0.6
    CHECK(column(kRepeat, -2.6f) == 1);    // 0.4
    CHECK(column(kRepeat, 0.999f) == 3);
    CHECK(column(kRepeat, -1e-10f) == 3);  // -1e-10 + 1 rounds to 1: the last texel, beside 0
    CHECK(row(kRepeat, -0.25f) == 1);      // 0.75: (1 - 0.75) * 4
    CHECK(row(kRepeat, 1.0f) == 3);        // 0: the bottom row
    CHECK(row(kRepeat, 2.1f) == 3);        // 0.1
}

TEST_CASE("mirrored repeat runs forward on even periods and backward on odd ones") {
    CHECK(column(kMirror, 0.6f) == 2);
    CHECK(column(kMirror, 1.0f) == 3);     // odd integers read as 1
    CHECK(column(kMirror, 1.25f) == 3);    // 0.75
    CHECK(column(kMirror, 1.6f) == 1);     // 0.4
    CHECK(column(kMirror, 2.0f) == 0);     // even integers read as 0
    CHECK(column(kMirror, 2.6f) == 2);     // 0.6
    CHECK(column(kMirror, 3.0f) == 3);
    CHECK(column(kMirror, -0.25f) == 1);   // 0.25, on texel 1's left edge
    CHECK(column(kMirror, -0.1f) == 0);    // 0.1
    CHECK(column(kMirror, -1.0f) == 3);
    CHECK(column(kMirror, -1.6f) == 1);    // t = -1.6 + 2 = 0.4
    CHECK(column(kMirror, -2.6f) == 2);    // t = 1.4, 2 - 1.4 = 0.6
    CHECK(column(kMirror, -1e-10f) == 0);  // t rounds to 2, which mirrors to 0
    CHECK(row(kMirror, 1.0f) == 0);        // 1: the top row
    CHECK(row(kMirror, 1.6f) == 2);        // 0.4: (1 - 0.4) * 4
}

TEST_CASE("NaN and infinite coordinates read texel 0 in every mode") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (TextureWrap wrap : {kClamp, kRepeat, kMirror}) {
        CHECK(column(wrap, nan) == 0);
        if (wrap != kClamp) CHECK(column(wrap, inf) == 0);
        if (wrap != kClamp) CHECK(column(wrap, -inf) == 0);
    }
    CHECK(column(kClamp, inf) == 3);
}

TEST_CASE("each axis wraps by its own mode in a 4 x 2 texture") {
    // u repeated: 2.6 -> 0.6, column 2; v mirrored: 1.25 -> 0.75, row floor(0.25 * 2) = 0.
    CHECK(nearestTexelIndex(4, 2, {kRepeat, kMirror}, {2.6f, 1.25f}) == 2);
    // v mirrored: 2.25 -> 0.25, row floor(0.75 * 2) = 1; u clamped: -3 -> column 0.
    CHECK(nearestTexelIndex(4, 2, {kClamp, kMirror}, {-3.0f, 2.25f}) == 4);
}
