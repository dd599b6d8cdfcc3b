// The receiver octree and the shaft hierarchy (differential/receiver_octree.h,
// shaft_hierarchy.h; Gibson et al. 2003 section 6): the octree's ranges partition the
// patches; every source-receiver pair's shaft appears once as a leaf; the traversal finds
// every source and receiver whose pair shaft an object's box touches (brute force over all
// pairs); insignificant shafts are not kept; a kept shaft whose children all fail the rule
// lists every patch below it.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>

#include "differential/shaft_hierarchy.h"
#include "tests/differential/random_boxes.h"

using namespace shadowlab;

using test::contains;
using test::randomBoxes;

TEST_CASE("receiver octree: the children's ranges partition their parent's, leaves hold at most 8 patches") {
    std::mt19937_64 rng(4);
    for (int count : {1, 8, 9, 100, 2000}) {
        const std::vector<Aabb> patches = randomBoxes(rng, count, glm::dvec3(-10.0, 0.0, -10.0), glm::dvec3(10.0, 0.0, 10.0), 0.4);
        const ReceiverOctree tree = buildReceiverOctree(patches);
        CHECK(std::set<uint32_t>(tree.patches.begin(), tree.patches.end()).size() == size_t(count));
        for (const ReceiverNode& n : tree.nodes) {
            for (uint32_t k = n.firstPatch; k < n.firstPatch + n.patchCount; ++k) REQUIRE(contains(n.bounds, patches[tree.patches[k]]));
            if (n.leaf()) {
                REQUIRE(n.patchCount <= 8);
                continue;
            }
            REQUIRE(n.childCount >= 2);
            REQUIRE(n.childCount <= 8);
            uint32_t next = n.firstPatch;
            for (uint32_t c = 0; c < n.childCount; ++c) {
                const ReceiverNode& child = tree.nodes[n.firstChild + c];
                REQUIRE(child.firstPatch == next);
                next += child.patchCount;
            }
            REQUIRE(next == n.firstPatch + n.patchCount);
        }
    }
    // Patches that share one centre cannot be split: one leaf, whatever its size.
    const std::vector<Aabb> stacked(20, Aabb{{0, 0, 0}, {1, 1, 1}});
    CHECK(buildReceiverOctree(stacked).nodes.size() == 1);
    CHECK_THROWS_AS(buildReceiverOctree(stacked, 0), std::invalid_argument);
}

TEST_CASE("shaft hierarchy: one leaf per source patch and receiver leaf, and the traversal misses no pair's shaft") {
    std::mt19937_64 rng(6);
    // Sources on a ceiling and a wall, receivers on the floor, as in the paper's room.
    std::vector<Aabb> sourceBoxes = randomBoxes(rng, 30, glm::dvec3(-5, 4, -5), glm::dvec3(5, 4, 5), 0.5);
    for (const Aabb& b : randomBoxes(rng, 10, glm::dvec3(-5, 1, -5), glm::dvec3(-5, 3, 5), 0.5)) sourceBoxes.push_back(b);
    const std::vector<Aabb> receiverBoxes = randomBoxes(rng, 200, glm::dvec3(-5, 0, -5), glm::dvec3(5, 0, 5), 0.3);
    const SourceTree sources = buildSourceTree(sourceBoxes, std::vector<double>(sourceBoxes.size(), 1.0));
    const ReceiverOctree receivers = buildReceiverOctree(receiverBoxes);
    const ShaftHierarchy shafts = buildShaftHierarchy(sources, receivers, [](int32_t, int32_t) { return true; });
    const size_t receiverLeaves = size_t(std::count_if(receivers.nodes.begin(), receivers.nodes.end(),
                                                       [](const ReceiverNode& n) { return n.leaf(); }));
    CHECK(shafts.leafCount() == sourceBoxes.size() * receiverLeaves);

    int found = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const Aabb object = randomBoxes(rng, 1, glm::dvec3(-5, 0, -5), glm::dvec3(5, 3, 5), 0.8)[0];
        const ShaftHits hits = traverseShafts(shafts, sources, receivers, object);
        const std::set<uint32_t> foundSources(hits.sourcePatches.begin(), hits.sourcePatches.end());
        const std::set<uint32_t> foundReceivers(hits.receiverPatches.begin(), hits.receiverPatches.end());
        REQUIRE(foundSources.size() == hits.sourcePatches.size());   // each once
        for (uint32_t j = 0; j < sourceBoxes.size(); ++j) {
            for (uint32_t r = 0; r < receiverBoxes.size(); ++r) {
                if (!shaftMayTouch(makeShaft(sourceBoxes[j], receiverBoxes[r]), object)) continue;
                ++found;
                REQUIRE(foundSources.contains(j));
                REQUIRE(foundReceivers.contains(r));
            }
        }
    }
    CHECK(found > 1000);   // the objects did stand in the way
}

