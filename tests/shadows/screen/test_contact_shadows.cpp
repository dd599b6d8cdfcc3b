// contact-shadows (RTR 7.10) against the exact hard reference: on box-contact it restores
// the contact shadow that the shadow map's bias loses; the buffer's depth under a sample is
// the ground plane's, analytically; a plane never shadows itself; its known failure (a
// caster off screen casts no march shadow) is asserted; its bytes, and the march kernel's,
// are the same for every thread count and SIMD level; and the plotted march is the mask's.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "raster/thread_count.h"
#include "shading/lights.h"
#include "shadows/screen/march_plot.h"
#include "shadows/screen/screen_march.h"
#include "tests/scratch_directory.h"
#include "tests/shadows/shadow_test_support.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

// RMS of V against the reference over the hit pixels, optionally only those `inside` picks.
template <class Inside>
double rms(const HardScene& s, const std::vector<float>& v, Inside inside) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t k = 0; k < v.size(); ++k) {
        if (!s.gbuffer.hit[k] || !inside(glm::dvec3(s.gbuffer.position[k]))) continue;
        const double e = double(v[k]) - double(s.reference[k]);
        sum += e * e, ++n;
    }
    REQUIRE(n > 0);
    return std::sqrt(sum / double(n));
}

double rms(const HardScene& s, const std::vector<float>& v) {
    return rms(s, v, [](const glm::dvec3&) { return true; });
}

// The ground within 10 cm of box-contact's box (its footprint is [-0.3, 0.3]^2 in x, z).
bool nearContact(const glm::dvec3& P) {
    const double dx = std::max(std::abs(P.x) - 0.3, 0.0), dz = std::max(std::abs(P.z) - 0.3, 0.0);
    return P.y < 1e-4 && (dx > 0.0 || dz > 0.0) && std::hypot(dx, dz) < 0.1;
}

// box-contact seen from 0.5 m above the ground beyond the box's shadow, looking down: a
// view of the ground alone, the box out of it.
Scene groundOnlyView(int width, int height) {
    Scene scene = loadScene(hardCase("box-contact"));
    scene.camera.eye = {-0.8f, 0.5f, -0.05f};
    scene.camera.target = {-0.75f, 0.0f, -0.05f};
    scene.camera.width = width, scene.camera.height = height;
    return scene;
}

}  // namespace

TEST_CASE("contact-shadows on box-contact: the shadow map leaks at the contact, the march restores it") {
    const HardScene s(hardCase("box-contact"));
    const std::vector<float> map = s.run("shadow-map").visibility;
    const ShadowOutputs contact = s.run("contact-shadows");
    const Misclassified mapErrors = misclassified(s.gbuffer, s.reference, s.light(), map);
    const Misclassified contactErrors = misclassified(s.gbuffer, s.reference, s.light(), contact.visibility);
    // (INFO prints lazily: every figure it shows is computed first.)
    const double mapNear = rms(s, map, nearContact), contactNear = rms(s, contact.visibility, nearContact);
    const double mapRms = rms(s, map), contactRms = rms(s, contact.visibility);
    INFO("shadow-map: " << mapErrors.falseLight << " false light, " << mapErrors.falseShadow << " false shadow, RMS "
                        << mapRms << ", near the contact " << mapNear);
    INFO("contact-shadows: " << contactErrors.falseLight << " false light, " << contactErrors.falseShadow
                             << " false shadow, RMS " << contactRms << ", near the contact " << contactNear);
    // The case holds what it says: the map at its defaults leaks a strip of light from the
    // contact on (and farther along the shadow's edge, beyond the march's reach).
    CHECK(mapErrors.falseLight > 5000);
    CHECK(mapNear > 0.25);
    // The march finds the box there: a quarter of the map's error near the contact at most;
    // over the whole image, where the strip goes on beyond the march, a quarter fewer leaks.
    CHECK(contactNear < 0.25 * mapNear);
    CHECK(contactErrors.falseLight < 0.75 * double(mapErrors.falseLight));
    // It adds no false shadow to the map's (a plane never shadows itself through its own
    // pixels, nor past a silhouette), and the whole image is within its bound.
    CHECK(contactErrors.falseShadow == mapErrors.falseShadow);
    CHECK(contactRms < 0.18);
    CHECK(stat(contact, "restored_pixels") > 2000);
}

