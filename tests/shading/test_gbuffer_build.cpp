// buildGBuffer on hand-made triangles: P on the triangle's plane and on the pixel ray,
// N unit and facing the camera, background cleared.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "scenes/camera.h"
#include "shading/gbuffer_build.h"

using namespace shadowlab;

namespace {

Camera smallCamera() {
    Camera c;
    c.eye = {0.3f, 0.2f, 5.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.fovyDeg = 60.0f;
    c.width = 9;
    c.height = 7;
    return c;
}

// Triangle 0 is wound counter-clockwise as seen from the camera, triangle 1 clockwise,
// so one normal must be flipped and the other kept.
WorldGeometry twoTriangles() {
    WorldGeometry w;
    w.positions = {{-3.0f, -3.0f, 0.5f}, {3.0f, -2.0f, -0.5f}, {0.0f, 3.0f, 0.0f},
                   {2.0f, -1.0f, -1.0f}, {2.0f, 2.0f, 0.0f},  {-2.0f, 2.0f, -2.0f}};
    w.triangles = {{0, 1, 2}, {3, 5, 4}};
    w.triangleMaterial = {7, 3};
    w.triangleInstance = {0, 1};
    return w;
}

glm::dvec3 vertex(const WorldGeometry& w, uint32_t t, int k) {
    return glm::dvec3(w.positions[w.triangles[t][k]]);
}

}  // namespace

TEST_CASE("buildGBuffer puts P on the triangle plane and the pixel ray, N unit and camera-facing") {
    const Camera camera = smallCamera();
    const WorldGeometry world = twoTriangles();
    const size_t n = size_t(camera.width) * size_t(camera.height);
    std::vector<uint32_t> visible(n);
    std::vector<float> depth(n);
    for (int j = 0; j < camera.height; ++j) {
        for (int i = 0; i < camera.width; ++i) {
            const size_t k = size_t(j) * size_t(camera.width) + size_t(i);
            visible[k] = i == 0 ? kNoTriangle : uint32_t(j % 2);
            depth[k] = 0.25f + 0.001f * float(k);
        }
    }
    const GBuffer g = buildGBuffer(world, camera, visible, depth);
    REQUIRE(g.width == camera.width);
    REQUIRE(g.height == camera.height);

    int flipped = 0, kept = 0;
    for (int j = 0; j < g.height; ++j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            CAPTURE(i);
            CAPTURE(j);
            if (visible[k] == kNoTriangle) {
                CHECK(g.hit[k] == 0);
                CHECK(g.position[k] == glm::vec3(0.0f));
                CHECK(g.normal[k] == glm::vec3(0.0f));
                CHECK(g.shadingNormal[k] == glm::vec3(0.0f));
                CHECK(g.depth[k] == 1.0f);
                CHECK(g.triangle[k] == kNoTriangle);
                continue;
            }
            const uint32_t t = visible[k];
            const glm::dvec3 v0 = vertex(world, t, 0), v1 = vertex(world, t, 1), v2 = vertex(world, t, 2);
            const glm::dvec3 planeNormal = glm::normalize(glm::cross(v1 - v0, v2 - v0));
            const glm::dvec3 P(g.position[k]), N(g.normal[k]);
            const RayD ray = PixelRays(camera)(i, j);
            // P is the exact point rounded to float: within sqrt(3) * 2^-24 * |P| ~ 1e-6 m.
            CHECK(std::abs(glm::dot(planeNormal, P - v0)) < 1e-6);
            CHECK(glm::length(glm::cross(P - ray.origin, glm::normalize(ray.direction))) < 1e-6);
            CHECK(std::abs(glm::length(N) - 1.0) < 1e-6);
            CHECK(glm::dot(N, glm::dvec3(camera.eye) - P) > 0.0);
            CHECK(std::abs(std::abs(glm::dot(N, planeNormal)) - 1.0) < 1e-6);
            CHECK(g.shadingNormal[k] == g.normal[k]);   // a world without corner normals shades flat
            (glm::dot(N, planeNormal) < 0.0 ? flipped : kept) += 1;
            CHECK(g.hit[k] == 1);
            CHECK(g.triangle[k] == t);
            CHECK(g.material[k] == world.triangleMaterial[t]);
            CHECK(g.depth[k] == depth[k]);
        }
    }
    CHECK(flipped > 0);  // triangle 1 faces away from the camera
    CHECK(kept > 0);
}

TEST_CASE("buildGBuffer rejects mismatched buffers and bad triangle indices") {
    const Camera camera = smallCamera();
    const WorldGeometry world = twoTriangles();
    const size_t n = size_t(camera.width) * size_t(camera.height);
    CHECK_THROWS_AS(buildGBuffer(world, camera, std::vector<uint32_t>(n - 1, 0), std::vector<float>(n)),
                    std::invalid_argument);
    CHECK_THROWS_AS(buildGBuffer(world, camera, std::vector<uint32_t>(n, 2), std::vector<float>(n)),
                    std::invalid_argument);
}

