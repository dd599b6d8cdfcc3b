#include "differential/outdoor_case.h"

#include "differential/environment_dome.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/portable_constants.h"
#include "scenes/camera.h"
#include "shading/luminance.h"

namespace shadowlab {
namespace {

// The ground's diffuse reflectance: pi times its mean radiance in the map (the lower
// hemisphere within 60 degrees of the nadir, where the ground is seen) over the sky's
// irradiance on a level surface.
glm::dvec3 groundReflectance(const EnvironmentMap& map) {
    glm::dvec3 ground(0.0), sky(0.0);
    double groundWeight = 0.0;
    for (int j = 0; j < map.height; ++j) {
        const double omega = map.texelSolidAngle(j);
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 d = map.direction((i + 0.5) / map.width, (j + 0.5) / map.height);
            if (d.y > 0.0) sky += glm::dvec3(map.at(i, j)) * (d.y * omega);
            if (d.y < -0.5) ground += glm::dvec3(map.at(i, j)) * omega, groundWeight += omega;
        }
    }
    if (luminance(sky) <= 0.0) throw std::invalid_argument("outdoor case: the map has no light above the horizon");
    if (!(groundWeight > 0.0))
        throw std::invalid_argument("outdoor case: the map has no texel within 60 degrees of the nadir");
    const glm::dvec3 rho = kPi * (ground / groundWeight) / glm::max(sky, glm::dvec3(1e-12));
    return glm::clamp(rho, glm::dvec3(0.02), glm::dvec3(0.9));
}

}  // namespace

CompositingScene compositingOutdoor(const EnvironmentMap& map, const Mesh& object, const OutdoorSettings& s) {
    if (s.width < 16 || s.height < 16 || s.width > 4096 || s.height > 4096) {
        throw std::invalid_argument("outdoor case: the image needs 16 to 4096 pixels per side");
    }
    CompositingScene scene;
    scene.name = "outdoor";
    // Looking down the path (the map's centre column), a little below the horizon.
    const glm::dvec3 eye(0.0, s.cameraHeightM, 0.0), view = map.direction(0.5, 0.58);
    scene.camera.eye = glm::vec3(eye);
    scene.camera.target = glm::vec3(eye + view);
    scene.camera.fovyDeg = 60.0f;
    scene.camera.width = s.width, scene.camera.height = s.height;
    scene.camera.zNear = 0.05f, scene.camera.zFar = float(4.0 * s.domeRadiusM);
    // The photograph: the panorama through the pinhole, nearest texel.
    const PixelRays rays(scene.camera);
    for (int j = 0; j < s.height; ++j) {
        for (int i = 0; i < s.width; ++i) {
            const glm::ivec2 t = map.texelToward(rays(i, j).direction);
            scene.background.push_back(map.at(t.x, t.y));
        }
    }
    // The ground: 24 x 24 m under and ahead of the camera, in 0.5 m cells.
    const glm::dvec3 ahead = glm::normalize(glm::dvec3(view.x, 0.0, view.z));
    const glm::dvec3 side = glm::cross(ahead, glm::dvec3(0, 1, 0));   // ahead x up: to the right
    const glm::dvec3 corner = -12.0 * side - 4.0 * ahead;
    scene.surfaces.push_back({"ground", corner, 24.0 * side, 24.0 * ahead, 48, 48, groundReflectance(map), {}});
    if (glm::cross(scene.surfaces[0].edgeU, scene.surfaces[0].edgeV).y < 0.0) {
        std::swap(scene.surfaces[0].edgeU, scene.surfaces[0].edgeV);
    }
    for (PatchSurface& sky : environmentDome(map, s.domeColumns, s.domeRows, s.domeRadiusM)) {
        scene.surfaces.push_back(std::move(sky));
    }
    // The object walks across the path 3 m ahead.
    SyntheticObject walker{object, glm::dvec3(0.72, 0.7, 0.66), {}};
    for (int k = 0; k <= 10; ++k) {
        const glm::dvec3 at = 3.0 * ahead + (-1.0 + 0.2 * k) * side;
        walker.path.push_back(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(at)), glm::vec3(0.06f)));
    }
    scene.objects = {std::move(walker)};
    // White at the photograph's 98th percentile of luminance (the brightest sky clips).
    std::vector<float> luminances;
    for (const glm::vec3& L : scene.background) luminances.push_back(luminance(L));
    const auto white = luminances.begin() + std::ptrdiff_t(0.98 * double(luminances.size() - 1));
    std::nth_element(luminances.begin(), white, luminances.end());
    scene.response = {1.0 / std::max(double(*white), 1e-6), 2.2};
    return scene;
}

}  // namespace shadowlab