TEST_CASE("contact-shadows known failure: a caster off screen casts no march shadow, the shadow map sees it") {
    // box-contact's camera turned to look almost straight down at the far end of the box's
    // shadow (which reaches x = -0.87 m): the box itself is out of the view.
    const HardScene s(groundOnlyView(640, 400));
    size_t shadowed = 0;
    for (size_t k = 0; k < s.gbuffer.pixelCount(); ++k) {
        REQUIRE((!s.gbuffer.hit[k] || std::abs(s.gbuffer.position[k].y) < 1e-4f));   // only ground on screen
        shadowed += s.gbuffer.hit[k] && s.reference[k] == 0.0f;
    }
    REQUIRE(shadowed > 10000);
    const Misclassified alone =
        misclassified(s.gbuffer, s.reference, s.light(), s.run("contact-shadows", {{"shadow-map", "off"}}).visibility);
    const Misclassified withMap =
        misclassified(s.gbuffer, s.reference, s.light(), s.run("contact-shadows").visibility);
    INFO(shadowed << " shadowed pixels; the march alone lights " << alone.falseLight << ", with the map "
                  << withMap.falseLight);
    CHECK(alone.falseLight == shadowed);   // the march finds nothing at all
    CHECK(alone.falseShadow == 0);
    CHECK(withMap.count < shadowed / 100);
}

TEST_CASE("contact-shadows: the march mask alone, and a plane never shadows itself") {
    // Only the ground in view (the off-screen case's camera): no sample of any march lies
    // behind the ground's plane, at any step count.
    const HardScene s(groundOnlyView(160, 100));
    for (int steps : {1, 16, 200}) {
        const ScreenMarch march(s.gbuffer, s.scene.camera, s.light(), {0.5f, steps, 0.05f});
        const ScreenMarch::Mask mask = march.mask(raster::bestSimdLevel());
        CHECK(std::count(mask.visibility.begin(), mask.visibility.end(), 0.0f) == 0);
    }
}

TEST_CASE("contact-shadows: the buffer's depth under each sample is the ground's, met by the camera's ray") {
    // Only the ground y = 0 in view: the camera's ray from the eye E through a sample S meets
    // it at the fraction E.y / (E.y - S.y) of the way to S, so the buffer's depth under S is
    // that fraction of S's view depth, whatever pixel S falls in.
    const HardScene s(groundOnlyView(160, 100));
    const ScreenMarch march(s.gbuffer, s.scene.camera, s.light(), {0.5f, 12, 0.05f});
    const glm::dvec3 eye(s.scene.camera.eye);
    int checked = 0;
    for (int j = 5; j < 100; j += 15) {
        for (int i = 7; i < 160; i += 20) {
            for (const MarchSample& sample : marchSamples(march, s.gbuffer, i, j)) {
                if (!std::isfinite(sample.bufferDepth)) continue;   // its own pixel
                const glm::dvec3 S = glm::dvec3(s.gbuffer.position[s.gbuffer.index(i, j)]) +
                                     double(sample.distanceM) * glm::normalize(glm::dvec3(s.light().direction));
                const double expected = double(sample.sampleDepth) * eye.y / (eye.y - S.y);
                INFO("pixel " << i << ", " << j << " at " << sample.distanceM << " m");
                CHECK(sample.bufferDepth == doctest::Approx(expected).epsilon(1e-5));
                CHECK(sample.bufferDepth > sample.sampleDepth);   // the ground lies behind every sample
                ++checked;
            }
        }
    }
    CHECK(checked > 100);
}

TEST_CASE("contact-shadows: the same bytes for 1 and 2 threads and every SIMD level") {
    Scene scene = loadScene(hardCase("box-contact"));
    scene.camera.width = 320, scene.camera.height = 200;
    const HardScene s(std::move(scene));
    const auto run = [&](raster::SimdLevel level) { return s.run("contact-shadows", {}, level).visibility; };
    const std::vector<float> twin = withThreads(1, [&] { return run(raster::SimdLevel::Scalar); });
    CHECK(std::count(twin.begin(), twin.end(), 0.0f) > 1000);
    test::checkSameBytesEverywhere(twin, run);
}

namespace {

// The march mask as one V buffer for checkSameBytesEverywhere: V, then each pixel's end.
std::vector<float> maskBytes(const ScreenMarch::Mask& mask) {
    std::vector<float> out = mask.visibility;
    for (uint8_t end : mask.end) out.push_back(float(end));
    return out;
}

}  // namespace

