// `sweep --images`: each setting's pictures (image, error map, V, debug buffers) and each
// reference's are written once beside the sweep's files, the rows name them at every
// thread count, the JSON reads them back byte for byte, and merge-sweep rebases them.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/measure/sweep.h"
#include "app/measure/sweep_json.h"
#include "frame/frame_images.h"
#include "frame/registry.h"
#include "scenes/read_file.h"
#include "scenes/write_file.h"
#include "tests/app/text_count.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;
using test::countOf;

namespace {

// Two shadow-map settings and the reference on a small view, with pictures.
SweepResults sweepWithImages(const std::filesystem::path& outDir) {
    SweepOptions options;
    options.scene = "sphere-box";
    options.overrides.width = 64;
    options.overrides.height = 40;
    options.techniques = {&findTechnique("shadow-map")};
    options.axes = {{"resolution", {"64", "512"}}};
    options.threads = {1, 2};
    options.warmupRuns = 0;
    options.runs = 1;
    options.imagesOutDir = outDir;
    return runSweep(options);
}

}  // namespace

TEST_CASE("sweep --images: each setting's pictures once, at every thread count the same paths") {
    const test::ScratchDirectory scratch("report_sweep_images");
    const SweepResults results = sweepWithImages(scratch.path);
    REQUIRE(results.rows.size() == 4);   // 2 settings x 2 thread counts
    const std::string folder = "sphere-box-shadow-map-images/";
    CHECK(results.rows[0].images.image == folder + "setting-0-image.png");
    CHECK(results.rows[0].images.errorMap == folder + "setting-0-error-map.png");
    CHECK(results.rows[0].images.visibility == folder + "setting-0-visibility.png");
    CHECK(results.rows[0].images.referenceImage == folder + "reference-image.png");
    CHECK(results.rows[0].images.referenceVisibility == folder + "reference-visibility.png");
    CHECK(results.rows[1].images.image == results.rows[0].images.image);
    CHECK(results.rows[2].images.image == folder + "setting-1-image.png");
    REQUIRE_FALSE(results.rows[2].images.debugBuffers.empty());
    for (const SweepRow& row : results.rows) {
        for (const std::string& path : {row.images.image, row.images.errorMap, row.images.referenceImage})
            CHECK(std::filesystem::is_regular_file(scratch.path / path));
        for (const std::string& path : row.images.debugBuffers) {
            CHECK(std::filesystem::is_regular_file(scratch.path / path));
            CHECK(path.starts_with(folder + "setting-" + std::to_string(row.setting) + "-debug/"));
        }
    }
    // A coarse map misses pixels a fine one gets right: the error maps differ.
    CHECK(readWholeFile((scratch.path / results.rows[0].images.errorMap).string()) !=
          readWholeFile((scratch.path / results.rows[2].images.errorMap).string()));
}

TEST_CASE("sweep JSON with pictures: read back, it writes the same bytes, and without them no images field") {
    SweepResults results;
    results.scene = "box";
    results.techniques = {"shadow-map"};
    results.grid.settings = 1, results.grid.threads = {1}, results.grid.runs = 1;   // one row, as read back
    SweepRow row;
    row.technique = "shadow-map";
    row.errors.channel = "V";
    row.images = {"s-images/setting-0-image.png", "s-images/setting-0-error-map.png", "",
                  "s-images/reference-image.png", "s-images/reference-visibility.png",
                  {"s-images/setting-0-debug/b.png", "s-images/setting-0-debug/a.svg"}};
    results.rows = {row};
    const std::string json = formatSweepJson(results);
    const SweepResults read = parseSweepJson(json, "sweep.json");
    CHECK(read.rows.at(0).images.debugBuffers == row.images.debugBuffers);
    CHECK(read.rows.at(0).images.errorMap == row.images.errorMap);
    CHECK(read.rows.at(0).images.visibility.empty());
    CHECK(formatSweepJson(read) == json);
    results.rows[0].images = {};
    CHECK(countOf(formatSweepJson(results), "\"images\"") == 0);
}

TEST_CASE("merge-sweep with pictures: the paths are made relative to the merged JSON's directory") {
    FrameImages images;
    images.image = "s-images/setting-0-image.png";
    images.debugBuffers = {"s-images/setting-0-debug/a.png"};
    const FrameImages moved = rebased(images, "out/shards", "out");
    CHECK(moved.image == "shards/s-images/setting-0-image.png");
    CHECK(moved.debugBuffers.at(0) == "shards/s-images/setting-0-debug/a.png");
    CHECK(moved.errorMap.empty());
    CHECK(rebased(images, "out", "out").image == images.image);
}


TEST_CASE("a technique's debug pictures leave out those of a technique whose name extends its own") {
    const test::ScratchDirectory scratch("debug_pictures_names");
    for (const char* name : {"reference-a.png", "reference-soft-b.png", "izb-x.svg", "izb-pcss-y.png", "izb-z.exr"})
        writeTextFile(scratch.path / name, "x");
    CHECK(debugPictures(scratch.path, scratch.path, "reference") == std::vector<std::string>{"reference-a.png"});
    CHECK(debugPictures(scratch.path, scratch.path, "reference-soft") ==
          std::vector<std::string>{"reference-soft-b.png"});
    CHECK(debugPictures(scratch.path, scratch.path, "izb") == std::vector<std::string>{"izb-x.svg"});
    CHECK(debugPictures(scratch.path, scratch.path, "izb-pcss") == std::vector<std::string>{"izb-pcss-y.png"});
}
