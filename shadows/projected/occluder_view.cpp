#include "shadows/projected/occluder_view.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "scenes/camera.h"

namespace shadowlab {
namespace {

// The occluders' extent in a view: x and y (divided by the depth for a perspective view),
// and depth along -z. Minima and maxima are exact, so the result is the same for any split
// of the work between threads.
struct Extent {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    bool behind = false;   // perspective: a vertex at depth <= 0 has no place on the texture
    static Extent merged(Extent a, const Extent& b) {
        a.lo = glm::min(a.lo, b.lo), a.hi = glm::max(a.hi, b.hi), a.behind = a.behind || b.behind;
        return a;
    }
};

Extent extentIn(const WorldGeometry& casters, std::span<const uint32_t> occluders, const glm::dmat4& viewFromWorld,
                bool perspective) {
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, occluders.size(), 4096), Extent{},
        [&](const tbb::blocked_range<size_t>& r, Extent e) {
            for (size_t k = r.begin(); k != r.end(); ++k) {
                for (int c = 0; c < 3; ++c) {
                    const glm::dvec3 p(casters.positions[casters.triangles[occluders[k]][c]]);
                    const glm::dvec3 q(viewFromWorld * glm::dvec4(p, 1.0));
                    const double depth = -q.z;
                    if (perspective && !(depth > 0.0)) {
                        e.behind = true;
                        continue;
                    }
                    const double scale = perspective ? 1.0 / depth : 1.0;
                    const glm::dvec3 placed(q.x * scale, q.y * scale, depth);
                    e.lo = glm::min(e.lo, placed), e.hi = glm::max(e.hi, placed);
                }
            }
            return e;
        },
        Extent::merged);
}

glm::dvec3 occludersCentre(const WorldGeometry& casters, std::span<const uint32_t> occluders) {
    const Extent box = extentIn(casters, occluders, glm::dmat4(1.0), false);
    // extentIn's depth is -z: the box's z runs from -hi.z to -lo.z.
    return {0.5 * (box.lo.x + box.hi.x), 0.5 * (box.lo.y + box.hi.y), -0.5 * (box.lo.z + box.hi.z)};
}

// Sides widened by two texels, so that no occluder vertex lies on a clipping plane; depth
// by a part in 10^4 for the same reason.
void widen(Extent& e, int resolution) {
    const glm::dvec2 margin = (glm::dvec2(e.hi) - glm::dvec2(e.lo)) * (2.0 / resolution) + 1e-9;
    e.lo.x -= margin.x, e.hi.x += margin.x, e.lo.y -= margin.y, e.hi.y += margin.y;
    const double depthMargin = 1e-4 * (e.hi.z - e.lo.z) + 1e-4;
    e.lo.z -= depthMargin, e.hi.z += depthMargin;
}

}  // namespace

LightView fitOccluderView(const WorldGeometry& casters, std::span<const uint32_t> occluders, const Light& light,
                          int resolution) {
    LightView view;
    view.orthographic = light.type == LightType::Directional;
    const glm::dvec3 apex = view.orthographic ? glm::dvec3(0.0) : glm::dvec3(light.position);
    const glm::dvec3 axis =
        view.orthographic ? -glm::dvec3(light.direction) : occludersCentre(casters, occluders) - apex;
    if (!(glm::length(axis) > 0.0)) {
        throw std::invalid_argument("projected-texture: the occluders are centred on the light");
    }
    view.viewFromWorld = glm::lookAtRH(apex, apex + glm::normalize(axis), lookAtUp(glm::normalize(axis)));
    Extent e = extentIn(casters, occluders, view.viewFromWorld, !view.orthographic);
    // A frustum wider than 4 in x / depth (about 63 degrees either side of a centred axis)
    // would stretch its outer texels without bound.
    if (e.behind || e.hi.x - e.lo.x >= 4.0 || e.hi.y - e.lo.y >= 4.0) {
        throw std::invalid_argument("projected-texture: the occluders reach beside or behind the light, no frustum "
                                    "of one texture holds them (choose fewer with occluders=...)");
    }
    widen(e, resolution);
    view.zFar = e.hi.z;
    if (view.orthographic) {
        view.zNear = e.lo.z;
        view.clipFromView = glm::orthoRH_NO(e.lo.x, e.hi.x, e.lo.y, e.hi.y, view.zNear, view.zFar);
    } else {
        const double n = view.zNear = std::max(e.lo.z, e.hi.z * 1e-4);   // as light_view.h's minNearFraction
        view.clipFromView = glm::frustumRH_NO(e.lo.x * n, e.hi.x * n, e.lo.y * n, e.hi.y * n, n, view.zFar);
    }
    return view;
}

}  // namespace shadowlab
