// Soft shadows in scoring: `reference-soft` is the exact soft V, techniques are scored
// against the reference they name, and --light-radius (SceneOverrides::lightRadius)
// changes the penumbra as geometry says it must.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/measure/sweep.h"
#include "frame/registry.h"
#include "frame/score.h"
#include "scenes/scene_file.h"
#include "shadows/reference/reference.h"

using namespace shadowlab;

namespace {

SceneOverrides imageSize(int width, int height) {
    SceneOverrides overrides;
    overrides.width = width;
    overrides.height = height;
    return overrides;
}

SceneOverrides lightRadius(float radius) {
    SceneOverrides overrides;
    overrides.lightRadius = radius;
    return overrides;
}

// sphere-box, small enough for 1024 rays per pixel in a test.
Scene smallSphereBox(int width, int height) {
    Scene scene = loadScene("sphere-box");
    applyOverrides(scene, imageSize(width, height));
    return scene;
}

Frame renderSoftReference(const PreparedScene& prepared, const std::string& samplesPerAxis) {
    return renderFrame(prepared, findTechnique("reference-soft"),
                       {raster::SimdLevel::Scalar, {{"samples-per-axis", samplesPerAxis}}, {}});
}

// Pixels in the penumbra: neither umbra nor fully lit (CompareOptions' thresholds).
size_t penumbraPixels(const Frame& frame) {
    const CompareOptions options;
    size_t count = 0;
    for (size_t k = 0; k < frame.shadow.visibility.size(); ++k) {
        const float v = frame.shadow.visibility[k];
        count += frame.gbuffer.hit[k] && v >= options.umbraThreshold && v <= 1.0f - options.umbraThreshold;
    }
    return count;
}

}  // namespace

TEST_CASE("reference-soft: selectable, and exactly ReferenceVisibility of the disk light") {
    const Technique& soft = findTechnique("reference-soft");
    CHECK(soft.referenceName == "reference-soft");
    CHECK(findTechnique("reference").referenceName == "reference");
    CHECK(findTechnique("none").referenceName == "reference");
    for (const char* name : {"pcss", "vsm", "esm", "evsm", "msm", "multi-sample", "fins", "smoothies", "penumbra-maps"})
        CHECK_MESSAGE(findTechnique(name).referenceName == "reference-soft", name);
    for (const char* name : {"shadow-map", "csm", "izb", "shadow-volume", "planar"})
        CHECK_MESSAGE(findTechnique(name).referenceName == "reference", name);
    const Scene scene = smallSphereBox(96, 60);
    const PreparedScene prepared(scene);
    const WorldGeometry& world = prepared.world();
    REQUIRE(scene.lights[0].type == LightType::Disk);
    const Frame frame = renderSoftReference(prepared, "32");
    const CasterTransmission transmission(prepared.scene(), world);
    const std::vector<float> expected = ReferenceVisibility(world, &transmission).visibility(frame.gbuffer, scene.lights[0]);
    CHECK(frame.shadow.visibility == expected);
    // Soft: some pixels see part of the light, unlike the hard reference.
    size_t fractional = 0;
    for (float v : frame.shadow.visibility) fractional += v > 0.0f && v < 1.0f;
    CHECK(fractional > 0);
    CHECK_THROWS_AS(renderSoftReference(prepared, "0"), std::invalid_argument);
}

TEST_CASE("scoring: each technique against the reference it names, each reference rendered once") {
    Technique softHard = findTechnique("reference");   // hard V, but claims to be soft
    softHard.name = "hard-as-soft";
    softHard.referenceName = "reference-soft";
    SweepOptions options;
    options.scene = "sphere-box";
    options.overrides = imageSize(96, 60);
    options.techniques = {&findTechnique("reference"), &findTechnique("reference-soft"), &softHard};
    options.threads = {1};
    options.warmupRuns = 0;
    options.runs = 1;
    const SweepResults results = runSweep(options);
    REQUIRE(results.rows.size() == 3);
    CHECK(results.rows[0].reference == "reference");
    CHECK(results.rows[0].errors.rms == 0.0);
    CHECK(results.rows[1].reference == "reference-soft");
    CHECK(results.rows[1].errors.rms == 0.0);
    CHECK(results.rows[2].reference == "reference-soft");
    CHECK(results.rows[2].errors.rms > 0.0);   // hard edges against the soft reference
    CHECK(formatSweepCsv(results).find(",reference-soft") != std::string::npos);

    // One reference for all: the hard reference is now wrong against the soft one.
    options.reference = "reference-soft";
    options.techniques = {&findTechnique("reference")};
    const SweepResults overridden = runSweep(options);
    CHECK(overridden.rows[0].reference == "reference-soft");
    CHECK(overridden.rows[0].errors.rms == results.rows[2].errors.rms);
    options.reference = "reference-sfot";
    CHECK_THROWS_WITH_AS(runSweep(options), doctest::Contains("unknown technique"), std::invalid_argument);
}

TEST_CASE("--light-radius: a larger disk widens the penumbra, monotonically") {
    Scene scene = smallSphereBox(320, 200);
    PreparedScene prepared(scene);
    size_t previous = 0;
    for (float radius : {0.125f, 0.25f, 0.5f, 1.0f}) {
        CAPTURE(radius);
        applyOverrides(scene, lightRadius(radius));
        prepared.setLights(scene.lights);
        CHECK(scene.lights[0].radius == radius);
        const size_t band = penumbraPixels(renderSoftReference(prepared, "8"));
        CHECK(band > previous + previous / 4);   // the band is at least 25% wider each time
        previous = band;
    }
}

TEST_CASE("--light-radius: only a disk, only > 0") {
    Scene disk = loadScene("sphere-box");
    for (float bad : {0.0f, -1.0f, NAN, INFINITY}) {
        CAPTURE(bad);
        CHECK_THROWS_WITH_AS(applyOverrides(disk, lightRadius(bad)), doctest::Contains("must be a finite number > 0"),
                             std::invalid_argument);
    }
    Scene sun = loadScene(builtinSceneDir() + "/hard/sun.json");
    CHECK_THROWS_WITH_AS(applyOverrides(sun, lightRadius(1.0f)), doctest::Contains("not a disk"), std::invalid_argument);
    Scene point = loadScene(builtinSceneDir() + "/hard/thin-occluder.json");
    CHECK_THROWS_WITH_AS(applyOverrides(point, lightRadius(1.0f)), doctest::Contains("not a disk"), std::invalid_argument);
}
