// A sweep of a scene of several lights (docs/many-lights.md): each row carries each light's
// error figures, which are those of the frame scored light by light and sum to the row's;
// the JSON reads them back byte for byte, shards merge them, an older file without them
// still reads; the CSV has a column per light and figure, the text a line per light; the
// report shows them and lists each light's debug buffers under its own heading.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/measure/sweep.h"
#include "app/measure/sweep_json.h"
#include "app/measure/sweep_merge.h"
#include "app/report/report_site.h"
#include "frame/frame_images.h"
#include "frame/registry.h"
#include "frame/score.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"
#include "scenes/write_file.h"
#include "tests/app/csv_fields.h"
#include "tests/app/text_count.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;
using test::countOf;
using test::splitCsvLine;

namespace {

const std::string kThreeLights = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/many-lights/three-lights.json";

// A point, a spot and a sun on a 96 x 60 view: shadow-map at 64 texels (it misses pixels
// of some lights, not of others) and 512, and shadow-volume.
SweepOptions threeLightOptions(SweepShard shard = {}) {
    SweepOptions options;
    options.scene = kThreeLights;
    options.overrides.width = 96;
    options.overrides.height = 60;
    options.techniques = {&findTechnique("shadow-map"), &findTechnique("shadow-volume")};
    options.axes = {{"resolution", {"64", "512"}}};
    options.threads = {1};
    options.warmupRuns = 0;
    options.runs = 1;
    options.shard = shard;
    return options;
}

const SweepResults& threeLightSweep() {
    static const SweepResults results = runSweep(threeLightOptions());
    return results;
}

std::vector<std::string> jsonOf(const std::vector<ErrorFigures>& figures) {
    std::vector<std::string> texts;
    for (const ErrorFigures& f : figures) texts.push_back(formatJson(f));
    return texts;
}

// The data-value of every number cell of the table row that links to `page`.
std::vector<double> rowValues(const std::string& html, const std::string& page) {
    const size_t link = html.find("<tr><td><a href=\"" + page + "\"");
    REQUIRE(link != std::string::npos);
    const std::string row = html.substr(link, html.find("</tr>", link) - link);
    std::vector<double> values;
    const std::string key = "data-value=\"";
    for (size_t at = row.find(key); at != std::string::npos; at = row.find(key, at + 1))
        values.push_back(std::stod(row.substr(at + key.size())));
    return values;
}

}  // namespace

TEST_CASE("sweep of several lights: each light's figures are the frame's, scored light by light, and sum to the row's") {
    const SweepResults& results = threeLightSweep();
    REQUIRE(results.rows.size() == 3);   // shadow-map at 64 and 512 texels, shadow-volume
    Scene scene = loadScene(kThreeLights);
    applyOverrides(scene, threeLightOptions().overrides);
    const PreparedScene prepared(std::move(scene));
    const ImageChannels reference = renderReferenceImage(prepared, FrameSettings{}.simd);
    for (const SweepRow& row : results.rows) {
        CAPTURE(row.technique);
        CAPTURE(row.settingsLabel());
        REQUIRE(row.lightErrors.size() == 3);
        FrameSettings settings;
        settings.params = row.settings;
        const Frame frame = renderFrame(prepared, findTechnique(row.technique), settings);
        CHECK(jsonOf(row.lightErrors) == jsonOf(scoreLights(reference, scoredImage(frame))));
        // Scored over every (pixel, light) pair: the counts are the lights' sums, and the
        // RMS the root of the mean of their squares (each light scores the same pixels).
        uint64_t pixels = 0, falseShadow = 0, falseLight = 0;
        double squares = 0.0;
        for (const ErrorFigures& light : row.lightErrors) {
            CHECK(light.pixels == row.lightErrors[0].pixels);
            pixels += light.pixels, falseShadow += light.falseShadow, falseLight += light.falseLight;
            squares += light.rms * light.rms;
        }
        CHECK(row.errors.pixels == pixels);
        CHECK(row.errors.falseShadow == falseShadow);
        CHECK(row.errors.falseLight == falseLight);
        CHECK(row.errors.rms == doctest::Approx(std::sqrt(squares / 3.0)).epsilon(1e-12));
    }
    // The coarse map errs on some lights and not on all: a row's lights differ.
    const std::vector<ErrorFigures>& coarse = results.rows[0].lightErrors;
    CHECK(results.rows[0].settings.at("resolution") == "64");
    CHECK(results.rows[0].errors.misclassified() > 0);
    CHECK(coarse[0].misclassified() != coarse[1].misclassified());
    CHECK(results.rows[2].errors.misclassified() == 0);   // shadow volumes are exact here
}

