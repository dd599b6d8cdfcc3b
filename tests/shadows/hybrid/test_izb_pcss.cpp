// izb-pcss (RTR 7.9, Figure 7.31; Story and Wyman's hybrid) against the exact soft
// reference on branch-over-crate: within its RMS bound and better than PCSS, the exact hard
// shadow wherever it chose the hard part, which beats PCSS there; the blend weight follows
// the occluder distance; the same bytes for every thread count and SIMD level; and a point
// light is a clear error.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "raster/thread_count.h"
#include "shading/lights.h"
#include "shadows/filtered/pcss.h"
#include "shadows/hybrid/izb_pcss.h"
#include "tests/scratch_directory.h"
#include "tests/shadows/shadow_test_support.h"
#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

std::string branchOverCrate() { return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/soft/branch-over-crate.json"; }

// RMS against the reference over the hit pixels `pick` chooses.
template <class Pick>
double rmsWhere(const SoftScene& s, const std::vector<float>& v, Pick pick) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t k = 0; k < v.size(); ++k) {
        if (!s.gbuffer.hit[k] || !pick(k)) continue;
        const double e = double(v[k]) - double(s.reference[k]);
        sum += e * e, ++n;
    }
    REQUIRE(n > 0);
    return std::sqrt(sum / double(n));
}

const SoftScene& scene() {
    static const SoftScene s(smallScene(branchOverCrate(), 320, 200));
    return s;
}

// The hybrid's stages run one by one at the defaults: the PCSS pass and the blend weight.
struct Parts {
    PcssBuffers pcss;
    std::vector<float> weight;
    explicit Parts(const SoftScene& s) {
        const TechniqueParams defaults("pcss", pcssSettingsTable().specs(), {});
        const ShadowInputs in{.prepared = s.prepared,
                              .gbuffer = s.gbuffer,
                              .light = s.scene.lights[0],
                              .simd = raster::bestSimdLevel(),
                              .params = defaults};
        const PcssSettings settings = pcssSettingsTable().read(defaults);
        const SoftShadowMap soft = renderPcssMap(in, settings.resolution);
        pcss = pcssPerPixel(in, soft, settings, std::nullopt);
        weight = blendWeights(s.gbuffer, soft, pcss.blockerDistance, BlendDistances{});
    }
};

}  // namespace

TEST_CASE("izb-pcss on branch-over-crate: within its bound, better than PCSS, exact where the occluder is close") {
    const SoftScene& s = scene();
    const std::vector<float> hybrid = s.run("izb-pcss").visibility, pcss = s.run("pcss").visibility,
                             izb = s.run("izb").visibility;
    const Parts parts(s);
    REQUIRE(parts.pcss.visibility == pcss);
    const double hybridRms = s.rms(hybrid), pcssRms = s.rms(pcss), izbRms = s.rms(izb);
    INFO("RMS: izb-pcss " << hybridRms << ", pcss " << pcssRms << ", izb " << izbRms);
    CHECK(hybridRms < 0.025);
    CHECK(hybridRms < pcssRms);
    CHECK(hybridRms < 0.25 * izbRms);
    // Where it keeps the hard shadow (w = 0) on a surface facing the light, and some V is
    // below 1: there the occluder is within centimetres, as at the crate's foot, where PCSS,
    // comparing on the receiver's plane, takes the ground beside the crate's face for a
    // blocker of the face and darkens it.
    const LightReach reaches(pointLightFor(s.scene.lights[0]));
    const auto hardPart = [&](size_t k) {
        return parts.weight[k] == 0.0f && reaches(s.gbuffer.position[k], s.gbuffer.normal[k]) &&
               std::min({s.reference[k], izb[k], pcss[k]}) < 1.0f;
    };
    const double hybridHard = rmsWhere(s, hybrid, hardPart), pcssHard = rmsWhere(s, pcss, hardPart);
    INFO("where the occluder is close: izb-pcss " << hybridHard << ", pcss " << pcssHard);
    CHECK(hybridHard < 0.5 * pcssHard);
    for (size_t k = 0; k < hybrid.size(); ++k) {
        if (s.gbuffer.hit[k] && parts.weight[k] == 0.0f) REQUIRE(hybrid[k] == izb[k]);
    }
}

