// `shadowlab report`: the pages link what they must and show each setting's pictures,
// escape odd names, read a render's JSON too, and bad inputs fail naming the file before
// anything is written. The browser's side is tests/report/browser_test.mjs.
#include <doctest/doctest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/measure/sweep_json.h"
#include "app/report/report_collect.h"
#include "app/report/report_site.h"
#include "frame/score.h"
#include "frame/score_json.h"
#include "scenes/read_file.h"
#include "scenes/write_file.h"
#include "shading/image_io.h"
#include "tests/app/text_count.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;
using test::countOf;

namespace {

// A tiny PNG, for results whose pictures are not rendered.
void writeTinyPng(const std::filesystem::path& path) {
    std::filesystem::create_directories(path.parent_path());
    writePng(path, 3, 2, std::vector<uint8_t>(3 * 3 * 2, 128));
}

// A sweep of one row with every picture, its names as odd as a user may make them.
SweepResults oddSweep(const std::filesystem::path& dir) {
    SweepResults results;
    results.scene = "a <scene> & \"quotes\"";
    results.techniques = {"<b>technique</b>"};
    results.grid.threads = {1};
    results.grid.runs = 1;
    results.grid.settings = 1;
    SweepRow row;
    row.technique = "<b>technique</b>";
    row.reference = "reference";
    row.settings = {{"bias", "<script>alert(1)</script>"}};
    row.threads = 1;
    row.medianMs = row.minMs = 2.5;
    row.errors.channel = "V";
    row.errors.pixels = 6;
    row.stats = {{"odd<stat>_count", 3}};
    for (const char* name : {"pics/image.png", "pics/error.png", "pics/reference.png", "pics/debug/map.png"})
        writeTinyPng(dir / name);
    row.images.image = "pics/image.png";
    row.images.errorMap = "pics/error.png";
    row.images.referenceImage = "pics/reference.png";
    row.images.debugBuffers = {"pics/debug/map.png"};
    results.rows = {row};
    return results;
}

std::string oddSweepFile(const std::filesystem::path& dir) {
    const std::string file = (dir / "odd.json").string();
    writeTextFile(file, formatSweepJson(oddSweep(dir)));
    return file;
}

// shadow-map at two resolutions, each at 1 and 2 threads, with its pictures as a sweep
// --images names them; returns the JSON file.
std::string twoSettingSweepFile(const std::filesystem::path& dir) {
    SweepResults results;
    results.scene = "box";
    results.techniques = {"shadow-map"};
    results.grid.threads = {1, 2};
    results.grid.runs = 1;
    results.grid.settings = 2;
    for (uint64_t setting : {0, 1}) {
        const std::string name = "s-images/setting-" + std::to_string(setting);
        const FrameImages images = {name + "-image.png", name + "-error-map.png", name + "-visibility.png",
                                    "s-images/reference-image.png", "", {name + "-debug/shadow-map-depth.png"}};
        withPaths(images, [&](const std::string& picture) {
            writeTinyPng(dir / picture);
            return picture;
        });
        for (int threads : {1, 2}) {
            SweepRow row;
            row.setting = setting;
            row.technique = "shadow-map";
            row.reference = "reference";
            row.settings = {{"resolution", setting == 0 ? "256" : "512"}};
            row.threads = threads;
            row.medianMs = row.minMs = double(setting + 1) / threads;
            row.errors.channel = std::string("V");   // not = "V": GCC 12 warns of an overlap (-Wrestrict, PR 105329)
            row.errors.pixels = 6;
            row.errors.falseShadow = 1 - setting;
            row.stats = {{"resolution_texels", setting == 0 ? 256.0 : 512.0}};
            row.images = images;
            results.rows.push_back(row);
        }
    }
    const std::string file = (dir / "sweep.json").string();
    writeTextFile(file, formatSweepJson(results));
    return file;
}

std::string messageOf(const std::function<void()>& work) {
    try {
        work();
    } catch (const std::exception& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("report: the index links the scenes, a scene's plot links every setting, a setting shows its pictures") {
    const test::ScratchDirectory scratch("report_pages");
    const std::string file = twoSettingSweepFile(scratch.path / "results");
    const std::filesystem::path site = scratch.path / "site";
    CHECK(writeReportSite({file}, site, PlotErrorAxis::Misclassified) == 1 + 1 + 2);
    for (const char* name : {"index.html", "scene-box.html", "sweep-setting-0.html", "sweep-setting-1.html",
                             "report.css", "report.js"})
        CHECK(std::filesystem::is_regular_file(site / name));
    const std::string index = readWholeFile((site / "index.html").string());
    CHECK(countOf(index, "<a href=\"scene-box.html\">") == 2);   // in the scenes' and the techniques' tables
    CHECK(countOf(index, "<a href=\"sweep-setting-1.html\">resolution=512</a>") == 1);
    const std::string scene = readWholeFile((site / "scene-box.html").string());
    CHECK(countOf(scene, "<a href=\"sweep-setting-0.html\"><circle class=\"point\"") == 2);   // at 1 and 2 threads
    CHECK(countOf(scene, "<a href=\"sweep-setting-1.html\"><circle class=\"point\"") == 2);
    CHECK(countOf(scene, "<table class=\"sortable\">") == 1);
    const std::string setting = readWholeFile((site / "sweep-setting-1.html").string());
    for (const char* picture : {"s-images/setting-1-image.png", "s-images/setting-1-error-map.png",
                                "s-images/setting-1-visibility.png", "s-images/reference-image.png",
                                "s-images/setting-1-debug/shadow-map-depth.png"}) {
        CAPTURE(picture);
        const std::string path = std::string("images/sweep/") + picture;
        CHECK(countOf(setting, "src=\"" + path + "\"") >= 1);
        CHECK(std::filesystem::is_regular_file(site / path));
    }
    CHECK(countOf(setting, "setting-0-") == 0);   // only this setting's pictures
    CHECK(countOf(setting, "class=\"slider\" hidden") == 1);
    CHECK(countOf(setting, "width=\"3\" height=\"2\"") >= 3);   // the zoom's unit, from the PNG
    CHECK(countOf(setting, "--width: 3px") == 1);
    CHECK(countOf(setting, "<img class=\"debug\"") == 1);
    CHECK(countOf(setting, "resolution_texels") == 1);
    CHECK(countOf(readWholeFile((site / "report.css").string()), "image-rendering: pixelated") == 1);
}

TEST_CASE("report: odd names are escaped in every page and kept out of file names") {
    const test::ScratchDirectory scratch("report_escaping");
    const std::filesystem::path site = scratch.path / "site";
    writeReportSite({oddSweepFile(scratch.path)}, site, PlotErrorAxis::Misclassified);
    const std::string scenePage = "scene-a--scene-----quotes-.html";
    REQUIRE(std::filesystem::is_regular_file(site / scenePage));
    for (const std::string& page : {std::string("index.html"), scenePage, std::string("odd-setting-0.html")}) {
        CAPTURE(page);
        const std::string html = readWholeFile((site / page).string());
        CHECK(countOf(html, "<script>alert") == 0);
        CHECK(countOf(html, "<b>") == 0);
        CHECK(countOf(html, "a &lt;scene&gt; &amp; &quot;quotes&quot;") >= 1);
    }
    const std::string setting = readWholeFile((site / "odd-setting-0.html").string());
    CHECK(countOf(setting, "&lt;script&gt;alert(1)&lt;/script&gt;") >= 1);
    CHECK(countOf(setting, "odd&lt;stat&gt;_count") == 1);
    CHECK(safeFileName("../a b/c?.png") == "-..-a-b-c-.png");
}

TEST_CASE("report: a render's JSON is a page of one row with its pictures") {
    const test::ScratchDirectory scratch("report_render");
    const SweepRow row = oddSweep(scratch.path).rows[0];
    Frame frame;
    frame.techniqueMs = 1.25;
    writeTextFile(scratch.path / "render.json",
                  formatScoreJson("box", "shadow-map", "reference", {{"resolution", "512"}}, frame, row.errors,
                                  row.images));
    const std::filesystem::path site = scratch.path / "site";
    CHECK(writeReportSite({(scratch.path / "render.json").string()}, site, PlotErrorAxis::Misclassified) == 3);
    const std::string page = readWholeFile((site / "render-setting-0.html").string());
    CHECK(countOf(page, "src=\"images/render/pics/error.png\"") == 1);
    CHECK(countOf(page, "shadow-map, resolution=512") >= 1);
    CHECK(std::filesystem::is_regular_file(site / "images/render/pics/debug/map.png"));
    CHECK(countOf(page, "<th scope=\"row\">umbra lit 0.02 %</th><td") == 1);
    CHECK(countOf(page, "not recorded") == 0);
}

// What a render's JSON did not yet record is shown as not recorded, not as a default: the
// scene's own view and light, or no umbra lit above 0.02.
TEST_CASE("report: a render's JSON from before the overrides and umbra lit 0.02 shows both as not recorded") {
    const test::ScratchDirectory scratch("report_old_render");
    const SweepRow row = oddSweep(scratch.path).rows[0];
    nlohmann::json old = nlohmann::json::parse(formatScoreJson("box", "pcss", "reference-soft", {}, Frame{}, row.errors));
    old.erase("overrides");
    for (const char* key : {"full_umbra_pixels", "full_umbra_lit", "full_umbra_lit_percent"}) old.at("errors").erase(key);
    writeTextFile(scratch.path / "old.json", old.dump(2));
    writeTextFile(scratch.path / "new.json", formatScoreJson("box", "pcss", "reference-soft", {}, Frame{}, row.errors));
    const std::filesystem::path site = scratch.path / "site";
    writeReportSite({(scratch.path / "old.json").string(), (scratch.path / "new.json").string()}, site,
                    PlotErrorAxis::Auto);
    const std::string page = readWholeFile((site / "old-setting-0.html").string());
    CHECK(countOf(page, "<th scope=\"row\">umbra lit 0.02 %</th><td>not recorded</td>") == 1);
    CHECK(countOf(page, "Measured under: conditions not recorded") == 1);
    // Not filed with the render under the scene's own view and light.
    CHECK(countOf(readWholeFile((site / "index.html").string()), "href=\"scene-box-2.html\"") >= 1);
}

// A render under another view or light is not comparable with one under the scene's own:
// the JSON records the overrides, and the report files each under its conditions.
TEST_CASE("report: results are grouped by the conditions they were measured under, shown on every page") {
    const test::ScratchDirectory scratch("report_conditions");
    const SweepRow row = oddSweep(scratch.path).rows[0];
    SceneOverrides moved;
    moved.width = 320, moved.height = 200, moved.lightPosition = glm::vec3(-5.0f, 5.0f, 2.0f);
    writeTextFile(scratch.path / "default.json", formatScoreJson("box", "pcss", "reference-soft", {}, Frame{}, row.errors));
    writeTextFile(scratch.path / "moved.json",
                  formatScoreJson("box", "pcss", "reference-soft", {}, Frame{}, row.errors, {}, moved));
    const auto record = std::get<ScoreRecord>(parseResultsJson(readWholeFile((scratch.path / "moved.json").string()), "m"));
    REQUIRE(record.overrides);
    CHECK(record.overrides->lightPosition == moved.lightPosition);
    CHECK(record.overrides->width == 320);
    const std::filesystem::path site = scratch.path / "site";
    writeReportSite({(scratch.path / "default.json").string(), (scratch.path / "moved.json").string()}, site,
                    PlotErrorAxis::Auto);
    const std::string index = readWholeFile((site / "index.html").string());
    CHECK(countOf(index, "href=\"scene-box.html\"") >= 1);
    CHECK(countOf(index, "href=\"scene-box-2.html\"") >= 1);   // the same scene under other conditions
    // In the scenes' table and the techniques': twice each.
    CHECK(countOf(index, "the scene&#39;s own view and light") + countOf(index, "the scene's own view and light") == 2);
    const std::string conditions = "320 x 200 pixels, light at (-5, 5, 2)";
    CHECK(countOf(index, conditions) == 2);
    CHECK(countOf(readWholeFile((site / "scene-box-2.html").string()), conditions) == 1);
    CHECK(countOf(readWholeFile((site / "moved-setting-0.html").string()), conditions) == 1);
}

TEST_CASE("report: two pictures whose safe names are alike keep their own files") {
    // "a b.png" and "a-b.png" are both made "a-b.png"; the second must not show the first.
    const test::ScratchDirectory scratch("report_alike");
    const SweepRow row = oddSweep(scratch.path).rows[0];
    writeTinyPng(scratch.path / "a b.png");
    writePng(scratch.path / "a-b.png", 2, 2, std::vector<uint8_t>(2 * 2 * 3, 7));
    FrameImages images;
    images.image = "a b.png";
    images.errorMap = "a-b.png";
    writeTextFile(scratch.path / "render.json",
                  formatScoreJson("box", "shadow-map", "reference", {}, Frame{}, row.errors, images));
    const std::filesystem::path site = scratch.path / "site";
    writeReportSite({(scratch.path / "render.json").string()}, site, PlotErrorAxis::Misclassified);
    const std::string page = readWholeFile((site / "render-setting-0.html").string());
    CHECK(countOf(page, "src=\"images/render/a-b.png\"") == 1);
    CHECK(countOf(page, "src=\"images/render/a-b-2.png\"") == 1);
    CHECK(readWholeFile((site / "images/render/a-b.png").string()) == readWholeFile((scratch.path / "a b.png").string()));
    CHECK(readWholeFile((site / "images/render/a-b-2.png").string()) ==
          readWholeFile((scratch.path / "a-b.png").string()));
}

TEST_CASE("report: a file of neither kind, a missing picture, broken JSON and no files fail naming the problem") {
    const test::ScratchDirectory scratch("report_errors");
    const std::filesystem::path site = scratch.path / "site";
    writeTextFile(scratch.path / "other.json", "{\"name\": \"something else\"}");
    const std::string other = (scratch.path / "other.json").string();
    const std::string neither = messageOf([&] { writeReportSite({other}, site, {}); });
    CHECK(countOf(neither, "other.json: neither a sweep's JSON") == 1);
    writeTextFile(scratch.path / "broken.json", "{\"grid\": ");
    CHECK(countOf(messageOf([&] { writeReportSite({(scratch.path / "broken.json").string()}, site, {}); }),
                  "broken.json: invalid JSON") == 1);
    const std::string odd = oddSweepFile(scratch.path);
    std::filesystem::remove(scratch.path / "pics/error.png");
    const std::string missing = messageOf([&] { writeReportSite({odd}, site, {}); });
    CHECK(countOf(missing, "odd.json: picture 'pics/error.png' not found") == 1);
    CHECK_FALSE(std::filesystem::exists(site));   // nothing written before every input was read
    CHECK(countOf(messageOf([&] { writeReportSite({}, site, {}); }), "report: give the JSON files") == 1);
}
