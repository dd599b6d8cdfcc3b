#include "shadows/temporal/reprojection.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "shading/gbuffer_build.h"

namespace shadowlab {
namespace {

// Whether texel (x, y) of the previous image saw the surface whose point was at `p` with
// normal `n` (reprojection.h: the depth and the normal tests).
bool sameSurface(const PreviousView& previous, int x, int y, const glm::dvec3& p, const glm::dvec3& n,
                 double tolerance, const ReprojectionSettings& s) {
    if (x < 0 || y < 0 || x >= previous.camera.width || y >= previous.camera.height) return false;
    const size_t t = previous.index(x, y);
    if (!previous.hit[t]) return false;
    const glm::dvec3 tn(previous.normal[t]);
    return std::abs(glm::dot(glm::dvec3(previous.position[t]) - p, n)) <= tolerance &&
           glm::dot(tn, n) >= s.minNormalCos;
}

}  // namespace

Reprojection reproject(const GBuffer& g, const PreviousView& previous, const ReprojectionSettings& s) {
    requireConsistent(g, "reproject");
    if (g.motion.pixelOffset.empty())
        throw std::invalid_argument("reproject: the G-buffer has no motion (a frame without a frame before)");
    if (!(s.planeTolerance > 0.0) || !(s.minNormalCos >= -1.0 && s.minNormalCos <= 1.0))
        throw std::invalid_argument("reproject: the plane tolerance must be > 0 and the normal cosine in [-1, 1]");
    const size_t n = g.pixelCount();
    Reprojection r{std::vector<glm::uvec4>(n, glm::uvec4(0)), std::vector<glm::vec4>(n, glm::vec4(0.0f)),
                   std::vector<uint8_t>(n, 0), 0, previous.hit.size()};
    const glm::dvec3 eye(previous.camera.eye);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            const glm::vec2 offset = g.motion.pixelOffset[k];
            if (!g.hit[k] || !std::isfinite(offset.x) || !std::isfinite(offset.y)) continue;
            // The 2x2 texel centres around the point (texel x's centre at x + 0.5).
            const double bx = i + double(offset.x), by = j + double(offset.y);
            if (std::abs(bx) > 1e9 || std::abs(by) > 1e9) continue;   // far outside: no int overflow
            const int x0 = int(std::floor(bx)), y0 = int(std::floor(by));
            const double fx = bx - x0, fy = by - y0;
            const glm::dvec3 p(g.motion.previousPosition[k]), normal(g.motion.previousNormal[k]);
            const double tolerance = s.planeTolerance * glm::length(p - eye);
            const int xs[4] = {x0, x0 + 1, x0, x0 + 1}, ys[4] = {y0, y0, y0 + 1, y0 + 1};
            const double bilinear[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
            double w[4], sum = 0.0;
            for (int c = 0; c < 4; ++c) {
                w[c] = sameSurface(previous, xs[c], ys[c], p, normal, tolerance, s) ? bilinear[c] : 0.0;
                sum += w[c];
                if (w[c] > 0.0) r.texels[k][c] = uint32_t(previous.index(xs[c], ys[c]));
            }
            if (!(sum >= kMinKeptWeight)) continue;
            for (int c = 0; c < 4; ++c) r.weights[k][c] = float(w[c] / sum);
            r.kept[k] = 1;
        }
    });
    for (size_t k = 0; k < n; ++k) r.rejectedPixels += g.hit[k] && !r.kept[k];
    return r;
}

std::optional<Reprojection> reprojectHistory(const GBuffer& g, const PreviousView* previous, size_t historyPixels,
                                             const ReprojectionSettings& s) {
    if (!previous || historyPixels != previous->hit.size()) return std::nullopt;
    return reproject(g, *previous, s);
}

void requireHistoryOf(const Reprojection& reprojection, size_t historyPixels, const char* who) {
    if (historyPixels != reprojection.previousPixels)
        throw std::logic_error(std::string(who) + ": a history of " + std::to_string(historyPixels) +
                               " pixels read through a reprojection into " +
                               std::to_string(reprojection.previousPixels));
}

}  // namespace shadowlab
