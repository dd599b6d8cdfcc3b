#include "differential/cluster_shadow_maps.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/camera.h"

namespace shadowlab {
namespace {

// A light at (or inside) the object's bounding sphere sees it over a hemisphere or more:
// the cone is capped at 160 degrees (cot 80 degrees), which one map can still hold.
constexpr double kWidestCotangent = 0.17632698070846498;

}  // namespace

ClusterMap clusterShadowMap(const glm::dvec3& light, const glm::dvec3& sphereCentre, double sphereRadius,
                            const WorldGeometry& casters, int size, raster::SimdLevel simd) {
    const glm::dvec3 toObject = sphereCentre - light;
    const double d = glm::length(toObject);
    const double r = std::max(sphereRadius, 1e-6);
    // The cone's half-angle a holds the sphere: sin a = r / d, so cot a = sqrt(d^2 - r^2) / r.
    const double cotangent = d > r ? std::max(std::sqrt(d * d - r * r) / r, kWidestCotangent) : kWidestCotangent;
    LightView view;
    const glm::dvec3 forward = d > 0.0 ? toObject / d : glm::dvec3(0, -1, 0);
    view.viewFromWorld = glm::lookAt(light, light + forward, lookAtUp(forward));
    view.zNear = std::max(d - r, 1e-3 * r);
    view.zFar = d + r;
    view.clipFromView = glm::dmat4(0.0);
    view.clipFromView[0][0] = cotangent;
    view.clipFromView[1][1] = cotangent;
    view.clipFromView[2][2] = (view.zFar + view.zNear) / (view.zNear - view.zFar);
    view.clipFromView[2][3] = -1.0;
    view.clipFromView[3][2] = 2.0 * view.zFar * view.zNear / (view.zNear - view.zFar);
    DepthMapSettings settings;
    settings.size = size;
    return {light, renderDepthMap(casters, view, settings, simd)};
}

bool occluded(const ClusterMap& cluster, const glm::dvec3& P) {
    const DepthMap& map = cluster.map;
    const glm::dvec4 h = map.texelFromWorld * glm::dvec4(P, 1.0);
    if (!(h.w > 0.0)) return false;
    const double x = h.x / h.w, y = h.y / h.w, depth = h.z / h.w;
    if (!(x >= 0.0 && y >= 0.0 && x < map.size && y < map.size)) return false;
    const float drawn = map.at(int(x), int(y));
    return drawn < 1.0f && depth > double(drawn);
}

}  // namespace shadowlab
