#include "shadows/maps/shadow_lookup.h"

#include <algorithm>
#include <cmath>

#include "scenes/camera.h"
#include "shading/lights.h"
#include "shadows/receiver_pass.h"

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

bool inDensitySample(int i, int j) { return i % kDensitySampleStride == 0 && j % kDensitySampleStride == 0; }

}  // namespace

glm::dvec3 unitTowardsLight(const Light& light, const glm::dvec3& P) {
    if (light.type == LightType::Directional) return glm::normalize(glm::dvec3(light.direction));
    return glm::normalize(glm::dvec3(light.position) - P);
}

double texelsPerPixel(const DepthMap& map, const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N) {
    const glm::dvec2 t = texelOf(map, P);
    const glm::dvec2 dx = texelOf(map, onPlane(rays, i + 1, j, P, N)) - t;
    const glm::dvec2 dy = texelOf(map, onPlane(rays, i, j + 1, P, N)) - t;
    const double area = std::abs(dx.x * dy.y - dx.y * dy.x);
    return std::isfinite(area) ? area : 0.0;
}

ShadowLookup lookUpShadows(const GBuffer& g, const Camera& camera, const Light& light,
                           const std::vector<DepthMap>& maps, const MapSelector& select, const BiasSettings& bias,
                           const PcfKernel& kernel, bool everyPixelDensity) {
    ShadowLookup out;
    out.width = g.width;
    out.visibility.assign(g.pixelCount(), 0.0f);
    out.texelDensity.assign(g.pixelCount(), 0.0f);
    out.mapIndex.assign(g.pixelCount(), -1);
    const PixelRays rays(camera);
    // Every surface pixel, not only those the light reaches: the map serving a pixel and its
    // texel density are shown (and measured) wherever there is a surface.
    forEachSurfacePixel(g, [&](int i, int j, size_t k) {
        const glm::dvec3 P(g.position[k]), N(g.normal[k]);
        const int m = select(P, k);
        if (m < 0) return;
        out.mapIndex[k] = int8_t(m);
        if (everyPixelDensity || inDensitySample(i, j)) out.texelDensity[k] = float(texelsPerPixel(maps[m], rays, i, j, P, N));
        if (!lightReaches(light, g.position[k], g.normal[k])) return;
        const MapReceiver r = mapReceiver(maps[m], P, N, unitTowardsLight(light, P), bias);
        out.visibility[k] = float(filteredVisibility(maps[m], r, kernel, k));
    });
    return out;
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
