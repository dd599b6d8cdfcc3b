#include "shadows/maps/shadow_lookup.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

glm::dvec2 texelOf(const DepthMap& map, const glm::dvec3& p) {
    const glm::dvec4 h = map.texelFromWorld * glm::dvec4(p, 1.0);
    return glm::dvec2(h) / h.w;
}

// Where the ray through the centre of pixel (i, j) meets the plane (P, N).
glm::dvec3 onPlane(const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N) {
    const RayD ray = rays(i, j);
    return ray.origin + ray.direction * (glm::dot(N, P - ray.origin) / glm::dot(N, ray.direction));
}

}  // namespace

double texelsPerPixel(const DepthMap& map, const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N) {
    const glm::dvec2 t = texelOf(map, P);
    const glm::dvec2 dx = texelOf(map, onPlane(rays, i + 1, j, P, N)) - t;
    const glm::dvec2 dy = texelOf(map, onPlane(rays, i, j + 1, P, N)) - t;
    const double area = std::abs(dx.x * dy.y - dx.y * dy.x);
    return std::isfinite(area) ? area : 0.0;
}

double medianTexelDensity(const ShadowLookup& lookup) {
    std::vector<float> served;
    const int height = lookup.width ? int(lookup.mapIndex.size()) / lookup.width : 0;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < lookup.width; ++i) {
            const size_t k = size_t(j) * size_t(lookup.width) + size_t(i);
            if (lookup.mapIndex[k] >= 0 && inDensitySample(i, j)) served.push_back(lookup.texelDensity[k]);
        }
    }
    if (served.empty()) return 0.0;
    std::nth_element(served.begin(), served.begin() + served.size() / 2, served.end());
    return served[served.size() / 2];
}

}  // namespace shadowlab
