#include "shadows/volumes/counting_mode.h"

#include <algorithm>
#include <cmath>

#include "scenes/camera.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/volumes/volume_extrusion.h"

namespace shadowlab {
namespace {

struct Plane {
    glm::dvec3 normal;   // points out of the hull
    double offset;       // signed distance (times |normal|) of x: dot(normal, x) + offset
    double at(const glm::dvec3& x) const { return glm::dot(normal, x) + offset; }
};

// The hull's face planes, oriented so that `inside` is behind each; empty if the hull is
// flat (the light on the near plane), where nothing can be separated.
std::vector<Plane> hullPlanes(const std::vector<glm::dvec3>& corner, const glm::dvec4& light) {
    const glm::dvec3 centre = (corner[0] + corner[1] + corner[2] + corner[3]) * 0.25;
    const glm::dvec3 inside = centre + 0.5 * towardsLight(light, centre);
    std::vector<glm::dvec3> normals = {glm::cross(corner[1] - corner[0], corner[2] - corner[0])};
    std::vector<glm::dvec3> points = {corner[0]};
    for (int i = 0; i < 4; ++i) {
        normals.push_back(glm::cross(corner[(i + 1) % 4] - corner[i], towardsLight(light, corner[i])));
        points.push_back(corner[i]);
    }
    std::vector<Plane> planes;
    for (size_t k = 0; k < normals.size(); ++k) {
        Plane p{normals[k], -glm::dot(normals[k], points[k])};
        const double side = p.at(inside);
        if (!(std::abs(side) > 0.0)) return {};
        if (side > 0.0) p = {-p.normal, -p.offset};
        planes.push_back(p);
    }
    return planes;
}

// The box corner deepest behind the plane is still in front of it.
bool boxOutside(const Aabb& box, const Plane& p) {
    const glm::dvec3 deepest(p.normal.x > 0 ? box.min.x : box.max.x, p.normal.y > 0 ? box.min.y : box.max.y,
                             p.normal.z > 0 ? box.min.z : box.max.z);
    return p.at(deepest) > 0.0;
}

// For a point light the hull is bounded by its five vertices; it lies beyond one of the
// box's face planes if all five do.
bool hullOutsideBox(const std::vector<glm::dvec3>& corner, const glm::dvec4& light, const Aabb& box) {
    if (light.w == 0.0) return false;
    std::vector<glm::dvec3> vertices = corner;
    vertices.push_back(glm::dvec3(light));
    for (int axis = 0; axis < 3; ++axis) {
        auto below = [&](const glm::dvec3& v) { return v[axis] < box.min[axis]; };
        auto above = [&](const glm::dvec3& v) { return v[axis] > box.max[axis]; };
        if (std::all_of(vertices.begin(), vertices.end(), below)) return true;
        if (std::all_of(vertices.begin(), vertices.end(), above)) return true;
    }
    return false;
}

// Boxes are grown by this fraction of their largest coordinate (plus 1 um) before the
// test, so that float rounding of the vertices or of the hull's planes cannot turn a
// touching occluder into a separated one: far above the 2^-24 relative rounding of both.
constexpr double kBoxMargin = 1e-6;

Aabb grown(const Aabb& box) {
    const double extent = std::max({glm::length(box.min), glm::length(box.max), 1.0});
    const glm::dvec3 margin(kBoxMargin * extent);
    return {box.min - margin, box.max + margin};
}

}  // namespace

std::vector<glm::dvec3> nearPlaneCorners(const Camera& camera) {
    const glm::dmat4 worldFromClip = glm::inverse(clipFromWorldD(camera));
    std::vector<glm::dvec3> corners;
    for (const glm::dvec2 ndc : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
        const glm::dvec4 p = worldFromClip * glm::dvec4(ndc, -1.0, 1.0);
        corners.push_back(glm::dvec3(p) / p.w);
    }
    return corners;
}

bool nearPlaneMayBeShadowed(const Camera& camera, const glm::dvec4& light, std::span<const Aabb> occluders) {
    const std::vector<glm::dvec3> corners = nearPlaneCorners(camera);
    const std::vector<Plane> planes = hullPlanes(corners, light);
    if (planes.empty()) return !occluders.empty();
    return std::any_of(occluders.begin(), occluders.end(), [&](const Aabb& occluder) {
        const Aabb box = grown(occluder);
        const bool separated = hullOutsideBox(corners, light, box) ||
                               std::any_of(planes.begin(), planes.end(), [&](const Plane& p) { return boxOutside(box, p); });
        return !separated;
    });
}

}  // namespace shadowlab
