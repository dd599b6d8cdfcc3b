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
