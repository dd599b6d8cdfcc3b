#include "shadows/raytraced/shadow_rays.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/portable_math.h"

namespace shadowlab {

float lightAngularDiameter(const Light& light, const glm::vec3& P) {
    double radius = 0.0;
    switch (light.type) {
        case LightType::Point:
        case LightType::Spot:
            return 0.0f;
        case LightType::Directional:
            return float(double(light.angularDiameterDeg) * std::numbers::pi / 180.0);
        case LightType::Disk:
            radius = double(light.radius);
            break;
        case LightType::Rectangle: {   // the farthest corner: the half-edges need not be orthogonal
            const glm::dvec3 u(light.halfEdgeU), v(light.halfEdgeV);
            radius = std::max(glm::length(u + v), glm::length(u - v));
            break;
        }
    }
    const double distance = glm::length(glm::dvec3(light.position) - glm::dvec3(P));
    // asin(x) = atan(x / sqrt(1 - x^2)) through the portable atan: libm's asin is dispatched
    // at run time, and its last bit differs between CPUs.
    const double x = radius / distance;
    return distance <= radius ? float(std::numbers::pi) : float(2.0 * portable::atan(x / std::sqrt(1.0 - x * x)));
}

ShadowRayBuffers traceShadowRays(const ReferenceVisibility& rays, const GBuffer& g, const Light& light,
                                 int raysPerPixel, uint32_t frame, Progress* progress) {
    if (raysPerPixel < 1) throw std::invalid_argument("ray-traced shadows: rays per pixel must be >= 1");
    ReferenceVisibility::Passed passed =
        rays.passed(g, light, {.progress = progress, .sequence = PixelSequence{.count = raysPerPixel, .frame = frame},
                               .occluderDistance = true});
    ShadowRayBuffers out{.visibility = std::move(passed.visibility),
                         .coloured = std::move(passed.coloured),
                         .occluderDistance = std::move(passed.occluderDistance),
                         .occludedRays = std::move(passed.occludedRays),
                         .lightAngle = std::vector<float>(g.pixelCount(), 0.0f),
                         .raysCast = passed.raysCast};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount()), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t k = range.begin(); k != range.end(); ++k) {
            if (g.hit[k]) out.lightAngle[k] = lightAngularDiameter(light, g.position[k]);
        }
    });
    return out;
}

}  // namespace shadowlab
