#include "shadows/light_view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"

namespace shadowlab {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The frustum's side planes in view space, as (a, b, c) with a x + b y + c z >= 0 inside;
// they pass through the origin for a perspective view. For an orthographic view the
// planes are x >= x0 etc., written as (normal, offset).
struct SidePlanes {
    glm::dvec4 plane[4];   // (nx, ny, nz, d): inside when dot(n, p) + d >= 0
};

// Receiver bounds in the view: tangents (perspective) or coordinates (orthographic).
struct Bounds {
    double x0 = kInfinity, x1 = -kInfinity, y0 = kInfinity, y1 = -kInfinity;
    double nearest = kInfinity, farthest = 0.0;
};

// The pixels the map must serve: every surface, except that a spot light's map serves only
// its cone (outside it V = 0 without a lookup, as in the reference).
bool served(const Light& light, const GBuffer& g, size_t k) {
    return g.hit[k] && (light.type != LightType::Spot || insideSpotCone(light, g.position[k]));
}

// visit(accumulator, k) over every pixel k in parallel, the chunks' accumulators combined by
// join. Used for minima and maxima only, which are exact, so the order of joins cannot show.
template <typename T, typename Visit, typename Join>
T reducePixels(const GBuffer& g, const T& identity, const Visit& visit, const Join& join) {
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, g.pixelCount(), 8192), identity,
        [&](const tbb::blocked_range<size_t>& r, T acc) {
            for (size_t k = r.begin(); k != r.end(); ++k) visit(acc, k);
            return acc;
        },
        join);
}

Bounds joinBounds(Bounds a, const Bounds& b) {
    a.x0 = std::min(a.x0, b.x0), a.x1 = std::max(a.x1, b.x1), a.y0 = std::min(a.y0, b.y0), a.y1 = std::max(a.y1, b.y1);
    a.nearest = std::min(a.nearest, b.nearest), a.farthest = std::max(a.farthest, b.farthest);
    return a;
}

Bounds receiverBounds(const Light& light, const GBuffer& g, const glm::dmat4& viewFromWorld, bool orthographic) {
    const Bounds b = reducePixels(g, Bounds{}, [&](Bounds& acc, size_t k) {
        if (!served(light, g, k)) return;
        const glm::dvec3 q = glm::dvec3(viewFromWorld * glm::dvec4(glm::dvec3(g.position[k]), 1.0));
        const double depth = -q.z;
        if (!orthographic && !(depth > 0.0)) {
            throw std::invalid_argument("light view: a receiver lies beside or behind the light; use cube faces");
        }
        const double x = orthographic ? q.x : q.x / depth, y = orthographic ? q.y : q.y / depth;
        acc.x0 = std::min(acc.x0, x), acc.x1 = std::max(acc.x1, x), acc.y0 = std::min(acc.y0, y), acc.y1 = std::max(acc.y1, y);
        acc.nearest = std::min(acc.nearest, depth), acc.farthest = std::max(acc.farthest, depth);
    }, joinBounds);
    if (!(b.farthest > 0.0) && !orthographic) throw std::invalid_argument("light view: no receivers (no pixel has hit = 1)");
    if (b.x0 > b.x1) throw std::invalid_argument("light view: no receivers (no pixel has hit = 1)");
    return b;
}

SidePlanes sidePlanes(const Bounds& b, bool orthographic) {
    if (orthographic) {
        return {{{1, 0, 0, -b.x0}, {-1, 0, 0, b.x1}, {0, 1, 0, -b.y0}, {0, -1, 0, b.y1}}};
    }
    // x / (-z) >= x0  <=>  x + x0 z >= 0, and so on (depth = -z > 0).
    return {{{1, 0, b.x0, 0}, {-1, 0, -b.x1, 0}, {0, 1, b.y0, 0}, {0, -1, -b.y1, 0}}};
}

// The smallest depth (-z) of the triangle's part inside the four side planes, or +inf.
double nearestInside(const glm::dvec3 (&triangle)[3], const SidePlanes& sides) {
    glm::dvec3 polygon[8] = {triangle[0], triangle[1], triangle[2]}, next[8];
    int n = 3;
    for (const glm::dvec4& p : sides.plane) {
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 &a = polygon[i], &b = polygon[(i + 1) % n];
            const double da = glm::dot(glm::dvec3(p), a) + p.w, db = glm::dot(glm::dvec3(p), b) + p.w;
            if (da >= 0.0) next[m++] = a;
            if ((da >= 0.0) != (db >= 0.0)) next[m++] = da >= 0.0 ? a + (b - a) * (da / (da - db)) : b + (a - b) * (db / (db - da));
        }
        std::copy(next, next + m, polygon);
        n = m;
        if (n == 0) return kInfinity;
    }
    double nearest = kInfinity;
    for (int i = 0; i < n; ++i) nearest = std::min(nearest, -polygon[i].z);
    return nearest;
}

// The nearest geometry inside the sides, over all triangles; a minimum is exact and
// independent of the order, so the per-chunk minima can be combined in any order.
double nearestGeometry(const WorldGeometry& world, const glm::dmat4& viewFromWorld, const SidePlanes& sides) {
    constexpr size_t kChunk = 16384;
    const size_t chunks = (world.triangles.size() + kChunk - 1) / kChunk;
    std::vector<double> nearest(chunks, kInfinity);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        for (size_t t = c * kChunk; t < std::min(world.triangles.size(), (c + 1) * kChunk); ++t) {
            glm::dvec3 v[3];
            for (int k = 0; k < 3; ++k) {
                v[k] = glm::dvec3(viewFromWorld * glm::dvec4(glm::dvec3(world.positions[world.triangles[t][k]]), 1.0));
            }
            nearest[c] = std::min(nearest[c], nearestInside(v, sides));
        }
    });
    return chunks ? *std::min_element(nearest.begin(), nearest.end()) : kInfinity;
}

