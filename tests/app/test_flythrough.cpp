// `shadowlab flythrough`: time, error and flicker along a camera path. A camera that does
// not move must not flicker at all; texel snapping must remove the flicker a sub-texel
// move of the camera causes in cascaded shadow maps; the files read back; a path that moves
// an object gives each frame the references of the moved scene, and the techniques follow.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/measure/flythrough.h"
#include "app/measure/flythrough_report.h"
#include "app/plots/flythrough_plot.h"
#include "frame/registry.h"
#include "frame/score.h"
#include "scenes/camera_path.h"
#include "scenes/scene_file.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;

namespace {

std::string sunScene() { return builtinSceneDir() + "/hard/sun.json"; }
std::string movingScene(const std::string& name) { return builtinSceneDir() + "/flythrough/" + name + ".json"; }

// Keyframes as CSV: the camera from (eye, target) at time 0 to both moved by `move` at time 1.
std::string writePath(const test::ScratchDirectory& dir, const glm::vec3& eye, const glm::vec3& target,
                      const glm::vec3& move) {
    const std::string file = (dir.path / "path.csv").string();
    std::ofstream out(file);
    out << "time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n";
    for (float s : {0.0f, 1.0f}) {
        const glm::vec3 e = eye + s * move, t = target + s * move;
        out << s << ',' << e.x << ',' << e.y << ',' << e.z << ',' << t.x << ',' << t.y << ',' << t.z << '\n';
    }
    return file;
}

FlythroughOptions smallRun(const std::string& scene, std::vector<std::string> techniques, int frames) {
    FlythroughOptions options;
    options.scene = scene;
    options.overrides.width = 160;
    options.overrides.height = 100;
    options.frames = frames;
    options.warmupRuns = 0;
    options.runs = 1;
    options.threads = 2;
    for (const std::string& name : techniques) options.techniques.push_back(&findTechnique(name));
    return options;
}

}  // namespace

TEST_CASE("a static camera gives zero flicker for every technique") {
    const test::ScratchDirectory dir("flythrough_static");
    using Case = std::pair<std::string, std::vector<std::string>>;
    for (const auto& [scene, techniques] : {Case{"sphere-box", {"shadow-map", "pcss", "fins"}},
                                            Case{sunScene(), {"csm", "shadow-map"}}}) {
        FlythroughOptions options = smallRun(scene, techniques, 3);
        options.pathFile = writePath(dir, {0, 4, 9}, {0, 0.5f, 0}, {0, 0, 0});
        const FlythroughResults results = runFlythrough(options);
        REQUIRE(results.series.size() == techniques.size());
        for (const FlythroughSeries& series : results.series) {
            const std::string label = series.label();
            CAPTURE(label);
            REQUIRE(series.frames.size() == 3);
            CHECK_FALSE(series.frames[0].flicker);
            for (size_t f = 1; f < 3; ++f) {
                REQUIRE(series.frames[f].flicker);
                const FlickerFigures& flicker = *series.frames[f].flicker;
                CHECK(flicker.pixels > 10000);
                CHECK(flicker.stablePixels == flicker.pixels);
                CHECK(flicker.mean == 0.0);
                CHECK(flicker.p99 == 0.0);
                CHECK(series.frames[f].errors.rms == series.frames[0].errors.rms);
                CHECK(series.frames[f].errors.flipMean == series.frames[0].errors.flipMean);
            }
            CHECK(pathFigures(series).flickerMean == 0.0);
        }
    }
}

TEST_CASE("texel snapping removes the flicker a sub-texel camera move causes in cascaded shadow maps") {
    // The sun over sphere-box, the camera moving 13 mm a frame along its view axis (the path's
    // 94 mm over 8 frames): under a texel of every cascade at 512 texels (the nearest is over
    // 12 m wide, 2.4 cm a texel). Unsnapped, every cascade follows the
    // camera and its texels slide under the world, flipping texels along every shadow edge;
    // snapped, the texels stay in place and only pixels sliding over the (world-fixed)
    // staircase change, few near the image's centre, whose surface points barely move.
    FlythroughOptions options = smallRun(builtinSceneDir() + "/hard/sun.json", {"csm"}, 8);
    options.overrides.width = 640;
    options.overrides.height = 400;
    options.pathFile = builtinSceneDir() + "/flythrough/sun-dolly.csv";
    options.axes = {{"snap", {"off", "on"}}, {"resolution", {"512"}}};
    const FlythroughResults results = runFlythrough(options);
    REQUIRE(results.series.size() == 2);
    CHECK(results.series[0].settings.at("snap") == "off");
    const PathFigures off = pathFigures(results.series[0]), on = pathFigures(results.series[1]);
    MESSAGE("flicker mean: snap off ", off.flickerMean, ", on ", on.flickerMean);
    CHECK(off.flickerMean > 2e-4);
    CHECK(on.flickerMean < 0.5 * off.flickerMean);
    for (const FlythroughFrame& frame : results.series[1].frames)
        if (frame.flicker) CHECK(frame.flicker->stablePercent() > 99.0);
}

