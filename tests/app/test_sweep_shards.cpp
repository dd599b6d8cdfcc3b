// `sweep --shard i/n` and `merge-sweep`: a sweep run as shards and merged gives the
// unsharded run's CSV, JSON and SVG, byte for byte once the measured times are set alike;
// the JSON reads back exactly; shards that do not make up one sweep are refused by name.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/measure/sweep.h"
#include "app/measure/sweep_json.h"
#include "app/measure/sweep_merge.h"
#include "app/plots/sweep_plot.h"
#include "frame/registry.h"
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

// Each shard's JSON read back, as merge-sweep reads the files.
std::vector<SweepShardFile> shardFiles(const std::vector<SweepResults>& shards) {
    std::vector<SweepShardFile> files;
    for (const SweepResults& shard : shards) {
        const std::string name = sweepFileStem(shard) + ".json";
        files.push_back({name, parseSweepJson(formatSweepJson(shard), name)});
    }
    return files;
}

// The measured times replaced by the same made-up ones in any run: distinct per row, so
// that the plot is laid out as with real times.
SweepResults withTimesSetAlike(SweepResults results) {
    for (SweepRow& row : results.rows) {
        row.medianMs = 1.0 + double(row.setting) + 0.25 * row.threads;
        row.minMs = row.medianMs / 2;
        for (TechniqueStat& stat : row.stats)
            if (stat.name.ends_with("_ms")) stat.value = 0.0;
    }
    return results;
}

// A hand-made shard of a 3-setting grid at one thread count: one row per setting it holds.
SweepShardFile handShard(int index, int count, const std::string& path) {
    SweepResults results;
    results.scene = "sun";
    results.techniques = {"shadow-map"};
    results.grid.axes = {{"resolution", {"64", "256", "1024"}}};
    results.grid.referenceFingerprints = {{"reference", "0123456789abcdef"}};
    results.grid.threads = {1};
    results.grid.runs = 5;
    results.grid.settings = 3;
    results.shard = {index, count};
    for (uint64_t setting = 0; setting < 3; ++setting) {
        if (!results.shard.holds(setting)) continue;
        SweepRow row;
        row.setting = setting;
        row.technique = "shadow-map";
        row.settings = {{"resolution", results.grid.axes[0].values[setting]}};
        results.rows.push_back(row);
    }
    return {path, results};
}

