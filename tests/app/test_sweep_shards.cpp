// `sweep --shard i/n`: shard i runs every n-th setting, with the unsharded run's error
// figures; bad shards are refused before anything is rendered.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "app/sweep.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

namespace {

// 7 settings (none's defaults, then shadow-map's 3 x 2) at 2 thread counts, on a 96 x 60
// view of the sun case, whose shadow maps miss some pixels: error figures to compare.
SweepOptions tinyOptions(SweepShard shard) {
    SweepOptions options;
    options.scene = builtinSceneDir() + "/hard/sun.json";
    options.overrides.width = 96;
    options.overrides.height = 60;
    options.techniques = {&findTechnique("none"), &findTechnique("shadow-map")};
    options.axes = {{"resolution", {"64", "256", "1024"}}, {"slope-factor", {"0.5", "1.5"}}};
    options.threads = {1, 2};
    options.warmupRuns = 0;
    options.runs = 1;
    options.shard = shard;
    return options;
}

const SweepResults& unsharded() {
    static const SweepResults results = runSweep(tinyOptions({}));
    return results;
}

const std::vector<SweepResults>& threeShards() {
    static const std::vector<SweepResults> shards = {runSweep(tinyOptions({1, 3})), runSweep(tinyOptions({2, 3})),
                                                     runSweep(tinyOptions({3, 3}))};
    return shards;
}

}  // namespace

TEST_CASE("sweep --shard: shard i runs the settings k with k mod n = i - 1, at every thread count") {
    CHECK(unsharded().rows.size() == 7 * 2);
    CHECK(unsharded().grid.settings == 7);
    size_t rows = 0;
    for (const SweepResults& shard : threeShards()) {
        CAPTURE(shard.shard.name());
        CHECK(shard.grid.settings == 7);
        CHECK(shard.techniques == unsharded().techniques);
        for (const SweepRow& row : shard.rows) CHECK(int(row.setting % 3) == shard.shard.index - 1);
        rows += shard.rows.size();
    }
    CHECK(threeShards()[0].rows.size() == 3 * 2);   // settings 0, 3, 6
    CHECK(threeShards()[1].rows.size() == 2 * 2);   // 1, 4
    CHECK(rows == unsharded().rows.size());
    // Each shard renders the references itself: the same bytes as the unsharded run's.
    CHECK(threeShards()[2].grid.referenceFingerprints == unsharded().grid.referenceFingerprints);
    CHECK(unsharded().grid.referenceFingerprints.at("reference").size() == 16);
}

TEST_CASE("sweep --shard: each shard's error figures are the unsharded run's, setting by setting") {
    for (const SweepResults& shard : threeShards()) {
        for (const SweepRow& row : shard.rows) {
            const SweepRow& whole = unsharded().rows[2 * row.setting + (row.threads == 2)];
            CAPTURE(row.setting);
            CHECK(whole.settings == row.settings);
            CHECK(whole.threads == row.threads);
            CHECK(whole.errors.rms == row.errors.rms);
            CHECK(whole.errors.falseLight == row.errors.falseLight);
            CHECK(whole.errors.falseShadow == row.errors.falseShadow);
        }
    }
    // The figures compared differ from setting to setting: the coarse maps err here.
    CHECK(unsharded().rows[2].errors.misclassified() > 0);
    CHECK(unsharded().rows[2].errors.rms != unsharded().rows[4].errors.rms);
}

TEST_CASE("sweep --shard: I/N with 1 <= I <= N, digits only") {
    CHECK(parseSweepShard("1/3").index == 1);
    CHECK(parseSweepShard("3/3").count == 3);
    CHECK(parseSweepShard("1/1").name() == "1/1");
    for (const char* bad : {"0/3", "4/3", "1/0", "0/0", "garbage", "", "1/", "/3", "1/3x", "-1/3", "+1/3", " 1/3", "1//3",
                            "1.0/3", "99999999999/3"}) {
        CAPTURE(bad);
        CHECK_THROWS_WITH_AS(parseSweepShard(bad), doctest::Contains("expected I/N with 1 <= I <= N (I counts from 1"),
                             std::invalid_argument);
    }
}

TEST_CASE("sweep --shard: more shards than settings is an error, before rendering") {
    SweepOptions options = tinyOptions({8, 8});
    options.scene = "no-such-scene";   // not reached
    CHECK_THROWS_WITH_AS(runSweep(options), doctest::Contains("the sweep has only 7 settings, so this shard has none"),
                         std::invalid_argument);
}

TEST_CASE("sweep file stem: a shard's names the shard, the whole sweep's does not") {
    SweepResults results;
    results.scene = "sphere-box";
    results.techniques = {"none", "reference"};
    results.shard = {2, 3};
    CHECK(sweepFileStem(results) == "sphere-box-none+reference-shard-2-of-3");
    results.shard = {1, 1};
    CHECK(sweepFileStem(results) == "sphere-box-none+reference");
}
