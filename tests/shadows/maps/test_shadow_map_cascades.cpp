// csm: split schemes (RTR eq. 7.5), texel snapping under a sub-texel camera move, and
// LiSPSM's warp, including the dueling-frusta case where it degenerates to uniform.
#include <doctest/doctest.h>

#include <cmath>

#include "shadows/maps/csm.h"
#include "shadows/maps/shadow_map_settings.h"
#include "tests/shadows/maps/shadow_map_test_util.h"

using namespace shadowlab;
using namespace shadowlab::test;

TEST_CASE("cascade splits: logarithmic (RTR eq. 7.5), uniform and the practical blend") {
    const std::vector<double> log = cascadeSplits(1.0, 1000.0, 3, SplitScheme::Logarithmic, 0.0);
    CHECK(log[1] == doctest::Approx(10.0));   // RTR's example: r = cbrt(1000 / 1) = 10
    CHECK(log[2] == doctest::Approx(100.0));
    const std::vector<double> uniform = cascadeSplits(1.0, 1000.0, 3, SplitScheme::Uniform, 1.0);
    CHECK(uniform[1] == doctest::Approx(334.0));
    const std::vector<double> practical = cascadeSplits(1.0, 1000.0, 3, SplitScheme::Practical, 0.25);
    CHECK(practical[1] == doctest::Approx(0.25 * 10.0 + 0.75 * 334.0));
    CHECK(practical.front() == 1.0);
    CHECK(practical.back() == 1000.0);
}

namespace {

struct CascadeFrame {
    Scene scene;
    GBuffer g;
    CascadedMaps maps;
};

CascadeFrame cascadeFrame(const WorldGeometry& world, glm::vec3 move, bool snap, bool sampleBounds) {
    CascadeFrame f{sunSphereBox(320, 200), {}, {}};
    f.scene.camera.zNear = 0.5f, f.scene.camera.zFar = 30.0f;
    f.scene.camera.eye += move, f.scene.camera.target += move;
    f.g = renderGBuffer(world, f.scene.camera, raster::bestSimdLevel());
    CascadeSettings cs;
    cs.sampleBounds = sampleBounds;
    cs.snap = snap;
    cs.resolution = 1024;
    DepthMapSettings ds;
    ds.size = 1024;
    ds.offset = polygonOffsetFor(BiasSettings{});   // the default bias: slope-scaled
    f.maps = renderCascades(f.scene.lights[0], f.scene.camera, f.g, world, cs, ds, raster::bestSimdLevel());
    return f;
}

// The largest distance from a whole number of texels between the two frames' texel
// coordinates of the same world points, over the cascades both have.
double gridMisalignment(const CascadeFrame& a, const CascadeFrame& b) {
    double worst = 0.0;
    for (size_t k = 0; k < a.maps.maps.size(); ++k) {
        if (!a.maps.maps[k].size || !b.maps.maps[k].size) continue;
        for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(3, 1, -2), glm::dvec3(-5, 0.5, 4)}) {
            const glm::dvec4 ta = a.maps.maps[k].texelFromWorld * glm::dvec4(p, 1.0);
            const glm::dvec4 tb = b.maps.maps[k].texelFromWorld * glm::dvec4(p, 1.0);
            for (int c = 0; c < 2; ++c) worst = std::max(worst, std::abs(tb[c] - ta[c] - std::round(tb[c] - ta[c])));
        }
    }
    return worst;
}

// Receivers of frame a classified with each frame's maps; the count that differ where
// both frames put the point in the same cascade.
int classificationChanges(const CascadeFrame& a, const CascadeFrame& b) {
    const Light& sun = a.scene.lights[0];
    const PcfKernel nearest = makePcfKernel({FilterKind::Nearest});
    const ShadowLookup va = lookUpShadows(a.g, a.scene.camera, sun, a.maps.maps, CascadeSelector{a.maps, a.scene.camera}, {}, nearest,
                                          raster::bestSimdLevel());
    const ShadowLookup vb = lookUpShadows(a.g, a.scene.camera, sun, b.maps.maps, CascadeSelector{b.maps, b.scene.camera}, {}, nearest,
                                          raster::bestSimdLevel());
    int changes = 0;
    for (size_t k = 0; k < va.visibility.size(); ++k) {
        changes += va.mapIndex[k] >= 0 && va.mapIndex[k] == vb.mapIndex[k] && va.visibility[k] != vb.visibility[k];
    }
    return changes;
}

}  // namespace

TEST_CASE("csm: texel snapping keeps the texel grid and the shadows of fixed points under a sub-texel camera move") {
    const Scene scene = sunSphereBox(320, 200);
    const WorldGeometry world = flatten(scene);
    // Split distances from the camera's planes, and from the receivers (the default).
    for (const bool sampleBounds : {false, true}) {
        INFO((sampleBounds ? "sample bounds" : "camera bounds"));
        const CascadeFrame a = cascadeFrame(world, glm::vec3(0.0f), true, sampleBounds);
        // A third of the nearest used cascade's texel, obliquely.
        size_t first = 0;
        while (first < a.maps.maps.size() && a.maps.maps[first].size == 0) ++first;
        REQUIRE(first + 1 < a.maps.maps.size());   // at least two cascades hold receivers
        const double texel = 2.0 / (a.maps.maps[first].view.clipFromView[0][0] * a.maps.maps[first].size);
        const glm::vec3 move = float(texel / 3.0) * glm::normalize(glm::vec3(1.0f, 0.3f, -0.7f));
        const CascadeFrame b = cascadeFrame(world, move, true, sampleBounds);
        CHECK(gridMisalignment(a, b) < 1e-3);
        CHECK(classificationChanges(a, b) == 0);
        // Without snapping the grid slides with the camera and edge points flip: the test can fail.
        const CascadeFrame c = cascadeFrame(world, glm::vec3(0.0f), false, sampleBounds);
        const CascadeFrame d = cascadeFrame(world, move, false, sampleBounds);
        CHECK(gridMisalignment(c, d) > 0.05);
        CHECK(classificationChanges(c, d) > 0);
    }
}