TEST_CASE("contact-shadows: the march kernel gives the scalar twin's mask and ends at every SIMD level and thread count") {
    // 317 pixels a row: no multiple of any vector's width, so every row has a tail too.
    Scene scene = loadScene(hardCase("box-contact"));
    scene.camera.width = 317, scene.camera.height = 190;
    const HardScene s(std::move(scene));
    for (const MarchSettings& settings : {MarchSettings{}, MarchSettings{0.6f, 40, 0.2f}}) {
        const ScreenMarch march(s.gbuffer, s.scene.camera, s.light(), settings);
        const auto run = [&](raster::SimdLevel level) { return maskBytes(march.mask(level)); };
        const ScreenMarch::Mask twin = withThreads(1, [&] { return march.mask(raster::SimdLevel::Scalar); });
        size_t ends[3] = {0, 0, 0};
        for (uint8_t end : twin.end) ++ends[end];
        INFO(ends[0] << " lit, " << ends[1] << " occluded, " << ends[2] << " left the screen");
        CHECK(ends[size_t(MarchEnd::Occluded)] > 500);
        CHECK(ends[size_t(MarchEnd::LeftScreen)] > 0);
        test::checkSameBytesEverywhere(maskBytes(twin), run);
    }
}

TEST_CASE("contact-shadows: the plotted march is the mask's, step by step") {
    // The mask ends at a pixel's first occluded sample, or where the ray leaves the screen;
    // the plot's samples (the scalar kernel's trace) must say the same at every pixel.
    Scene scene = loadScene(hardCase("box-contact"));
    scene.camera.width = 160, scene.camera.height = 100;
    const HardScene s(std::move(scene));
    const MarchSettings settings{0.4f, 20, 0.1f};
    const ScreenMarch march(s.gbuffer, s.scene.camera, s.light(), settings);
    const ScreenMarch::Mask mask = march.mask(raster::bestSimdLevel());
    const LightReach reaches(s.light());
    size_t occluded = 0, left = 0, mismatches = 0;
    for (size_t k = 0; k < s.gbuffer.pixelCount(); ++k) {
        if (!s.gbuffer.hit[k] || !reaches(s.gbuffer.position[k], s.gbuffer.normal[k])) continue;
        const std::vector<MarchSample> samples = march.samples(k);
        const auto first = std::find_if(samples.begin(), samples.end(), [](const MarchSample& x) { return x.occluded; });
        const MarchEnd expected = first != samples.end()          ? MarchEnd::Occluded
                                  : samples.size() < size_t(settings.steps) ? MarchEnd::LeftScreen
                                                                          : MarchEnd::Lit;
        mismatches += mask.end[k] != uint8_t(expected);
        occluded += expected == MarchEnd::Occluded, left += expected == MarchEnd::LeftScreen;
    }
    INFO(occluded << " occluded, " << left << " left the screen");
    CHECK(occluded > 100);
    CHECK(left > 0);
    CHECK(mismatches == 0);
}

TEST_CASE("contact-shadows: the debug buffers hold the mask and the chosen pixel's march") {
    Scene scene = loadScene(hardCase("box-contact"));
    scene.camera.width = 160, scene.camera.height = 100;
    const HardScene s(std::move(scene));
    const ScratchDirectory dir("contact-shadows-debug");
    s.run("contact-shadows", {}, raster::bestSimdLevel(), dir.path);
    for (const char* file : {"contact-shadows-march-mask.exr", "contact-shadows-march-mask.png",
                             "contact-shadows-march-path.png", "contact-shadows-march.csv",
                             "contact-shadows-march.svg", "contact-shadows-shadow-map/shadow-map-depth.png"}) {
        INFO(file);
        CHECK(std::filesystem::exists(dir.path / file));
    }
    std::ifstream csv(dir.path / "contact-shadows-march.csv");
    std::string line;
    int lines = 0;
    while (std::getline(csv, line)) ++lines;
    CHECK(lines == 1 + 16);   // the header and the default 16 steps
}

TEST_CASE("contact-shadows: bad settings are clear errors") {
    Scene scene = loadScene(hardCase("box-contact"));
    scene.camera.width = 64, scene.camera.height = 40;
    const HardScene s(std::move(scene));
    CHECK_THROWS_WITH_AS(s.run("contact-shadows", {{"plot-x", "64"}}),
                         "contact-shadows: plot-x, plot-y must name a pixel of the image", std::invalid_argument);
    CHECK_THROWS_AS(s.run("contact-shadows", {{"march-steps", "0"}}), std::invalid_argument);
    CHECK_THROWS_AS(s.run("contact-shadows", {{"march-length", "-1"}}), std::invalid_argument);
    CHECK_THROWS_WITH_AS(s.run("contact-shadows", {{"cube", "always"}}), "shadow-map: cube=always needs a point light",
                         std::invalid_argument);
}