TEST_CASE("a fly-through hands each setting's history on: a virtual map redraws only the pages a moving caster dirties") {
    // The sphere slides under a still sun: after the first frame, the pages kept from the
    // frame before are read from the cache and only those under the sphere's boxes drawn
    // again; the figures reach the CSV and the JSON frame by frame.
    FlythroughOptions options =
        smallRun(builtinSceneDir() + "/flythrough/sliding-sphere-still-sun.json", {"virtual-shadow-map"}, 3);
    options.axes = {{"virtual-resolution", {"4096"}}, {"page-texels", {"64"}}};
    const FlythroughResults results = runFlythrough(options);
    REQUIRE(results.series.size() == 1);
    const std::vector<FlythroughFrame>& frames = results.series[0].frames;
    REQUIRE(frames.size() == 3);
    const auto stat = [](const FlythroughFrame& f, const std::string& name) {
        const auto it = std::ranges::find(f.stats, name, &TechniqueStat::name);
        REQUIRE(it != f.stats.end());
        return it->value;
    };
    CHECK(stat(frames[0], "cache_drawn_pages") == stat(frames[0], "requested_pages"));
    for (size_t k = 1; k < frames.size(); ++k) {
        CHECK(stat(frames[k], "cache_invalidated_pages") > 0);
        CHECK(stat(frames[k], "cache_drawn_pages") > 0);
        CHECK(stat(frames[k], "cache_hit_percent") > 50.0);
        CHECK(frames[k].errors.percentOfPixels(frames[k].errors.misclassified()) < 0.5);
    }
    const std::string csv = formatFlythroughCsv(results);
    CHECK(csv.substr(0, csv.find('\n')).find(",cache_drawn_pages,") != std::string::npos);
    const nlohmann::json json = nlohmann::json::parse(formatFlythroughJson(results));
    CHECK(json["series"][0]["frames"][2]["stats"]["cache_drawn_pages"].get<double>() == stat(frames[2], "cache_drawn_pages"));
    // Its pages drawn and cache hits per frame are plotted, one point a frame.
    for (FlythroughPlot plot : {FlythroughPlot::DrawnPages, FlythroughPlot::CacheHits}) {
        REQUIRE(hasFlythroughPlot(results, plot));
        CHECK(formatFlythroughSvg(results, plot).find("virtual-shadow-map") != std::string::npos);
    }
}