glm::dvec3 anyPerpendicular(const glm::dvec3& axis) {
    return std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

void widen(Bounds& b, const LightFitOptions& o) {
    const double mx = (b.x1 - b.x0) * o.marginTexels / o.resolution, my = (b.y1 - b.y0) * o.marginTexels / o.resolution;
    b.x0 -= mx, b.x1 += mx, b.y0 -= my, b.y1 += my;
}

// Near and far from the receivers and the geometry in front of them.
void fitDepthRange(LightView& view, const Bounds& b, const WorldGeometry& world, const LightFitOptions& o) {
    view.zFar = b.farthest * (1.0 + 1e-4) + (view.orthographic ? 1e-4 : 0.0);
    const double occluder = nearestGeometry(world, view.viewFromWorld, sidePlanes(b, view.orthographic));
    double zNear = std::min(occluder, b.nearest);
    if (!view.orthographic) zNear = std::max(zNear * (1.0 - 1e-4), view.zFar * o.minNearFraction);
    else zNear -= 1e-4 * (view.zFar - zNear) + 1e-4;
    view.zNear = zNear;
}

LightView perspectiveView(const Light& light, const glm::dvec3& axis, const GBuffer& g, const WorldGeometry& world,
                          const LightFitOptions& o) {
    LightView view;
    const glm::dvec3 apex(light.position);
    view.viewFromWorld = glm::lookAtRH(apex, apex + axis, anyPerpendicular(axis));
    Bounds b = receiverBounds(light, g, view.viewFromWorld, false);
    widen(b, o);
    fitDepthRange(view, b, world, o);
    const double n = view.zNear;
    view.clipFromView = glm::frustumRH_NO(b.x0 * n, b.x1 * n, b.y0 * n, b.y1 * n, n, view.zFar);
    return view;
}

}  // namespace

LightView fitLightView(const Light& light, const GBuffer& receivers, const WorldGeometry& world,
                       const LightFitOptions& options) {
    if (light.type == LightType::Disk || light.type == LightType::Rectangle) {
        throw std::invalid_argument("light view: an area light has no single view; use its centre (pointLightFor)");
    }
    if (light.type != LightType::Directional) {
        // Aim along options.axis or at the centre of the receivers' bounding box, then fit the
        // sides around them.
        using Box = std::pair<glm::dvec3, glm::dvec3>;
        const auto [lo, hi] = reducePixels(
            receivers, Box(glm::dvec3(kInfinity), glm::dvec3(-kInfinity)),
            [&](Box& box, size_t k) {
                if (!served(light, receivers, k)) return;
                box.first = glm::min(box.first, glm::dvec3(receivers.position[k]));
                box.second = glm::max(box.second, glm::dvec3(receivers.position[k]));
            },
            [](const Box& a, const Box& b) { return Box(glm::min(a.first, b.first), glm::max(a.second, b.second)); });
        if (lo.x > hi.x) throw std::invalid_argument("light view: no receivers (no pixel has hit = 1, or none in the spot's cone)");
        const glm::dvec3 axis = options.axis != glm::dvec3(0.0) ? options.axis : 0.5 * (lo + hi) - glm::dvec3(light.position);
        return perspectiveView(light, glm::normalize(axis), receivers, world, options);
    }
    LightView view;
    view.orthographic = true;
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(light.direction));
    // The eye sits anywhere on the light's side; depths are then measured from it.
    view.viewFromWorld = glm::lookAtRH(glm::dvec3(0.0), -towardsLight, anyPerpendicular(towardsLight));
    Bounds b = receiverBounds(light, receivers, view.viewFromWorld, true);
    widen(b, options);
    b.farthest = reducePixels(
        receivers, -kInfinity,
        [&](double& farthest, size_t k) {
            if (receivers.hit[k]) farthest = std::max(farthest, -(view.viewFromWorld * glm::dvec4(glm::dvec3(receivers.position[k]), 1.0)).z);
        },
        [](double a, double b) { return std::max(a, b); });
    fitDepthRange(view, b, world, options);
    view.clipFromView = glm::orthoRH_NO(b.x0, b.x1, b.y0, b.y1, view.zNear, view.zFar);
    return view;
}

bool fitCubeFace(const Light& light, int face, const GBuffer& receivers, const WorldGeometry& world,
                 const LightFitOptions& options, LightView& view) {
    static const glm::dvec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::dvec3 kUps[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const glm::dvec3 apex(light.position);
    view = {};
    view.viewFromWorld = glm::lookAtRH(apex, apex + kAxes[face], kUps[face]);
    // The face's receivers: those inside its 90-degree pyramid.
    Bounds b = reducePixels(receivers, Bounds{}, [&](Bounds& acc, size_t k) {
        if (!receivers.hit[k]) return;
        const glm::dvec3 q = glm::dvec3(view.viewFromWorld * glm::dvec4(glm::dvec3(receivers.position[k]), 1.0));
        if (-q.z > 0.0 && std::abs(q.x) <= -q.z && std::abs(q.y) <= -q.z) {
            acc.nearest = std::min(acc.nearest, -q.z), acc.farthest = std::max(acc.farthest, -q.z);
        }
    }, joinBounds);
    b.x0 = b.y0 = -1.0, b.x1 = b.y1 = 1.0;
    if (!(b.farthest > 0.0)) return false;
    fitDepthRange(view, b, world, options);
    view.clipFromView = glm::frustumRH_NO(-view.zNear, view.zNear, -view.zNear, view.zNear, view.zNear, view.zFar);
    return true;
}

}  // namespace shadowlab