TEST_CASE("sweep JSON of several lights: read back it writes the same bytes, shards merge it, older files still read") {
    const SweepResults& results = threeLightSweep();
    const std::string json = formatSweepJson(results);
    const nlohmann::json parsed = nlohmann::json::parse(json);
    REQUIRE(parsed["rows"][0]["lights"].size() == 3);
    CHECK(parsed["rows"][0]["lights"][2]["light"] == 2);
    CHECK(parsed["rows"][0]["lights"][1]["errors"]["false_shadow"] == results.rows[0].lightErrors[1].falseShadow);
    const SweepResults read = parseSweepJson(json, "lights.json");
    for (size_t k = 0; k < results.rows.size(); ++k) CHECK(jsonOf(read.rows[k].lightErrors) == jsonOf(results.rows[k].lightErrors));
    CHECK(formatSweepJson(read) == json);

    // Each shard scores its own rows' lights; merged, they are the whole sweep's.
    std::vector<SweepShardFile> shards;
    for (int index : {1, 2}) {
        const SweepResults shard = runSweep(threeLightOptions({index, 2}));
        shards.push_back({"shard.json", parseSweepJson(formatSweepJson(shard), "shard.json")});
    }
    const SweepResults merged = mergeSweepShards(shards);
    REQUIRE(merged.rows.size() == results.rows.size());
    for (size_t k = 0; k < results.rows.size(); ++k) CHECK(jsonOf(merged.rows[k].lightErrors) == jsonOf(results.rows[k].lightErrors));

    // A file written before the lights' figures: none, and none written again.
    nlohmann::ordered_json old = nlohmann::ordered_json::parse(json);
    for (nlohmann::ordered_json& row : old["rows"]) row.erase("lights");
    const SweepResults older = parseSweepJson(old.dump(2), "old.json");
    CHECK(older.rows[0].lightErrors.empty());
    CHECK(countOf(formatSweepJson(older), "\"lights\"") == 0);
    CHECK(formatJson(older.rows[0].errors) == formatJson(results.rows[0].errors));

    // The lights in order, and two at least (one light's figures are the row's).
    nlohmann::ordered_json swapped = nlohmann::ordered_json::parse(json);
    swapped["rows"][1]["lights"][1]["light"] = 2;
    CHECK_THROWS_WITH_AS(parseSweepJson(swapped.dump(), "swapped.json"),
                         "swapped.json: not the JSON of a sweep: rows[1]: lights[1].light is 2, expected 1",
                         std::runtime_error);
    nlohmann::ordered_json alone = nlohmann::ordered_json::parse(json);
    alone["rows"][0]["lights"].erase(1), alone["rows"][0]["lights"].erase(1);
    CHECK_THROWS_WITH_AS(parseSweepJson(alone.dump(), "alone.json"), doctest::Contains("rows[0]: lights: expected an array of 2..16"),
                         std::runtime_error);
}

