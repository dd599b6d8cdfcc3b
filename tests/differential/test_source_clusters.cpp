// The source hierarchy and the representative source set (differential/
// source_tree.h, source_clusters.h; Gibson et al. 2003 sections 6 and 8): a binary tree with
// one patch per leaf and summed transfers, and clusters that keep every occluded patch's
// transfer once, at most n of them, single patches when n allows.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>

#include "differential/source_clusters.h"
#include "tests/differential/random_boxes.h"

using namespace shadowlab;
using test::contains;

namespace {

struct Sources {
    std::vector<Aabb> bounds;
    std::vector<double> transfer;
};

Sources randomSources(std::mt19937_64& rng, int count) {
    Sources s{test::randomBoxes(rng, count, glm::dvec3(-5.0), glm::dvec3(5.0), 0.3), {}};
    std::uniform_real_distribution<double> power(0.0, 1.0);
    for (int p = 0; p < count; ++p) s.transfer.push_back(power(rng) * power(rng));
    return s;
}

}  // namespace

TEST_CASE("source tree: one patch per leaf, 2P - 1 nodes, boxes and transfers summed up the tree") {
    std::mt19937_64 rng(1);
    for (int count : {1, 2, 3, 7, 100, 1000}) {
        const Sources s = randomSources(rng, count);
        const SourceTree tree = buildSourceTree(s.bounds, s.transfer);
        REQUIRE(tree.nodes.size() == size_t(2 * count - 1));
        CHECK(tree.nodes[0].parent == -1);
        std::set<uint32_t> leaves;
        for (size_t i = 0; i < tree.nodes.size(); ++i) {
            const SourceNode& n = tree.nodes[i];
            if (n.leaf()) {
                leaves.insert(n.patch);
                REQUIRE(tree.leafOfPatch[n.patch] == int32_t(i));
                REQUIRE(n.transfer == s.transfer[n.patch]);
                continue;
            }
            const SourceNode &l = tree.nodes[n.children[0]], &r = tree.nodes[n.children[1]];
            REQUIRE(l.parent == int32_t(i));
            REQUIRE(r.parent == int32_t(i));
            REQUIRE(n.transfer == l.transfer + r.transfer);
            REQUIRE(contains(n.bounds, l.bounds));
            REQUIRE(contains(n.bounds, r.bounds));
        }
        CHECK(leaves.size() == size_t(count));
        double total = 0.0;
        for (double t : s.transfer) total += t;
        CHECK(tree.nodes[0].transfer == doctest::Approx(total).epsilon(1e-12));
    }
    CHECK(buildSourceTree({}, {}).nodes.empty());
}

TEST_CASE("representative sources: at most n clusters keep every occluded patch's transfer exactly once") {
    std::mt19937_64 rng(2);
    const Sources s = randomSources(rng, 500);
    const SourceTree tree = buildSourceTree(s.bounds, s.transfer);
    std::uniform_int_distribution<uint32_t> patch(0, 499);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<uint32_t> occluded;
        const int k = 1 + int(patch(rng) % 120);
        for (int j = 0; j < k; ++j) occluded.push_back(patch(rng));   // repeats allowed, as the shafts find them
        const std::set<uint32_t> distinct(occluded.begin(), occluded.end());
        double total = 0.0;
        for (uint32_t p : distinct) total += s.transfer[p];
        for (int n : {1, 2, 5, 10, 20, 50, 1000}) {
            const std::vector<SourceCluster> clusters = representativeSources(tree, occluded, n);
            REQUIRE(clusters.size() <= size_t(n));
            REQUIRE(!clusters.empty());
            std::multiset<uint32_t> covered;
            double sum = 0.0;
            for (size_t c = 0; c < clusters.size(); ++c) {
                covered.insert(clusters[c].patches.begin(), clusters[c].patches.end());
                double own = 0.0;
                for (uint32_t p : clusters[c].patches) own += s.transfer[p];
                REQUIRE(clusters[c].transfer == doctest::Approx(own).epsilon(1e-12));
                sum += clusters[c].transfer;
                if (c > 0) REQUIRE(clusters[c - 1].transfer >= clusters[c].transfer);
                // The tightest node: a cluster of one patch is its leaf.
                if (clusters[c].patches.size() == 1) REQUIRE(tree.nodes[clusters[c].node].leaf());
            }
            REQUIRE(covered == std::multiset<uint32_t>(distinct.begin(), distinct.end()));
            REQUIRE(sum == doctest::Approx(total).epsilon(1e-12));
            // With a pass to spare for every patch, every cluster is one patch.
            if (size_t(n) >= distinct.size()) REQUIRE(clusters.size() == distinct.size());
            else REQUIRE(clusters.size() == size_t(n));
        }
    }
}

TEST_CASE("representative sources: nothing occluded gives no cluster, bad input is refused") {
    const Sources s{{Aabb{{0, 0, 0}, {1, 1, 1}}, Aabb{{2, 0, 0}, {3, 1, 1}}}, {1.0, 2.0}};
    const SourceTree tree = buildSourceTree(s.bounds, s.transfer);
    CHECK(representativeSources(tree, {}, 4).empty());
    CHECK_THROWS_AS(representativeSources(tree, std::vector<uint32_t>{0}, 0), std::invalid_argument);
    CHECK_THROWS_AS(representativeSources(tree, std::vector<uint32_t>{2}, 1), std::invalid_argument);
    // One pass for two patches: the root, their sum.
    const std::vector<SourceCluster> one = representativeSources(tree, std::vector<uint32_t>{0, 1}, 1);
    REQUIRE(one.size() == 1);
    CHECK(one[0].node == 0);
    CHECK(one[0].transfer == 3.0);
}