TEST_CASE("buildGBuffer interpolates corner normals at P by its barycentric coordinates, on the side of N") {
    const Camera camera = smallCamera();
    WorldGeometry world = twoTriangles();
    // Unit corner normals far apart, so a wrong weight moves the result by degrees.
    world.cornerNormals = {glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f)), glm::normalize(glm::vec3(-0.6f, 0.1f, 1.0f)),
                           glm::normalize(glm::vec3(0.1f, -0.7f, 1.0f)), glm::normalize(glm::vec3(0.5f, 0.5f, -1.0f)),
                           glm::normalize(glm::vec3(-0.2f, 0.4f, -1.0f)), glm::normalize(glm::vec3(0.0f, -0.5f, -1.0f))};
    const size_t n = size_t(camera.width) * size_t(camera.height);
    std::vector<uint32_t> visible(n);
    for (size_t k = 0; k < n; ++k) visible[k] = uint32_t(k % 2);
    const GBuffer g = buildGBuffer(world, camera, visible, std::vector<float>(n, 0.5f));
    for (size_t k = 0; k < n; ++k) {
        CAPTURE(k);
        const uint32_t t = visible[k];
        const glm::dvec3 v0 = vertex(world, t, 0), v1 = vertex(world, t, 1), v2 = vertex(world, t, 2);
        // Barycentric coordinates by Cramer's rule on P - v0 = b1 (v1 - v0) + b2 (v2 - v0),
        // a different route from the one buildGBuffer takes.
        const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0, d = glm::dvec3(g.position[k]) - v0;
        const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        const double b1 = (d22 * glm::dot(d, e1) - d12 * glm::dot(d, e2)) / (d11 * d22 - d12 * d12);
        const double b2 = (d11 * glm::dot(d, e2) - d12 * glm::dot(d, e1)) / (d11 * d22 - d12 * d12);
        const glm::vec3* c = &world.cornerNormals[3 * t];
        glm::dvec3 expected = glm::normalize((1.0 - b1 - b2) * glm::dvec3(c[0]) + b1 * glm::dvec3(c[1]) + b2 * glm::dvec3(c[2]));
        if (glm::dot(expected, glm::dvec3(g.normal[k])) < 0.0) expected = -expected;
        const glm::dvec3 Ns(g.shadingNormal[k]);
        CHECK(std::abs(glm::length(Ns) - 1.0) < 1e-6);
        CHECK(glm::length(Ns - expected) < 1e-5);
    }
    world.cornerNormals.pop_back();
    CHECK_THROWS_AS(buildGBuffer(world, camera, visible, std::vector<float>(n, 0.5f)), std::invalid_argument);
}

// Corner UVs that are an affine function of the world position, uv = (x + 0.1 z, y - 0.2 z),
// so the perspective-correct uv at P is that function of P (interpolating in screen space
// would miss it on these slanted triangles); the world without UVs gives no uv at all.
TEST_CASE("buildGBuffer gives the texture coordinate at P, perspective-correct, and none without corner UVs") {
    const Camera camera = smallCamera();
    WorldGeometry world = twoTriangles();
    const size_t n = size_t(camera.width) * size_t(camera.height);
    std::vector<uint32_t> visible(n);
    for (size_t k = 0; k < n; ++k) visible[k] = k % 5 == 0 ? kNoTriangle : uint32_t(k % 2);
    const std::vector<float> depth(n, 0.5f);
    CHECK(buildGBuffer(world, camera, visible, depth).uv.empty());
    const auto uvOf = [](const glm::dvec3& p) { return glm::dvec2(p.x + 0.1 * p.z, p.y - 0.2 * p.z); };
    for (uint32_t t = 0; t < 2; ++t)
        for (int c = 0; c < 3; ++c) world.cornerUvs.push_back(glm::vec2(uvOf(vertex(world, t, c))));
    const GBuffer g = buildGBuffer(world, camera, visible, depth);
    REQUIRE(g.uv.size() == n);
    for (size_t k = 0; k < n; ++k) {
        CAPTURE(k);
        if (visible[k] == kNoTriangle) {
            CHECK(g.uv[k] == glm::vec2(0.0f));
            continue;
        }
        CHECK(glm::length(glm::dvec2(g.uv[k]) - uvOf(glm::dvec3(g.position[k]))) < 1e-5);
    }
    world.cornerUvs.pop_back();
    CHECK_THROWS_AS(buildGBuffer(world, camera, visible, depth), std::invalid_argument);
}
