#include "shadows/projected/texture_projection.h"

#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"

namespace shadowlab {
namespace {

// Whether the texel P projects to is covered, in double through the float matrix the
// texture was drawn with (depth_map.h), the texel by the same floor as every map lookup.
bool inProjectedShadow(const OccluderTexture& texture, const glm::vec3& P) {
    if (texture.empty()) return false;
    const glm::dvec4 h = texture.map.texelFromWorld * glm::dvec4(glm::dvec3(P), 1.0);
    if (!(h.w > 0.0)) return false;
    const int x = texelIndexOf(h.x / h.w), y = texelIndexOf(h.y / h.w);
    const int size = texture.map.size;
    return x >= 0 && y >= 0 && x < size && y < size && texture.covered(x, y);
}

}  // namespace

ProjectedShadow projectOntoReceivers(const GBuffer& g, const WorldGeometry& world,
                                     const std::vector<uint8_t>& receiving, const Light& light,
                                     const OccluderTexture& texture) {
    ProjectedShadow out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    out.receiverMask.assign(g.pixelCount(), 0.0f);
    const bool spot = light.type == LightType::Spot;
    // Rows in parallel, each pixel written once; the counts are integer sums, the same in any order.
    using Counts = std::pair<size_t, size_t>;   // receiver pixels, shadowed ones
    const Counts counts = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, g.height), Counts{0, 0},
        [&](const tbb::blocked_range<int>& rows, Counts c) {
            for (int j = rows.begin(); j != rows.end(); ++j) {
                for (int i = 0; i < g.width; ++i) {
                    const size_t k = g.index(i, j);
                    if (!g.hit[k]) continue;
                    const bool receiver = receiving[world.triangleInstance[g.triangle[k]]] != 0;
                    out.receiverMask[k] = receiver ? 1.0f : 0.0f;
                    c.first += receiver;
                    if (spot && !insideSpotCone(light, g.position[k])) continue;
                    const bool shadowed = receiver && inProjectedShadow(texture, g.position[k]);
                    out.visibility[k] = shadowed ? 0.0f : 1.0f;
                    c.second += shadowed;
                }
            }
            return c;
        },
        [](Counts a, Counts b) { return Counts{a.first + b.first, a.second + b.second}; });
    out.receiverPixels = counts.first, out.shadowedPixels = counts.second;
    return out;
}

}  // namespace shadowlab