// 8 unit-power source patches 4 m above 50 receiver patches, placed at random.
struct SourcesOverReceivers {
    explicit SourcesOverReceivers(std::mt19937_64& rng)
        : sourceBoxes(randomBoxes(rng, 8, glm::dvec3(-2, 4, -2), glm::dvec3(2, 4, 2), 0.3)),
          receiverBoxes(randomBoxes(rng, 50, glm::dvec3(-3, 0, -3), glm::dvec3(3, 0, 3), 0.3)),
          sources(buildSourceTree(sourceBoxes, std::vector<double>(sourceBoxes.size(), 1.0))),
          receivers(buildReceiverOctree(receiverBoxes)) {}
    std::vector<Aabb> sourceBoxes, receiverBoxes;
    SourceTree sources;
    ReceiverOctree receivers;
};

TEST_CASE("shaft hierarchy: insignificant shafts are not kept, and their sources are not found") {
    std::mt19937_64 rng(8);
    const SourcesOverReceivers scene(rng);
    const SourceTree& sources = scene.sources;
    const ReceiverOctree& receivers = scene.receivers;
    const std::vector<Aabb>& receiverBoxes = scene.receiverBoxes;
    const int32_t dark = sources.leafOfPatch[3];   // a source whose transfers are all below 2%
    const ShaftHierarchy shafts = buildShaftHierarchy(sources, receivers, [&](int32_t s, int32_t) { return s != dark; });
    const ShaftHierarchy all = buildShaftHierarchy(sources, receivers, [](int32_t, int32_t) { return true; });
    CHECK(shafts.nodes.size() < all.nodes.size());
    CHECK(std::none_of(shafts.nodes.begin(), shafts.nodes.end(), [&](const ShaftNode& n) { return n.source == dark; }));
    const Aabb everywhere{{-10, -1, -10}, {10, 10, 10}};
    const ShaftHits hits = traverseShafts(shafts, sources, receivers, everywhere);
    CHECK(hits.sourcePatches.size() == 7);
    CHECK(std::find(hits.sourcePatches.begin(), hits.sourcePatches.end(), 3u) == hits.sourcePatches.end());
    CHECK(hits.receiverPatches.size() == receiverBoxes.size());
    // Nothing significant at all: no shaft, nothing found.
    const ShaftHierarchy none = buildShaftHierarchy(sources, receivers, [](int32_t, int32_t) { return false; });
    CHECK(none.nodes.empty());
    CHECK(traverseShafts(none, sources, receivers, everywhere).sourcePatches.empty());
}

TEST_CASE("shaft hierarchy: a kept shaft whose children all fail the rule is a leaf listing every patch below it") {
    std::mt19937_64 rng(9);
    // 8 sources, so every source node splits into two of equal size down to single patches.
    const SourcesOverReceivers scene(rng);
    const SourceTree& sources = scene.sources;
    const ReceiverOctree& receivers = scene.receivers;
    const std::vector<Aabb>& receiverBoxes = scene.receiverBoxes;
    // A light cut so finely that no patch passes on its own, though every pair of them does.
    const auto inner = [&](int32_t s, int32_t) { return !sources.nodes[s].leaf(); };
    const ShaftHierarchy shafts = buildShaftHierarchy(sources, receivers, inner);
    const ShaftHierarchy all = buildShaftHierarchy(sources, receivers, [](int32_t, int32_t) { return true; });
    REQUIRE(!shafts.nodes.empty());
    CHECK(std::none_of(shafts.nodes.begin(), shafts.nodes.end(),
                       [&](const ShaftNode& n) { return sources.nodes[n.source].leaf(); }));
    CHECK(shafts.leafCount() > 0);
    const Aabb everywhere{{-10, -1, -10}, {10, 10, 10}};
    const ShaftHits hits = traverseShafts(shafts, sources, receivers, everywhere);
    CHECK(hits.sourcePatches.size() == scene.sourceBoxes.size());
    CHECK(hits.receiverPatches.size() == receiverBoxes.size());
    // Nothing is lost against the hierarchy that keeps every shaft: each box lists at least
    // the sources and receivers that one lists (a leaf's shaft holds its pairs' shafts).
    for (int trial = 0; trial < 100; ++trial) {
        const Aabb object = randomBoxes(rng, 1, glm::dvec3(-3, 0, -3), glm::dvec3(3, 4, 3), 0.5)[0];
        const ShaftHits coarse = traverseShafts(shafts, sources, receivers, object);
        const ShaftHits fine = traverseShafts(all, sources, receivers, object);
        const std::set<uint32_t> coarseSources(coarse.sourcePatches.begin(), coarse.sourcePatches.end());
        const std::set<uint32_t> coarseReceivers(coarse.receiverPatches.begin(), coarse.receiverPatches.end());
        REQUIRE(coarseSources.size() == coarse.sourcePatches.size());   // each once
        for (const uint32_t s : fine.sourcePatches) REQUIRE(coarseSources.contains(s));
        for (const uint32_t r : fine.receiverPatches) REQUIRE(coarseReceivers.contains(r));
    }
}