TEST_CASE("sweep CSV and text of several lights: each light's headline figures in columns, a line per light") {
    const SweepResults& results = threeLightSweep();
    std::istringstream csv(formatSweepCsv(results));
    std::string line;
    std::getline(csv, line);
    const std::vector<std::string> header = splitCsvLine(line);
    REQUIRE(header.size() > 27);
    CHECK(header[16] == "reference");
    CHECK(header[17] == "flip_mean");
    const std::vector<std::string> figures = {"misclassified_percent", "rms", "umbra_lit_percent"};
    for (size_t light = 0; light < 3; ++light)
        for (size_t f = 0; f < figures.size(); ++f)
            CHECK(header[18 + 3 * light + f] == "light" + std::to_string(light) + "_" + figures[f]);
    CHECK(header[27] == "light0_technique_ms");   // then the stats, as before
    for (const SweepRow& row : results.rows) {
        REQUIRE(std::getline(csv, line));
        const std::vector<std::string> fields = splitCsvLine(line);
        REQUIRE(row.errors.flipMean.has_value());
        CHECK(std::stod(fields[17]) == doctest::Approx(*row.errors.flipMean).epsilon(1e-8));
        for (size_t light = 0; light < 3; ++light) {
            const ErrorFigures& e = row.lightErrors[light];
            CHECK(std::stod(fields[18 + 3 * light]) == doctest::Approx(e.percentOfPixels(e.misclassified())).epsilon(1e-8));
            CHECK(std::stod(fields[19 + 3 * light]) == doctest::Approx(e.rms).epsilon(1e-8));
            CHECK(std::stod(fields[20 + 3 * light]) == doctest::Approx(e.percentOfPixels(e.umbraLit)).epsilon(1e-8));
            CHECK_FALSE(e.flipMean.has_value());   // FLIP is of the whole shaded image, every light at once
        }
    }
    const std::string text = formatSweepText(results);
    CHECK(countOf(text, "\n  light ") == 3 * results.rows.size());
    char misclassified[32];   // light 1 of the coarse map, as its line shows it
    const ErrorFigures& light1 = results.rows[0].lightErrors[1];
    std::snprintf(misclassified, sizeof misclassified, "%14.4f", light1.percentOfPixels(light1.misclassified()));
    const size_t at = text.find("\n  light 1 ");
    REQUIRE(at != std::string::npos);
    CHECK(text.find(misclassified, at) == at + 1 + 16 + 1 + 40 + 1 + 7 + 1 + 10 + 1 + 10 + 1);
}

TEST_CASE("report of a sweep of several lights: each light's figures in the tables, its debug buffers under its name") {
    const test::ScratchDirectory scratch("report_three_lights");
    SweepOptions options = threeLightOptions();
    options.techniques = {&findTechnique("shadow-map")};
    options.axes = {{"resolution", {"64"}}};
    options.imagesOutDir = scratch.path / "results";
    const SweepResults results = runSweep(options);
    REQUIRE(results.rows.size() == 1);
    const SweepRow& row = results.rows[0];
    // Each light's debug buffers, from its own folder, light by light.
    const std::vector<std::string>& debug = row.images.debugBuffers;
    REQUIRE(debug.size() > 3);
    std::vector<size_t> lights;
    for (const std::string& path : debug) {
        REQUIRE(debugPictureLight(path));
        if (lights.empty() || lights.back() != *debugPictureLight(path)) lights.push_back(*debugPictureLight(path));
    }
    CHECK(lights == std::vector<size_t>{0, 1, 2});
    CHECK_FALSE(debugPictureLight("setting-0-debug/shadow-map-depth.png"));

    const std::string file = (scratch.path / "results" / "lights.json").string();
    writeTextFile(file, formatSweepJson(results));
    const std::filesystem::path site = scratch.path / "site";
    writeReportSite({file}, site, PlotErrorAxis::Misclassified);
    // The scene's table: the row's figures, then each light's misclassified % and RMS.
    const std::string scene = readWholeFile((site / "scene-three-lights.html").string());
    for (const char* column : {"light 0 misclassified %", "light 2 RMS"}) CHECK(countOf(scene, column) == 1);
    const std::vector<double> values = rowValues(scene, "lights-setting-0.html");
    REQUIRE(values.size() == 3 + 5 + 2 * 3);   // threads, times; five figures; two per light
    for (size_t light = 0; light < 3; ++light) {
        const ErrorFigures& e = row.lightErrors[light];
        CHECK(values[8 + 2 * light] == e.percentOfPixels(e.misclassified()));
        CHECK(values[9 + 2 * light] == e.rms);
    }
    // The setting's page: a column per light in the figures, a heading per light over its buffers.
    const std::string setting = readWholeFile((site / "lights-setting-0.html").string());
    CHECK(countOf(setting, "<th scope=\"col\">every light</th>") == 1);
    for (size_t light = 0; light < 3; ++light) {
        const std::string name = "light " + std::to_string(light);
        CHECK(countOf(setting, "<th scope=\"col\">" + name + "</th>") == 1);
        CHECK(countOf(setting, "<h3>" + name + "</h3>") == 1);
    }
    CHECK(setting.find("<h3>light 0</h3>") < setting.find("/light0/"));
    CHECK(setting.find("/light0/") < setting.find("<h3>light 1</h3>"));
    CHECK(countOf(setting, "<img class=\"debug\"") == debug.size());
}