TEST_CASE("izb-pcss: the blend weight follows the occluder distance, and the debug buffers show the parts") {
    const SoftScene& s = scene();
    const ScratchDirectory dir("izb-pcss-debug");
    const ShadowOutputs out = s.run("izb-pcss", {}, dir.path);
    for (const char* file : {"izb-pcss-blend-weight.exr", "izb-pcss-izb.png", "izb-pcss-pcss.png"}) {
        INFO(file);
        CHECK(std::filesystem::exists(dir.path / file));
    }
    const std::vector<float> izb = s.run("izb").visibility;
    const Parts parts(s);
    const std::vector<float>& w = parts.weight;
    size_t hard = 0, blended = 0, soft = 0;
    for (size_t k = 0; k < w.size(); ++k) {
        if (!s.gbuffer.hit[k]) continue;
        REQUIRE(w[k] >= 0.0f);
        REQUIRE(w[k] <= 1.0f);
        const float p = parts.pcss.visibility[k];
        if (w[k] == 0.0f) {
            ++hard;
            REQUIRE(out.visibility[k] == izb[k]);
        } else if (w[k] == 1.0f) {
            ++soft;
            REQUIRE(out.visibility[k] == p);
        } else {
            ++blended;
            REQUIRE(out.visibility[k] >= std::min(izb[k], p));
            REQUIRE(out.visibility[k] <= std::max(izb[k], p));
        }
        // No blocker found: the weight is the hard shadow's.
        if (parts.pcss.blockerDistance[k] == 0.0f) REQUIRE(w[k] == 0.0f);
    }
    INFO(hard << " hard, " << blended << " blended, " << soft << " soft pixels");
    CHECK(blended > 0);
    CHECK(soft > 1000);   // the branch's shadow, 3 m from the ground, and the crate's from its top edge
    CHECK(stat(out, "blended_pixels") == double(blended));
    CHECK(stat(out, "soft_pixels") == double(soft));
}

TEST_CASE("izb-pcss: the same bytes for 1 and 2 threads and every SIMD level") {
    Scene small = smallScene(branchOverCrate(), 160, 100);
    const PreparedScene prepared(small);
    const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::SimdLevel::Scalar);
    const Technique& t = findTechnique("izb-pcss");
    const TechniqueParams params(t.name, t.params, {});
    const auto run = [&](raster::SimdLevel level) {
        return t.run({.prepared = prepared,
                      .gbuffer = g,
                      .light = prepared.scene().lights[0],
                      .simd = level,
                      .params = params}).visibility;
    };
    const std::vector<float> twin = withThreads(1, [&] { return run(raster::SimdLevel::Scalar); });
    CHECK(std::count_if(twin.begin(), twin.end(), [](float v) { return v > 0.0f && v < 1.0f; }) > 100);
    test::checkSameBytesEverywhere(twin, run);
}

TEST_CASE("izb-pcss: a point light and crossed blend distances are clear errors") {
    Scene point = smallScene(branchOverCrate(), 64, 40);
    point.lights[0].type = LightType::Point;
    const PreparedScene prepared(point);
    const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
    const Technique& t = findTechnique("izb-pcss");
    const auto run = [&](const std::map<std::string, std::string>& given) {
        const TechniqueParams params(t.name, t.params, given);
        return t.run({.prepared = prepared,
                      .gbuffer = g,
                      .light = prepared.scene().lights[0],
                      .simd = raster::bestSimdLevel(),
                      .params = params});
    };
    CHECK_THROWS_WITH_AS(run({}), "izb-pcss: needs an area light (disk or rectangle)", std::invalid_argument);
    CHECK_THROWS_WITH_AS(run({{"hard-below", "0.5"}, {"soft-above", "0.2"}}),
                         "izb-pcss: hard-below must be less than soft-above", std::invalid_argument);
}
