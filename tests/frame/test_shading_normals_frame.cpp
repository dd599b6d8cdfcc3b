// The shading normal of a rendered frame: on sphere-box's tessellated sphere it follows the
// true sphere's normal closely where the facets' geometric normal is degrees off.
#include <doctest/doctest.h>

#include <cmath>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

TEST_CASE("on a tessellated sphere the shading normal is within 0.05 degree of the true normal, the facet's degrees off") {
    const PreparedScene prepared(loadScene("sphere-box"));
    const Frame frame = renderFrame(prepared, findTechnique("none"), FrameSettings{});
    const GBuffer& g = frame.gbuffer;
    const WorldGeometry& world = prepared.world();
    const glm::dvec3 centre(0.0, 1.2, 0.0);   // the sphere instance's translation
    double worstShading = 0.0, worstGeometric = 0.0;
    size_t sphere = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k] || prepared.scene().instances[world.triangleInstance[g.triangle[k]]].name != "sphere") continue;
        ++sphere;
        const glm::dvec3 exact = glm::normalize(glm::dvec3(g.position[k]) - centre);
        auto angle = [&](const glm::vec3& n) { return glm::degrees(std::acos(std::min(1.0, glm::dot(glm::dvec3(n), exact)))); };
        worstShading = std::max(worstShading, angle(g.shadingNormal[k]));
        worstGeometric = std::max(worstGeometric, angle(g.normal[k]));
    }
    MESSAGE("sphere pixels " << sphere << ", worst angle to the true normal: shading " << worstShading
                             << " deg, geometric " << worstGeometric << " deg");
    REQUIRE(sphere > 10000);
    CHECK(worstShading < 0.05);
    CHECK(worstGeometric > 2.0);
}
