#include "shadows/maps/lispsm.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadows/maps/receiver_ranges.h"

namespace shadowlab {
namespace {

// Below this sin(gamma) the warp would be indistinguishable from uniform (n_opt over a
// thousand times z_n + sqrt(z_n z_f)); it is skipped rather than computed in the limit.
constexpr double kMinSinGamma = 1e-3;

// Rows x, y, z of a rotation matrix (column-major glm) from three unit axes.
glm::dmat4 rotationRows(const glm::dvec3& x, const glm::dvec3& y, const glm::dvec3& z) {
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) m[c][0] = x[c], m[c][1] = y[c], m[c][2] = z[c];
    return m;
}

// The affine map [lo, hi] -> [-1, 1], applied to homogeneous coordinates: (a q + b w).
void fitRow(glm::dmat4& m, int row, int fromRow, const Range& r) {
    const double a = 2.0 / (r.hi - r.lo), b = -(r.hi + r.lo) / (r.hi - r.lo);
    for (int c = 0; c < 4; ++c) m[c][row] = 0.0;
    m[fromRow][row] = a;   // column fromRow of the input homogeneous vector
    m[3][row] = b;
}

}  // namespace

LispsmView lispsmView(const LightView& uniform, const Light& sun, const Camera& camera, const GBuffer& g,
                      int resolution, double marginTexels) {
    const glm::dvec3 zL = glm::normalize(glm::dvec3(sun.direction));   // towards the light
    const glm::dvec3 eye(camera.eye), viewDir = glm::normalize(glm::dvec3(camera.target) - eye);
    LispsmView out;
    out.view = uniform;
    out.nOpt = std::numeric_limits<double>::infinity();
    out.sinGamma = glm::length(glm::cross(viewDir, zL));
    if (out.sinGamma < kMinSinGamma) return out;

    // Light space: z towards the light, y the view direction projected onto the map plane.
    const glm::dvec3 yL = glm::normalize(viewDir - glm::dot(viewDir, zL) * zL), xL = glm::cross(yL, zL);
    const glm::dmat4 lightFromWorld = rotationRows(xL, yL, zL);
    const auto [across, along, cameraDepth] = receiverRanges<3>(g, [&](const glm::dvec3& p) {
        return glm::dvec3(glm::dot(p, xL), glm::dot(p, yL), glm::dot(p - eye, viewDir));
    });
    const double zn = std::max(cameraDepth.lo, 1e-3 * cameraDepth.hi), zf = cameraDepth.hi;
    const double n = (zn + std::sqrt(zn * zf)) / out.sinGamma, f = n + (along.hi - along.lo);
    out.nOpt = n;

    // The warp W in light space: s = y - c_y is the distance along the axis from the
    // centre c = (eye_x, y_min - n, -zNear); u = (x - c_x)/s, v = A + B/s (near n -> -1,
    // far f -> +1) and the depth (c_z - z)/s, which grows away from the light.
    const glm::dvec3 c(glm::dot(eye, xL), along.lo - n, -uniform.zNear);
    const double A = (f + n) / (f - n), B = -2.0 * f * n / (f - n);
    glm::dmat4 warp(0.0);
    warp[0][0] = 1.0, warp[3][0] = -c.x;                 // X = x - c_x
    warp[1][1] = A, warp[3][1] = B - A * c.y;            // Y = A (y - c_y) + B
    warp[2][2] = -1.0, warp[3][2] = c.z;                 // Z = c_z - z
    warp[1][3] = 1.0, warp[3][3] = -c.y;                 // W = y - c_y

    // Fit the warped receivers into the map, as fitLightView does for the uniform one.
    auto [u, v, depth] = receiverRanges<3>(g, [&](const glm::dvec3& p) {
        const glm::dvec4 h = warp * lightFromWorld * glm::dvec4(p, 1.0);
        return glm::dvec3(h.x / h.w, h.y / h.w, h.z / h.w);
    });
    u.widen(marginTexels / resolution), v.widen(marginTexels / resolution);
    depth.lo = 0.0;                        // the uniform view's near plane: every occluder
    depth.hi *= 1.0 + 1e-4;
    glm::dmat4 fit(0.0);
    fitRow(fit, 0, 0, u), fitRow(fit, 1, 1, v), fitRow(fit, 2, 2, depth);
    fit[3][3] = 1.0;
    out.view.viewFromWorld = lightFromWorld;
    out.view.clipFromView = fit * warp;
    out.view.orthographic = false;
    return out;
}

}  // namespace shadowlab
