#include "shadows/silhouettes/silhouette_image.h"

#include <algorithm>
#include <cmath>

#include "scenes/camera.h"

namespace shadowlab {
namespace {

// Liang-Barsky: the part of the segment p0 + t (p1 - p0), t in [0, 1], inside the box
// [0, size]; false if none.
bool clipToImage(glm::dvec2& p0, glm::dvec2& p1, const glm::dvec2& size) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = p1 - p0;
    for (int axis = 0; axis < 2; ++axis) {
        for (const auto& [q, r] : {std::pair{-d[axis], p0[axis]}, std::pair{d[axis], size[axis] - p0[axis]}}) {
            if (q == 0.0) {
                if (r < 0.0) return false;
                continue;
            }
            const double t = r / q;
            if (q < 0.0) t0 = std::max(t0, t);
            else t1 = std::min(t1, t);
        }
    }
    if (t0 > t1) return false;
    const glm::dvec2 start = p0 + t0 * d;
    p1 = p0 + t1 * d, p0 = start;
    return true;
}

}  // namespace

std::vector<float> silhouetteImage(const Camera& camera, std::span<const glm::vec3> positions,
                                   std::span<const SilhouetteEdge> edges) {
    const int W = camera.width, H = camera.height;
    std::vector<float> image(size_t(W) * size_t(H), 0.0f);
    const glm::dmat4 clipFromWorld = clipFromWorldD(camera);
    auto toPixels = [&](const glm::dvec4& c) { return glm::dvec2((c.x / c.w + 1.0) * 0.5 * W, (1.0 - c.y / c.w) * 0.5 * H); };
    for (const SilhouetteEdge& e : edges) {
        glm::dvec4 c0 = clipFromWorld * glm::dvec4(glm::dvec3(positions[e.from]), 1.0);
        glm::dvec4 c1 = clipFromWorld * glm::dvec4(glm::dvec3(positions[e.to]), 1.0);
        const double d0 = c0.z + c0.w, d1 = c1.z + c1.w;   // >= 0 in front of the near plane
        if (d0 < 0.0 && d1 < 0.0) continue;
        if (d0 < 0.0) c0 = c0 + (d0 / (d0 - d1)) * (c1 - c0);
        if (d1 < 0.0) c1 = c1 + (d1 / (d1 - d0)) * (c0 - c1);
        glm::dvec2 p0 = toPixels(c0), p1 = toPixels(c1);
        if (!clipToImage(p0, p1, glm::dvec2(W, H))) continue;
        const int steps = int(std::ceil(std::max(std::abs(p1.x - p0.x), std::abs(p1.y - p0.y)))) + 1;
        for (int s = 0; s <= steps; ++s) {
            const glm::dvec2 p = p0 + (double(s) / steps) * (p1 - p0);
            const int i = std::min(int(p.x), W - 1), j = std::min(int(p.y), H - 1);
            image[size_t(j) * W + i] = 1.0f;
        }
    }
    return image;
}

}  // namespace shadowlab