TEST_CASE("a fly-through follows the scene's path and writes its table, JSON, plots and frames") {
    const test::ScratchDirectory dir("flythrough_files");
    FlythroughOptions options = smallRun("sphere-box", {"shadow-map"}, 4);
    options.imagesOutDir = dir.path;
    const FlythroughResults results = runFlythrough(options);
    const std::filesystem::path frames = dir.path / "sphere-box-flythrough-shadow-map-frames" / "shadow-map";
    for (const char* file : {"0000-image.png", "0000-error-map.png", "0003-image.png", "0003-visibility.png"})
        CHECK(std::filesystem::file_size(frames / file) > 100);
    CHECK_FALSE(std::filesystem::exists(frames / "0004-image.png"));
    CHECK(results.path == "scene");
    REQUIRE(results.series.size() == 1);
    const FlythroughSeries& series = results.series[0];
    REQUIRE(series.frames.size() == 4);
    // sphere-box's path: frame 0 at its first keyframe, frame 3 at its last, frame 1 at time 1.
    CHECK(series.frames[0].eye == glm::vec3(0, 4, 9));
    CHECK(series.frames[1].eye == glm::vec3(5, 3.5f, 7.5f));
    CHECK(series.frames[3].eye == glm::vec3(6, 2, -4));
    // The camera moves a lot between frames: some pixels see other surfaces, whose reference
    // differs, and are left out.
    REQUIRE(series.frames[1].flicker);
    CHECK(series.frames[1].flicker->stablePixels < series.frames[1].flicker->pixels);
    CHECK(series.frames[1].errors.rms != series.frames[0].errors.rms);
    // FLIP beside the RMS on every frame: a shadow map's errors are small, seen, and under 1.
    for (const FlythroughFrame& frame : series.frames) {
        REQUIRE(frame.errors.flipMean.has_value());
        CHECK(*frame.errors.flipMean > 0.0);
        CHECK(*frame.errors.flipMean < 0.5);
    }

    const std::string csv = formatFlythroughCsv(results);
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 5);
    CHECK(csv.rfind("technique,settings,frame,time,eye_x", 0) == 0);
    CHECK(csv.substr(0, csv.find('\n')).find(",false_light_percent,flip_mean,flicker_mean,") != std::string::npos);
    const nlohmann::json json = nlohmann::json::parse(formatFlythroughJson(results));
    CHECK(json["frames"] == 4);
    CHECK(json["series"][0]["frames"][0]["flicker"].is_null());
    CHECK(json["series"][0]["frames"][2]["flicker"]["stable_pixels"].get<uint64_t>() ==
          series.frames[2].flicker->stablePixels);
    CHECK(json["series"][0]["path_figures"]["flicker_mean"].get<double>() == pathFigures(series).flickerMean);
    CHECK(json["series"][0]["path_figures"]["mean_flip"].get<double>() == pathFigures(series).meanFlip);
    CHECK(json["series"][0]["frames"][3]["errors"]["flip_mean"].get<double>() == *series.frames[3].errors.flipMean);
    CHECK(hasFlythroughPlot(results, FlythroughPlot::Flip));
    for (FlythroughPlot plot : {FlythroughPlot::Time, FlythroughPlot::Error, FlythroughPlot::Flicker, FlythroughPlot::Flip})
        CHECK(formatFlythroughSvg(results, plot).find("shadow-map") != std::string::npos);
    // A shadow map caches no pages: no cache plots.
    CHECK_FALSE(hasFlythroughPlot(results, FlythroughPlot::DrawnPages));
    CHECK_FALSE(hasFlythroughPlot(results, FlythroughPlot::CacheHits));
    CHECK(flythroughFileStem(results.scene, {&findTechnique("shadow-map"), &findTechnique("pcss")}) ==
          "sphere-box-flythrough-shadow-map+pcss");
}

