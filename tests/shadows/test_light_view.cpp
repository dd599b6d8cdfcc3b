// The fitted light view: every receiver the camera sees is inside the light's frustum, no
// geometry that could shadow a receiver is cut off by the near plane, and the fit is tight:
// receivers reach each of the four sides to within the margin and the far plane.
#include <doctest/doctest.h>

#include <cmath>

#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shadows/light_view.h"

using namespace shadowlab;

namespace {

glm::dvec3 clipPoint(const LightView& view, const glm::vec3& p) {
    const glm::dvec4 c = view.clipFromWorld() * glm::dvec4(glm::dvec3(p), 1.0);
    return glm::dvec3(c) / c.w;
}

void checkFit(const LightView& view, const GBuffer& g, const WorldGeometry& world) {
    int receivers = 0, outside = 0, cutOff = 0;
    glm::dvec2 lowest(INFINITY), highest(-INFINITY);
    double farthest = 0.0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const glm::dvec3 ndc = clipPoint(view, g.position[k]);
        outside += !(std::abs(ndc.x) < 1.0 && std::abs(ndc.y) < 1.0 && ndc.z >= -1.0 && ndc.z <= 1.0);
        lowest = glm::min(lowest, glm::dvec2(ndc)), highest = glm::max(highest, glm::dvec2(ndc));
        farthest = std::max(farthest, -(view.viewFromWorld * glm::dvec4(glm::dvec3(g.position[k]), 1.0)).z);
        ++receivers;
    }
    CHECK(receivers > 1000);
    CHECK(outside == 0);
    // Tight: within the default margin (2 texels of a 2048 map) of every side, in NDC units.
    const LightFitOptions defaults;
    const double margin = 2.0 * defaults.marginTexels / defaults.resolution;
    CHECK(lowest.x < -1.0 + 1.01 * margin);
    CHECK(lowest.y < -1.0 + 1.01 * margin);
    CHECK(highest.x > 1.0 - 1.01 * margin);
    CHECK(highest.y > 1.0 - 1.01 * margin);
    CHECK(farthest > view.zFar * (1.0 - 1e-3));
    // Geometry inside the sides and nearer than the far plane is behind the near plane.
    for (const glm::vec3& p : world.positions) {
        const glm::dvec3 q = glm::dvec3(view.viewFromWorld * glm::dvec4(glm::dvec3(p), 1.0));
        const glm::dvec3 ndc = clipPoint(view, p);
        if (std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0 && -q.z < view.zFar && (view.orthographic || -q.z > 0.0)) {
            cutOff += -q.z < view.zNear;
        }
    }
    CHECK(cutOff == 0);
}

}  // namespace

TEST_CASE("the fitted light view holds every visible receiver and cuts off no occluder") {
    const Scene scene = loadScene("sphere-box");
    const WorldGeometry world = flatten(scene);
    const GBuffer g = renderGBuffer(world, scene.camera, raster::bestSimdLevel());
    Light point = pointLightFor(scene.lights[0]);
    const LightView perspective = fitLightView(point, g, world);
    CHECK_FALSE(perspective.orthographic);
    checkFit(perspective, g, world);
    // The light is 8 m above the ground and the sphere's top (y = 2.2) is the nearest occluder.
    CHECK(perspective.zNear > 4.0);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1, 3, 2));
    const LightView ortho = fitLightView(sun, g, world);
    CHECK(ortho.orthographic);
    checkFit(ortho, g, world);
    CHECK_THROWS_AS(fitLightView(scene.lights[0], g, world), std::invalid_argument);   // the disk itself
}

TEST_CASE("a point light inside the scene needs cube faces, each face holds its receivers") {
    const Scene scene = loadScene("sphere-box");
    const WorldGeometry world = flatten(scene);
    const GBuffer g = renderGBuffer(world, scene.camera, raster::bestSimdLevel());
    Light inside = pointLightFor(scene.lights[0]);
    inside.position = glm::vec3(0.0f, 0.5f, 2.0f);   // low, in front of the sphere: receivers all around
    CHECK_THROWS_AS(fitLightView(inside, g, world), std::invalid_argument);
    int faces = 0;
    for (int face = 0; face < 6; ++face) {
        LightView view;
        if (!fitCubeFace(inside, face, g, world, {}, view)) continue;
        ++faces;
        CHECK(view.zNear > 0.0);
        CHECK(view.zFar > view.zNear);
    }
    CHECK(faces >= 4);
}

TEST_CASE("a triangle reaching out of the light's sides sets the near plane by its part inside, not its corner outside") {
    const Scene scene = loadScene("sphere-box");
    WorldGeometry world = flatten(scene);
    const GBuffer g = renderGBuffer(world, scene.camera, raster::bestSimdLevel());
    const Light point = pointLightFor(scene.lights[0]);
    const LightView before = fitLightView(point, g, world);
    // In the view: two corners on the axis at depth 4, nearer than every occluder, and one far
    // outside the +x side at depth 1. The sides depend on the receivers only, so they stay.
    const glm::dmat4 worldFromView = glm::inverse(before.viewFromWorld);
    const glm::dvec3 corners[3] = {{50.0, 0.0, -1.0}, {-0.2, -0.2, -4.0}, {0.2, 0.2, -4.0}};
    const auto first = uint32_t(world.positions.size());
    for (const glm::dvec3& c : corners) world.positions.push_back(glm::vec3(worldFromView * glm::dvec4(c, 1.0)));
    world.triangles.push_back({first, first + 1, first + 2});
    world.triangleMaterial.push_back(0), world.triangleInstance.push_back(0);
    const LightView view = fitLightView(point, g, world);
    // The nearest depth of the part inside the sides, from samples of the triangle.
    double nearest = INFINITY;
    constexpr int kSteps = 600;
    for (int i = 0; i <= kSteps; ++i) {
        for (int j = 0; i + j <= kSteps; ++j) {
            const double a = double(i) / kSteps, b = double(j) / kSteps;
            const glm::dvec3 q = (1.0 - a - b) * corners[0] + a * corners[1] + b * corners[2];
            const glm::dvec4 clip = view.clipFromView * glm::dvec4(q, 1.0);
            if (std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w) nearest = std::min(nearest, -q.z);
        }
    }
    REQUIRE(nearest > 1.5);   // the corner at depth 1 is outside
    REQUIRE(nearest < before.zNear);
    CHECK(view.zNear <= nearest);
    CHECK(view.zNear > nearest * (1.0 - 1e-4) - 0.02);
}