TEST_CASE("csm: sample bounds put the splits around the receivers, on the 2^(1/8) ladder") {
    Scene scene = sunSphereBox(320, 200);
    scene.camera.zNear = 0.1f, scene.camera.zFar = 1000.0f;   // far beyond every receiver
    const WorldGeometry world = flatten(scene);
    const GBuffer g = renderGBuffer(world, scene.camera, raster::bestSimdLevel());
    double nearest = INFINITY, farthest = 0.0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const double depth = viewDepth(scene.camera, glm::dvec3(g.position[k]));
        nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
    }
    CascadeSettings settings;   // sample bounds, the default
    const std::vector<Cascade> cascades = fitCascades(scene.lights[0], scene.camera, g, world, settings, raster::bestSimdLevel());
    const double n = cascades.front().nearDistance, f = cascades.back().farDistance;
    const double step = std::exp2(1.0 / 8.0);
    CHECK(n <= nearest);
    CHECK(n * step > nearest);
    CHECK(f >= farthest);
    CHECK(f < farthest * step);
    for (const double bound : {n, f}) CHECK(std::abs(std::log2(bound) * 8.0 - std::round(std::log2(bound) * 8.0)) < 1e-9);
    // Every cascade has receivers: none is wasted on empty depth, as camera bounds would.
    for (const Cascade& c : cascades) CHECK(c.hasReceivers);
    settings.sampleBounds = false;
    const std::vector<Cascade> camera = fitCascades(scene.lights[0], scene.camera, g, world, settings, raster::bestSimdLevel());
    CHECK_FALSE(camera.back().hasReceivers);
}

TEST_CASE("csm, defaults, sun over sphere-box: acne below 0.05% of lit pixels, leaks only at the boundary") {
    const Scene scene = sunSphereBox(640, 400);
    const PreparedScene prepared(scene);
    const Frame reference = frameOf(prepared, "reference");
    const Frame csm = frameOf(prepared, "csm");
    const BandedErrors m = bandedErrors(reference, csm, leakBandPixels(statOf(csm, "median_texels_per_pixel")));
    MESSAGE("csm: acne " << m.falseShadow << " of " << m.lit << ", leaks " << m.falseLight << " of " << m.shadowed);
    CHECK(m.falseShadow < 0.0005 * m.lit);
    CHECK(m.falseLightOffBoundary == 0);
    CHECK(statOf(csm, "cascades_count") == 4);
}

TEST_CASE("LiSPSM: more texels near the viewer, and uniform again when the light is along the view (dueling frusta)") {
    Scene scene = sunSphereBox(320, 200);
    PreparedScene prepared(scene);
    const Frame reference = frameOf(prepared, "reference");
    const Frame uniform = frameOf(prepared, "shadow-map", {{"resolution", "1024"}});
    const Frame warped = frameOf(prepared, "shadow-map", {{"resolution", "1024"}, {"warp", "lispsm"}});
    MESSAGE("texels per pixel: uniform " << statOf(uniform, "median_texels_per_pixel") << ", lispsm "
                                         << statOf(warped, "median_texels_per_pixel") << ", n_opt " << statOf(warped, "lispsm_n_opt_m"));
    CHECK(statOf(warped, "median_texels_per_pixel") > 1.5 * statOf(uniform, "median_texels_per_pixel"));
    const BandedErrors m = bandedErrors(reference, warped, leakBandPixels(statOf(warped, "median_texels_per_pixel")));
    CHECK(m.falseShadow < 0.0005 * m.lit);
    CHECK(m.falseLightOffBoundary == 0);
    // Dueling frusta: the sun straight behind the viewer, shining along the view direction
    // (tilted 0.5 degrees): sin(gamma) ~ 0.009, n_opt is huge and the warp is all but uniform.
    const glm::vec3 view = glm::normalize(scene.camera.target - scene.camera.eye);
    const glm::vec3 side = glm::normalize(glm::cross(view, glm::vec3(0, 1, 0)));
    scene.lights[0].direction = glm::normalize(-view + 0.0087f * side);
    prepared.setLights(scene.lights);
    const Frame dueling = frameOf(prepared, "shadow-map", {{"resolution", "1024"}, {"warp", "lispsm"}});
    const Frame dueling0 = frameOf(prepared, "shadow-map", {{"resolution", "1024"}});
    MESSAGE("dueling: texels per pixel uniform " << statOf(dueling0, "median_texels_per_pixel") << ", lispsm "
                                                 << statOf(dueling, "median_texels_per_pixel") << ", n_opt "
                                                 << statOf(dueling, "lispsm_n_opt_m"));
    CHECK(statOf(dueling, "lispsm_n_opt_m") > 50.0 * statOf(warped, "lispsm_n_opt_m"));
    CHECK(statOf(dueling, "median_texels_per_pixel") ==
          doctest::Approx(statOf(dueling0, "median_texels_per_pixel")).epsilon(0.1));
}
