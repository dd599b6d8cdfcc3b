// Shaft culling (differential/shaft.h): both end boxes inside every plane, no
// segment between them ever missed, and the diagonal shaft tighter than its bounding box.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "differential/shaft.h"
#include "tests/differential/random_boxes.h"

using namespace shadowlab;
using test::segmentHitsBox;

namespace {

Aabb randomBox(std::mt19937_64& rng, double extent, double size) {
    std::uniform_real_distribution<double> centre(-extent, extent), half(0.0, size);
    const glm::dvec3 c = test::randomVector(centre, rng);
    const glm::dvec3 h = test::randomVector(half, rng);
    return {c - h, c + h};
}

glm::dvec3 pointIn(std::mt19937_64& rng, const Aabb& box) {
    std::uniform_real_distribution<double> t(0.0, 1.0);
    return box.min + (box.max - box.min) * test::randomVector(t, rng);
}

bool inside(const Shaft& s, const glm::dvec3& p) {
    return std::ranges::all_of(s.planes, [&](const ShaftPlane& plane) { return glm::dot(plane.n, p) + plane.d <= 1e-9; });
}

}  // namespace

TEST_CASE("shaft: both end boxes lie inside every plane") {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 2000; ++trial) {
        const Aabb a = randomBox(rng, 10.0, 3.0), b = randomBox(rng, 10.0, 3.0);
        const Shaft s = makeShaft(a, b);
        CHECK(s.planes.size() <= 12);
        for (const Aabb& box : {a, b}) {
            for (int corner = 0; corner < 8; ++corner) {
                const glm::dvec3 c(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y, corner & 4 ? box.max.z : box.min.z);
                REQUIRE(inside(s, c));
            }
        }
    }
}

TEST_CASE("shaft: a box that a segment between the ends passes through is never culled") {
    std::mt19937_64 rng(11);
    int hits = 0, culled = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Aabb a = randomBox(rng, 10.0, 2.0), b = randomBox(rng, 10.0, 2.0), object = randomBox(rng, 6.0, 1.5);
        const Shaft s = makeShaft(a, b);
        bool anySegment = false;
        for (int k = 0; k < 64 && !anySegment; ++k) anySegment = segmentHitsBox(pointIn(rng, a), pointIn(rng, b), object);
        hits += anySegment;
        if (anySegment) REQUIRE(shaftMayTouch(s, object));
        culled += !shaftMayTouch(s, object);
    }
    CHECK(hits > 500);       // the campaign exercised the property (924 hits)
    CHECK(culled > 15000);   // and the test culls most boxes away from the shaft (93%)
}

// A shaft hierarchy tests a parent shaft before its children: the shaft of boxes inside
// the ends must lie inside the ends' shaft (true of convex hulls, which these shafts are:
// a hull facet of two boxes holds parallel edges of both, or is a face of their bounds).
TEST_CASE("shaft: the shaft of boxes inside the ends lies inside the ends' shaft") {
    std::mt19937_64 rng(13);
    const auto inner = [&](const Aabb& box) {
        const glm::dvec3 p = pointIn(rng, box), q = pointIn(rng, box);
        return Aabb{glm::min(p, q), glm::max(p, q)};
    };
    int tested = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const Aabb a = randomBox(rng, 10.0, 3.0), b = randomBox(rng, 10.0, 3.0);
        const Shaft outer = makeShaft(a, b), child = makeShaft(inner(a), inner(b));
        for (int k = 0; k < 200; ++k) {
            const glm::dvec3 p = pointIn(rng, child.bounds);
            if (!inside(child, p)) continue;
            ++tested;
            REQUIRE(inside(outer, p));
            REQUIRE(glm::all(glm::lessThanEqual(outer.bounds.min, p)));
            REQUIRE(glm::all(glm::lessThanEqual(p, outer.bounds.max)));
        }
    }
    CHECK(tested > 5000);   // 8925 points inside a child shaft
}

TEST_CASE("shaft: a diagonal shaft culls a box inside its bounds but off the diagonal") {
    const Aabb a{{0, 0, 0}, {1, 1, 1}}, b{{9, 9, 0}, {10, 10, 1}};
    const Shaft s = makeShaft(a, b);
    CHECK(s.planes.size() == 2);   // the two sides of the diagonal in x and y
    CHECK_FALSE(shaftMayTouch(s, Aabb{{8, 1, 0}, {9, 2, 1}}));   // in the bounds, far off the diagonal
    CHECK(shaftMayTouch(s, Aabb{{4.5, 4.5, 0.2}, {5.5, 5.5, 0.4}}));   // on it
    CHECK_FALSE(shaftMayTouch(s, Aabb{{4.5, 4.5, 2.0}, {5.5, 5.5, 3.0}}));   // above both ends
    // Two boxes, one inside the other's reach on every axis: the shaft is their bounds.
    CHECK(makeShaft(Aabb{{0, 0, 0}, {4, 4, 4}}, Aabb{{1, 1, 1}, {2, 2, 2}}).planes.empty());
}
