#include "shadows/maps/shadow_bias.h"

#include "shadows/maps/receiver_plane_tolerance.h"

#include <cmath>

namespace shadowlab {
namespace {


glm::dvec3 project(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

// The receiver's plane (N, P) in texel space solved for depth: z = z0 + s . (t - t0).
// Planes transform by the inverse transpose: pi_texel = (worldFromTexel)^T pi_world.
glm::dvec2 receiverPlaneSlope(const DepthMap& map, const glm::dvec3& P, const glm::dvec3& N) {
    const glm::dvec4 planeWorld(N, -glm::dot(N, P));
    const glm::dvec4 plane = glm::transpose(map.worldFromTexel) * planeWorld;
    const glm::dvec2 slope(-plane.x / plane.z, -plane.y / plane.z);
    // A plane that contains the light rays has no depth function; the light grazes it.
    return std::isfinite(slope.x) && std::isfinite(slope.y) ? slope : glm::dvec2(0.0);
}

}  // namespace

raster::PolygonOffset polygonOffsetFor(const BiasSettings& bias) {
    if (bias.mode != BiasMode::SlopeScaled) return {};
    return {bias.slopeFactor, bias.slopeUnits};
}

double texelWorldSize(const DepthMap& map, const glm::dvec3& P) {
    const glm::dvec3 t = project(map.texelFromWorld, P);
    return glm::length(project(map.worldFromTexel, t + glm::dvec3(1.0, 0.0, 0.0)) - P);
}

MapReceiver mapReceiver(const DepthMap& map, const glm::dvec3& P, const glm::dvec3& N,
                        const glm::dvec3& unitTowardsLight, const BiasSettings& bias) {
    glm::dvec3 p = P;
    // The constant part: alone, and under the normal offset, which vanishes where the
    // surface faces the light and leaves only the map's precision there (RTR 7.4).
    if (needsLightDirection(bias)) p += unitTowardsLight * bias.constantMetres;
    if (bias.mode == BiasMode::NormalOffset) {
        // Holbert's normal offset: proportional to sin(angle between N and L), RTR 7.4.
        const double cosine = glm::dot(N, unitTowardsLight);
        const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
        p += N * (bias.normalOffsetTexels * texelWorldSize(map, P) * sine);
    }
    const glm::dvec3 t = project(map.texelFromWorld, p);
    MapReceiver r;
    r.texel = glm::dvec2(t);
    r.depth = t.z;
    if (bias.mode == BiasMode::ReceiverPlane) {
        r.depthSlope = receiverPlaneSlope(map, p, N);
        using namespace receiver_plane;
        r.tolerance = (std::abs(r.depthSlope.x) + std::abs(r.depthSlope.y)) * kRasterPositionErrorTexels +
                      kDepthErrorSteps * kDepthStep;
    }
    return r;
}

}  // namespace shadowlab
