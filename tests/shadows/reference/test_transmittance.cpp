// The reference through casters that are not opaque, against closed forms:
//  (a) k parallel sheets of opacity a between a point light and a receiver pass (1 - a)^k,
//      each sheet counted once (the receivers on the diagonal send their rays through the
//      edge the sheet's two triangles share), and a tinted sheet passes its tint per channel;
//  (b) a slab of constant density sigma passes exp(-sigma d), d the path length inside it,
//      straight down and at a slant;
//  (c) the exact DDA sum through a smoke puff equals a fine numerical integral of the same
//      voxel field;
//  (d) a cut-out card shadows only where its alpha is at least the cutoff;
// and the result is the same bytes for 1 and 2 threads.
#include <doctest/doctest.h>

#include <cmath>

#include "raster/thread_count.h"
#include "scenes/procedural.h"
#include "scenes/procedural_casters.h"
#include "shading/luminance.h"
#include "shadows/reference/reference.h"
#include "shadows/volume_march.h"

using namespace shadowlab;

namespace {

// Receivers on the plane y = 0 facing up: n x n points over [-h, h]^2.
GBuffer groundPoints(int n, double h) {
    GBuffer g;
    g.width = g.height = n;
    const size_t count = g.pixelCount();
    g.hit.assign(count, 1);
    g.normal.assign(count, glm::vec3(0.0f, 1.0f, 0.0f));
    g.shadingNormal = g.normal;
    g.material.assign(count, 0);
    g.triangle.assign(count, 0);
    g.depth.assign(count, 0.5f);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            g.position.push_back(glm::vec3(float(-h + 2.0 * h * i / (n - 1)), 0.0f, float(-h + 2.0 * h * j / (n - 1))));
        }
    }
    return g;
}

// A scene of horizontal square sheets (2 m wide) at the given heights, each with its own
// material, over nothing: the receivers are G-buffer points, not geometry.
Scene sheets(const std::vector<float>& heights, const std::vector<Material>& materials) {
    Scene scene;
    scene.meshes.push_back(makeGrid({2.0f, 2.0f}, {1, 1}));
    scene.materials = materials;
    for (size_t k = 0; k < heights.size(); ++k) {
        MeshInstance sheet{.name = "sheet", .mesh = 0, .material = uint32_t(k), .worldFromObject = glm::mat4(1.0f)};
        sheet.worldFromObject[3] = glm::vec4(0.0f, heights[k], 0.0f, 1.0f);
        scene.instances.push_back(sheet);
    }
    return scene;
}

Material translucent(float opacity, glm::vec3 tint = glm::vec3(1.0f)) {
    return {.name = "sheet", .opacity = opacity, .transmittance = tint};
}

const Light kLightAbove{.type = LightType::Point, .position = {0.0f, 10.0f, 0.0f}};

ReferenceVisibility::Passed passedThrough(const Scene& scene, const GBuffer& g, const Light& light = kLightAbove) {
    const WorldGeometry world = flatten(scene);
    const CasterTransmission transmission(scene, world);
    return ReferenceVisibility(world, &transmission).passed(g, light);
}

}  // namespace

TEST_CASE("k sheets of opacity a pass (1 - a)^k, each counted once") {
    const GBuffer g = groundPoints(9, 0.5);   // under every sheet
    for (int k = 1; k <= 4; ++k) {
        const float a = 0.3f;
        const std::vector<float> heights = {1.0f, 1.5f, 2.0f, 2.5f};
        const Scene scene = sheets({heights.begin(), heights.begin() + k}, std::vector<Material>(size_t(k), translucent(a)));
        const ReferenceVisibility::Passed passed = passedThrough(scene, g);
        const double expected = std::pow(1.0 - a, k);
        for (float v : passed.visibility) CHECK(v == doctest::Approx(expected).epsilon(1e-5));
    }
}

TEST_CASE("a tinted sheet passes its tint per channel and V is the luminance") {
    const glm::vec3 tint(0.2f, 0.8f, 0.3f);
    const Scene scene = sheets({1.0f}, {translucent(0.5f, tint)});
    const ReferenceVisibility::Passed passed = passedThrough(scene, groundPoints(5, 0.5));
    REQUIRE(passed.coloured.size() == passed.visibility.size());
    for (size_t k = 0; k < passed.coloured.size(); ++k) {
        CHECK(passed.coloured[k].r == doctest::Approx(0.1));
        CHECK(passed.coloured[k].g == doctest::Approx(0.4));
        CHECK(passed.coloured[k].b == doctest::Approx(0.15));
        CHECK(passed.visibility[k] == luminance(passed.coloured[k]));
    }
}

TEST_CASE("an opaque sheet under a translucent one blocks the light") {
    const Scene scene = sheets({1.0f, 2.0f}, {Material{.name = "opaque"}, translucent(0.4f)});
    for (float v : passedThrough(scene, groundPoints(5, 0.5)).visibility) CHECK(v == 0.0f);
}