std::vector<SweepShardFile> handShards() {
    return {handShard(1, 3, "a.json"), handShard(2, 3, "b.json"), handShard(3, 3, "c.json")};
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

TEST_CASE("merge-sweep: three shards merged give the unsharded CSV, JSON and SVG but for the times") {
    const SweepResults merged = mergeSweepShards(shardFiles(threeShards()));
    CHECK(merged.shard.count == 1);
    CHECK(sweepFileStem(merged) == sweepFileStem(unsharded()));
    const SweepResults expected = withTimesSetAlike(unsharded()), got = withTimesSetAlike(merged);
    CHECK(formatSweepCsv(got) == formatSweepCsv(expected));
    CHECK(formatSweepJson(got) == formatSweepJson(expected));
    CHECK(formatSweepSvg(got, PlotErrorAxis::Misclassified) == formatSweepSvg(expected, PlotErrorAxis::Misclassified));
    // The times themselves are the shards' own, exactly.
    for (const SweepResults& shard : threeShards())
        for (const SweepRow& row : shard.rows) CHECK(merged.rows[2 * row.setting + (row.threads == 2)].medianMs == row.medianMs);
}

TEST_CASE("merge-sweep: the shards may be given in any order") {
    std::vector<SweepShardFile> files = shardFiles(threeShards());
    std::swap(files[0], files[2]);
    CHECK(formatSweepJson(mergeSweepShards(files)) == formatSweepJson(mergeSweepShards(shardFiles(threeShards()))));
}

TEST_CASE("sweep JSON: read back, it writes the same bytes (stats in order, NaN as null)") {
    SweepResults results = threeShards()[1];
    results.rows[0].errors.rms = std::numeric_limits<double>::quiet_NaN();
    results.rows[0].stats = {{"zeta_count", 3.0}, {"alpha_ms", 0.1 + 0.2}};
    const std::string json = formatSweepJson(results);
    const SweepResults read = parseSweepJson(json, "x.json");
    CHECK(std::isnan(read.rows[0].errors.rms));
    CHECK(read.rows[0].stats[0].name == "zeta_count");
    CHECK(read.shard.name() == "2/3");
    CHECK(read.grid.overrides.width == 96);
    CHECK(formatSweepJson(read) == json);
    CHECK(sweepDifference(read, results).empty());
}

TEST_CASE("sweep JSON: written before umbra lit 0.02, it reads as not recorded, not as zero") {
    nlohmann::json old = nlohmann::json::parse(formatSweepJson(threeShards()[0]));
    for (nlohmann::json& row : old.at("rows"))
        for (const char* key : {"full_umbra_pixels", "full_umbra_lit", "full_umbra_lit_percent"}) row.at("errors").erase(key);
    const SweepResults read = parseSweepJson(old.dump(), "old.json");
    CHECK_FALSE(read.rows[0].errors.fullUmbraRecorded);
    CHECK_FALSE(read.rows[0].errors.fullUmbraLitPercent());
    // Written again, the figure stays absent; shown, it says so; its CSV cell is empty.
    CHECK(formatSweepJson(read).find("full_umbra") == std::string::npos);
    CHECK(formatSweepText(read).find("not recorded") != std::string::npos);
    std::istringstream csv(formatSweepCsv(read));
    std::string row;
    std::getline(csv, row);
    std::getline(csv, row);
    size_t field = 0;   // full_umbra_lit_percent is the 14th field (test_sweep.cpp)
    for (int k = 0; k < 13; ++k) field = row.find(',', field) + 1;
    CHECK(row.at(field) == ',');
    // Merged with a shard that has it, each row keeps what its own file recorded.
    std::vector<SweepShardFile> files = shardFiles(threeShards());
    files[0].results = read;
    const SweepResults merged = mergeSweepShards(files);
    int recorded = 0;
    for (const SweepRow& row : merged.rows) recorded += row.errors.fullUmbraRecorded;
    CHECK(recorded == int(merged.rows.size() - read.rows.size()));
}

TEST_CASE("merge-sweep: a missing shard, a duplicate, another sweep or split, and rows cut short are refused") {
    std::vector<SweepShardFile> files = handShards();
    CHECK(mergeSweepShards(files).rows.size() == 3);
    CHECK_THROWS_WITH_AS(mergeSweepShards({files[0], files[2]}), "missing shard(s) 2/3 of the sweep of a.json", std::runtime_error);
    CHECK_THROWS_WITH_AS(mergeSweepShards({files[0], files[1], handShard(2, 3, "b2.json"), files[2]}),
                         "shard 2/3 is given twice: b.json and b2.json", std::runtime_error);
    CHECK_THROWS_WITH_AS(mergeSweepShards({files[0], handShard(1, 2, "d.json")}),
                         doctest::Contains("d.json is shard 1/2 but a.json is shard 1/3"), std::runtime_error);
    SweepShardFile other = handShard(2, 3, "other.json");
    other.results.grid.runs = 3;
    CHECK_THROWS_WITH_AS(mergeSweepShards({files[0], other, files[2]}),
                         "other.json: not a shard of the same sweep as a.json (runs: 3 against 5)", std::runtime_error);
    other = handShard(2, 3, "other.json");
    other.results.grid.referenceFingerprints["reference"] = "fedcba9876543210";
    CHECK_THROWS_WITH_AS(mergeSweepShards({files[0], other, files[2]}), doctest::Contains("(reference_fingerprints: "),
                         std::runtime_error);
    files[1].results.rows.clear();
    CHECK_THROWS_WITH_AS(mergeSweepShards(files), "the shards lack setting 1 at 1 threads (a file cut short or edited?)",
                         std::runtime_error);
    files[1] = handShard(2, 3, "b.json");
    files[1].results.rows.push_back(files[1].results.rows[0]);
    CHECK_THROWS_WITH_AS(mergeSweepShards(files), "the shards hold setting 1 at 1 threads twice (a file edited?)", std::runtime_error);
    files[1].results.rows.back().setting = 5;
    CHECK_THROWS_WITH_AS(mergeSweepShards(files), "the shards hold setting 5 at 1 threads, which the grid lacks", std::runtime_error);
    CHECK_THROWS_AS(mergeSweepShards({}), std::invalid_argument);
}

TEST_CASE("sweep JSON: unreadable text is refused naming the file") {
    CHECK_THROWS_WITH_AS(parseSweepJson("{\"scene\": ", "cut.json"), doctest::Contains("cut.json: invalid JSON: "), std::runtime_error);
    CHECK_THROWS_WITH_AS(parseSweepJson("[1, 2]", "array.json"), doctest::Contains("array.json: not the JSON of a sweep: "),
                         std::runtime_error);
    CHECK_THROWS_WITH_AS(parseSweepJson(std::string(100, '[') + std::string(100, ']'), "deep.json"),
                         "deep.json: nested deeper than 64 levels", std::runtime_error);
    std::string json = formatSweepJson(handShard(2, 3, "b.json").results);
    CHECK_THROWS_WITH_AS(parseSweepJson(json.replace(json.find("\"setting\""), 9, "\"set\""), "row.json"),
                         doctest::Contains("row.json: not the JSON of a sweep: rows[0]: [json.exception.out_of_range.403] key 'setting' not found"),
                         std::runtime_error);
    SweepResults zero = handShard(1, 3, "z.json").results;
    zero.shard = {0, 3};
    CHECK_THROWS_WITH_AS(parseSweepJson(formatSweepJson(zero), "z.json"), doctest::Contains("z.json: not the JSON of a sweep: shard 0/3: not a shard"),
                         std::runtime_error);
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
    // Shard 1 of 8 and of 10^9 hold setting 0, but merge-sweep would wait for N files.
    for (const SweepShard shard : {SweepShard{8, 8}, SweepShard{1, 8}, SweepShard{1, 1000000000}}) {
        SweepOptions options = tinyOptions(shard);
        options.scene = "no-such-scene";   // not reached
        CHECK_THROWS_WITH_AS(runSweep(options), doctest::Contains("the sweep has only 7 settings, so some shards would have none"),
                             std::invalid_argument);
    }
}

TEST_CASE("sweep JSON: every count is checked before it bounds a loop") {
    // Each of these kept merge-sweep busy for ever, or until memory ran out.
    const auto errorOf = [](SweepResults results) {
        try {
            parseSweepJson(formatSweepJson(results), "s.json");
        } catch (const std::runtime_error& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    const SweepResults shard = handShard(1, 3, "a.json").results;
    CHECK(errorOf(shard).empty());
    SweepResults bad = shard;
    bad.shard = {1, 1000000000};
    CHECK(errorOf(bad) == "s.json: not the JSON of a sweep: grid.settings 3 must be at least 1 and the shards' count 1000000000");
    bad = shard;
    bad.grid.settings = uint64_t(1) << 63;
    CHECK(errorOf(bad).find("shard 1/3 of 9223372036854775808 settings at 1 thread counts has 3074457345618258603 x 1 rows, "
                            "the file 1") != std::string::npos);
    bad = shard;
    bad.grid.threads.clear();
    CHECK(errorOf(bad) == "s.json: not the JSON of a sweep: grid.threads lists no thread count");
    for (const std::vector<int>& threads : {std::vector<int>{0}, std::vector<int>{2000}, std::vector<int>{1, 1}}) {
        bad.grid.threads = threads;
        CHECK(errorOf(bad).find("grid.threads: each must be 1..1024 and given once") != std::string::npos);
    }
    bad = shard;
    bad.grid.runs = 0;
    CHECK(errorOf(bad).find("grid.runs must be 1..10000 and grid.warmup 0..1000") != std::string::npos);
    bad = shard;
    bad.rows.push_back(bad.rows.back());
    CHECK(errorOf(bad).find("has 1 x 1 rows, the file 2") != std::string::npos);
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