TEST_CASE("a fly-through refuses what it cannot measure, before rendering") {
    CHECK_THROWS_WITH_AS(runFlythrough(smallRun(builtinSceneDir() + "/hard/spot.json", {"shadow-map"}, 2)),
                         doctest::Contains("has no \"flythrough\" path"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(runFlythrough(smallRun("sphere-box", {"env-subtractive"}, 2)),
                         doctest::Contains("flicker is measured on V"), std::invalid_argument);
    FlythroughOptions moved = smallRun("sphere-box", {"shadow-map"}, 2);
    moved.overrides.eye = glm::vec3(1, 2, 3);
    CHECK_THROWS_WITH_AS(runFlythrough(moved), doctest::Contains("the path places the camera"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(runFlythrough(smallRun("sphere-box", {"shadow-map"}, 1)), doctest::Contains("at least 2 frames"),
                         std::invalid_argument);
    FlythroughOptions typo = smallRun("sphere-box", {"shadow-map"}, 2);
    typo.axes = {{"resolutoin", {"512"}}};
    CHECK_THROWS_WITH_AS(runFlythrough(typo), doctest::Contains("none of the techniques"), std::invalid_argument);
}

TEST_CASE("a moved frame's references are those of the moved scene prepared afresh") {
    // The disk light's soft reference and its centre's hard one; the sun's hard one.
    using Case = std::pair<std::string, std::vector<std::string>>;
    // Named, not bound (clang 14 cannot capture structured bindings in INFO's lambda).
    for (const Case& c : {Case{"sliding-sphere", {"reference", "reference-soft"}}, Case{"sliding-sphere-sun", {"reference"}}}) {
        const std::string& name = c.first;
        const std::vector<std::string>& references = c.second;
        Scene scene = loadScene(movingScene(name));
        SceneOverrides small;
        small.width = 96, small.height = 60;
        applyOverrides(scene, small);
        PreparedScene moving(scene);
        std::vector<ImageChannels> before;   // the BVH built where the file put the sphere
        for (const std::string& reference : references)
            before.push_back(renderReferenceImage(moving, raster::bestSimdLevel(), reference));
        const PathSample sample = samplePath(scene.flythrough, 7, 12);
        REQUIRE(moving.setInstanceTransforms(sample.placements) == 1);
        placeOnPath(sample, 7, scene.camera, scene.lights);
        moving.setLights(scene.lights);
        for (const InstancePlacement& placement : sample.placements)
            scene.instances[placement.instance].worldFromObject = placement.worldFromObject;
        const PreparedScene fresh(scene);
        for (size_t r = 0; r < references.size(); ++r) {
            INFO(name, " ", references[r]);
            const ImageChannels a = renderReferenceImage(moving, raster::bestSimdLevel(), references[r]);
            const ImageChannels b = renderReferenceImage(fresh, raster::bestSimdLevel(), references[r]);
            CHECK(a.data == b.data);
            CHECK(a.data != before[r].data);
        }
    }
}

TEST_CASE("a path that moves an object and turns the sun renders, and shadow-map follows it") {
    for (const std::string name : {"sliding-sphere", "sliding-sphere-sun"}) {
        INFO(name);
        const FlythroughResults results = runFlythrough(smallRun(movingScene(name), {"shadow-map"}, 6));
        REQUIRE(results.series.size() == 1);
        const FlythroughSeries& series = results.series[0];
        REQUIRE(series.frames.size() == 6);
        for (const FlythroughFrame& frame : series.frames) {
            INFO("frame ", frame.frame);
            // A map left where the sphere was would misclassify its old and new shadows.
            CHECK(frame.errors.percentOfPixels(frame.errors.misclassified()) < 1.0);
        }
        // The camera stays, the sphere and its shadow move: the reference changes under more
        // than 3% of the pixels from frame to frame (about 6.8% on sliding-sphere), which a
        // map that did not follow would misclassify, far beyond the bound above.
        for (size_t f = 1; f < series.frames.size(); ++f) {
            REQUIRE(series.frames[f].flicker);
            const FlickerFigures& flicker = *series.frames[f].flicker;
            CHECK(double(flicker.pixels - flicker.stablePixels) > 0.03 * double(flicker.pixels));
        }
    }
}

TEST_CASE("a path that ends still measures how long a technique's history takes to settle, and its ghosting") {
    // sphere-stops: the sphere moves over frames 1 to 9 of 24, then stays. shadow-map keeps no
    // result from frame to frame: settled at once, no error above its last frame's. With
    // temporal accumulation its shadow lags the sphere (the history clamped to a neighbourhood
    // that spans the moving edge) and decays over the still frames: it takes frames to settle,
    // and its ghosting is many times larger.
    FlythroughOptions options = smallRun(builtinSceneDir() + "/flythrough/sphere-stops.json", {"shadow-map"}, 0);
    options.axes = {{"filter", {"poisson"}}, {"poisson-rotation", {"ign"}}, {"temporal", {"off", "on"}}};
    const FlythroughResults results = runFlythrough(options);
    REQUIRE(results.series.size() == 2);
    const FlythroughSeries& series = results.series[1];
    REQUIRE(series.frames.size() == 24);
    CHECK_FALSE(series.frames[0].moved);
    CHECK(series.frames[1].moved);
    CHECK(series.frames[9].moved);   // time 9/23 is past the stop at 0.35, frame 8's is not
    CHECK_FALSE(series.frames[10].moved);
    const PathFigures off = pathFigures(results.series[0]), on = pathFigures(series);
    REQUIRE(off.settleFrames);
    REQUIRE(on.settleFrames);
    MESSAGE("settle frames off ", *off.settleFrames, ", on ", *on.settleFrames, "; ghosting off ", *off.ghosting,
            ", on ", *on.ghosting);
    CHECK(*off.settleFrames == 0);
    CHECK(*off.ghosting < 0.02);   // the rotated disk's noise moves each frame's RMS a little
    CHECK(*on.settleFrames >= 2);
    CHECK(on.settled);                // within the 14 still frames
    CHECK(off.settled);
    CHECK(*on.ghosting > 10.0 * *off.ghosting);
}