TEST_CASE("a slab of constant density passes exp of minus sigma times the path length") {
    Scene scene = sheets({}, {});
    scene.meshes.clear();
    const float sigma = 0.7f;
    scene.volumes.push_back(makeConstantVolume({-20.0f, 1.0f, -20.0f}, {20.0f, 2.0f, 20.0f}, sigma));
    const GBuffer g = groundPoints(7, 3.0);
    const ReferenceVisibility::Passed passed = passedThrough(scene, g);
    for (size_t k = 0; k < g.position.size(); ++k) {
        // The ray from P to the light at height 10 crosses the 1 m slab over a length 1 / cos.
        const glm::dvec3 toLight = glm::dvec3(kLightAbove.position) - glm::dvec3(g.position[k]);
        const double pathLength = glm::length(toLight) / toLight.y;
        CHECK(passed.visibility[k] == doctest::Approx(std::exp(-sigma * pathLength)).epsilon(1e-5));
    }
    // A directional light: the ray runs to infinity, through the whole slab once.
    const Light sun{.type = LightType::Directional, .direction = glm::normalize(glm::vec3(0.6f, 0.8f, 0.0f))};
    for (float v : passedThrough(scene, g, sun).visibility) CHECK(v == doctest::Approx(std::exp(-sigma / 0.8)).epsilon(1e-5));
}

TEST_CASE("the DDA's optical depth through a smoke puff equals a fine numerical integral") {
    const DensityVolume puff = makeSmokePuff({-1.0f, 0.5f, -1.0f}, {1.0f, 2.5f, 1.0f}, 16, 3.0f, 7);
    const glm::dvec3 a(-1.7, 0.1, -0.4), b(1.3, 2.9, 0.8);
    const std::vector<DensityVolume> volumes{puff};
    const double exact = opticalDepth(volumes, a, b);
    // Midpoint rule over the same piecewise-constant field: the voxel holding each point.
    const int steps = 200000;
    double sum = 0.0;
    const glm::dvec3 voxel = glm::dvec3(puff.max - puff.min) / glm::dvec3(puff.resolution);
    for (int s = 0; s < steps; ++s) {
        const glm::dvec3 p = a + (s + 0.5) / steps * (b - a);
        const glm::dvec3 q = (p - glm::dvec3(puff.min)) / voxel;
        if (glm::any(glm::lessThan(q, glm::dvec3(0.0))) || glm::any(glm::greaterThanEqual(q, glm::dvec3(puff.resolution))))
            continue;
        sum += puff.at(int(q.x), int(q.y), int(q.z));
    }
    const double numeric = sum * glm::length(b - a) / steps;
    REQUIRE(exact > 0.5);   // the segment crosses dense smoke
    CHECK(exact == doctest::Approx(numeric).epsilon(1e-3));
}

TEST_CASE("a cut-out card shadows only where its alpha reaches the cutoff") {
    // The left half of the texture (u < 0.5) is a hole: alpha 0.2 against the cutoff 0.5.
    Scene scene = sheets({1.0f}, {Material{.name = "leaf", .alphaTexture = 0, .alphaCutoff = 0.5f}});
    scene.alphaTextures.push_back({.source = "test", .width = 4, .height = 2, .alpha = {0.2f, 0.2f, 0.9f, 0.9f, 0.2f, 0.2f, 0.9f, 0.9f}, .wrap = {}});
    const GBuffer g = groundPoints(9, 0.9);
    const ReferenceVisibility::Passed passed = passedThrough(scene, g);
    for (size_t k = 0; k < g.position.size(); ++k) {
        // The grid's u runs along +x; a point's shadow lands 1/10 closer to the centre.
        const float xOnCard = g.position[k].x * 0.9f;
        if (std::abs(xOnCard) < 0.02f) continue;
        INFO("x = " << g.position[k].x);
        CHECK(passed.visibility[k] == (xOnCard < 0.0f ? 1.0f : 0.0f));
    }
}

TEST_CASE("the reference through casters that are not opaque is the same bytes on 1 and 2 threads") {
    Scene scene = sheets({1.0f, 1.2f}, {translucent(0.3f, {0.9f, 0.5f, 0.2f}), translucent(0.6f)});
    scene.volumes.push_back(makeSmokePuff({-1.0f, 1.5f, -1.0f}, {1.0f, 3.0f, 1.0f}, 12, 2.0f, 3));
    const GBuffer g = groundPoints(48, 1.5);
    const Light disk{.type = LightType::Disk, .position = {0.3f, 6.0f, 0.0f}, .direction = {0.0f, -1.0f, 0.0f}, .radius = 1.0f};
    const ReferenceVisibility::Passed one = withThreads(1, [&] { return passedThrough(scene, g, disk); });
    const ReferenceVisibility::Passed two = withThreads(2, [&] { return passedThrough(scene, g, disk); });
    CHECK(one.visibility == two.visibility);
    CHECK(one.coloured == two.coloured);
}
