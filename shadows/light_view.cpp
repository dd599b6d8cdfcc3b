#include "shadows/light_view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "scenes/camera.h"
#include "shading/lights.h"
#include "shadows/receiver_bounds.h"

namespace shadowlab {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The frustum's side planes in view space, as (a, b, c) with a x + b y + c z >= 0 inside;
// they pass through the origin for a perspective view. For an orthographic view the
// planes are x >= x0 etc., written as (normal, offset).
struct SidePlanes {
    glm::dvec4 plane[4];   // (nx, ny, nz, d): inside when dot(n, p) + d >= 0
};

// How far inside side plane p the point q lies (negative outside): the one expression the
// clipping (nearestInside) and the per-vertex test (viewVertices) both decide by.
double sideDistance(const glm::dvec4& p, const glm::dvec3& q) { return glm::dot(glm::dvec3(p), q) + p.w; }

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

// The bounds of a value over every pixel the map serves, computed in parallel: minima and
// maxima are exact whatever order the chunks are merged in, so the result does not depend
// on the thread count.
template <class Value, class Add, class Merge>
Value overServedPixels(const Light& light, const GBuffer& g, const Value& empty, Add add, Merge merge) {
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, g.pixelCount()), empty,
        [&](const tbb::blocked_range<size_t>& range, Value value) {
            for (size_t k = range.begin(); k < range.end(); ++k) {
                if (served(light, g, k)) add(value, k);
            }
            return value;
        },
        merge);
}

Bounds merged(const Bounds& a, const Bounds& b) {
    return {std::min(a.x0, b.x0), std::max(a.x1, b.x1), std::min(a.y0, b.y0), std::max(a.y1, b.y1),
            std::min(a.nearest, b.nearest), std::max(a.farthest, b.farthest)};
}

const BoundsKernels& boundsKernels(raster::SimdLevel simd) {
    return raster::forSimdLevel(simd, boundsKernelsScalar, boundsKernelsAvx2, boundsKernelsAvx512);
}

// The bounds (receiver_bounds.h) of the pixels the map serves: chunks in parallel, each
// through the vector kernel and its tail through the scalar twin; minima and maxima merge
// exactly in any order.
BoundsResult servedBounds(const Light& light, const GBuffer& g, BoundsSpace space, const glm::dmat4& viewFromWorld,
                          raster::SimdLevel simd) {
    std::vector<uint8_t> inCone;
    if (light.type == LightType::Spot) {
        inCone.resize(g.pixelCount());
        tbb::parallel_for(size_t(0), g.pixelCount(), [&](size_t k) { inCone[k] = served(light, g, k); });
    }
    const uint8_t* servedBytes = inCone.empty() ? g.hit.data() : inCone.data();
    const float* positions = reinterpret_cast<const float*>(g.position.data());   // x, y, z per pixel
    const double* matrix = glm::value_ptr(viewFromWorld);
    const BoundsKernels &vector = boundsKernels(simd), &scalar = boundsKernelsScalar();
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, g.pixelCount(), 4096), emptyBounds(),
        [&](const tbb::blocked_range<size_t>& r, BoundsResult b) {
            const size_t body = r.size() / size_t(vector.width) * size_t(vector.width);
            vector.space[space]({positions + 3 * r.begin(), servedBytes + r.begin(), body, matrix}, b);
            const size_t tail = r.begin() + body;
            scalar.space[space]({positions + 3 * tail, servedBytes + tail, r.end() - tail, matrix}, b);
            return b;
        },
        [](BoundsResult a, const BoundsResult& b) {
            for (int c = 0; c < 3; ++c) a.lo[c] = std::min(a.lo[c], b.lo[c]), a.hi[c] = std::max(a.hi[c], b.hi[c]);
            a.behindApex = a.behindApex || b.behindApex;
            return a;
        });
}

// Tangents (perspective) or coordinates (orthographic) and depths of the served receivers.
Bounds receiverBounds(const Light& light, const GBuffer& g, const glm::dmat4& viewFromWorld, bool orthographic,
                      raster::SimdLevel simd) {
    const BoundsResult r = servedBounds(light, g, orthographic ? kOrthographicView : kPerspectiveView, viewFromWorld, simd);
    if (r.behindApex)
        throw std::invalid_argument("light view: a receiver lies beside or behind the light, where one perspective view "
                                    "cannot reach (shadow-map's cube faces can)");
    const Bounds b{r.lo[0], r.hi[0], r.lo[1], r.hi[1], r.lo[2], r.hi[2]};
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
            const double da = sideDistance(p, a), db = sideDistance(p, b);
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

glm::dvec3 inView(const WorldGeometry& world, const glm::dmat4& viewFromWorld, uint32_t vertex) {
    return glm::dvec3(viewFromWorld * glm::dvec4(glm::dvec3(world.positions[vertex]), 1.0));
}

constexpr uint8_t kInsideAll = 0xf;

// Each vertex once in the view: its depth (-z), and bit k set when it lies inside side plane
// k (sideDistance, as nearestInside() decides), in LightViewScratch's arrays.
void viewVertices(const WorldGeometry& world, const glm::dmat4& viewFromWorld, const SidePlanes& sides,
                  LightViewScratch& out) {
    out.depth.resize(world.positions.size()), out.insideBits.resize(world.positions.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, world.positions.size(), 16384), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const glm::dvec3 q = inView(world, viewFromWorld, uint32_t(i));
            uint8_t bits = 0;
            for (int k = 0; k < 4; ++k) bits |= uint8_t(sideDistance(sides.plane[k], q) >= 0.0) << k;
            out.depth[i] = -q.z, out.insideBits[i] = bits;
        }
    });
}

// The nearest geometry inside the sides, over all triangles; a minimum is exact and
// independent of the order, so the per-chunk minima can be combined in any order. A
// triangle with every corner inside every side is its own clipped polygon, so its nearest
// is its nearest corner's depth, the bits nearestInside() would return; only the others
// are clipped.
double nearestGeometry(const WorldGeometry& world, const glm::dmat4& viewFromWorld, const SidePlanes& sides,
                       LightViewScratch& vertices) {
    constexpr size_t kChunk = 16384;
    viewVertices(world, viewFromWorld, sides, vertices);
    const size_t chunks = (world.triangles.size() + kChunk - 1) / kChunk;
    std::vector<double> nearest(chunks, kInfinity);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        for (size_t t = c * kChunk; t < std::min(world.triangles.size(), (c + 1) * kChunk); ++t) {
            const glm::uvec3& corner = world.triangles[t];
            const auto& inside = vertices.insideBits;
            if ((inside[corner.x] & inside[corner.y] & inside[corner.z]) == kInsideAll) {
                nearest[c] = std::min({nearest[c], vertices.depth[corner.x], vertices.depth[corner.y], vertices.depth[corner.z]});
                continue;
            }
            const glm::dvec3 v[3] = {inView(world, viewFromWorld, corner.x), inView(world, viewFromWorld, corner.y),
                                     inView(world, viewFromWorld, corner.z)};
            nearest[c] = std::min(nearest[c], nearestInside(v, sides));
        }
    });
    return chunks ? *std::min_element(nearest.begin(), nearest.end()) : kInfinity;
}

// The margin of o.marginTexels around the receivers; a side of no width (one receiver, or
// receivers along a line the light looks across) first gets a width of 1e-6 of its
// coordinates' size, so the view's projection stays finite.
void widen(Bounds& b, const LightFitOptions& o) {
    const auto atLeastMinimum = [](double& low, double& high) {
        const double minimum = 1e-6 * std::max({1.0, std::abs(low), std::abs(high)});
        if (!(high - low >= minimum)) {
            const double middle = 0.5 * (low + high);
            low = middle - 0.5 * minimum, high = middle + 0.5 * minimum;
        }
    };
    atLeastMinimum(b.x0, b.x1), atLeastMinimum(b.y0, b.y1);
    const double mx = (b.x1 - b.x0) * o.marginTexels / o.resolution, my = (b.y1 - b.y0) * o.marginTexels / o.resolution;
    b.x0 -= mx, b.x1 += mx, b.y0 -= my, b.y1 += my;
}

// Near and far from the receivers and the geometry in front of them.
void fitDepthRange(LightView& view, const Bounds& b, const WorldGeometry& world, const LightFitOptions& o) {
    view.zFar = b.farthest * (1.0 + 1e-4) + (view.orthographic ? 1e-4 : 0.0);
    LightViewScratch own;
    const double occluder =
        nearestGeometry(world, view.viewFromWorld, sidePlanes(b, view.orthographic), o.scratch ? *o.scratch : own);
    double zNear = std::min(occluder, b.nearest);
    if (!view.orthographic) zNear = std::max(zNear * (1.0 - 1e-4), view.zFar * o.minNearFraction);
    else zNear -= 1e-4 * (view.zFar - zNear) + 1e-4;
    view.zNear = zNear;
}

LightView perspectiveView(const Light& light, const glm::dvec3& axis, const GBuffer& g, const WorldGeometry& world,
                          const LightFitOptions& o) {
    LightView view;
    const glm::dvec3 apex(light.position);
    view.viewFromWorld = glm::lookAtRH(apex, apex + axis, lookAtUp(axis));
    Bounds b = receiverBounds(light, g, view.viewFromWorld, false, o.simd);
    widen(b, o);
    fitDepthRange(view, b, world, o);
    const double n = view.zNear;
    view.clipFromView = glm::frustumRH_NO(b.x0 * n, b.x1 * n, b.y0 * n, b.y1 * n, n, view.zFar);
    return view;
}

// The distance from `from` to the farthest vertex, which no depth in a view from there
// exceeds; at least 1 m, so that a frustum has depth.
double farthestVertex(const WorldGeometry& world, const glm::dvec3& from) {
    double farthest = 1.0;
    for (const glm::vec3& p : world.positions) farthest = std::max(farthest, glm::length(glm::dvec3(p) - from));
    return farthest;
}

}  // namespace

bool insideCubeFace(const LightView& face, const glm::dvec3& P) {
    const glm::dvec3 q(face.viewFromWorld * glm::dvec4(P, 1.0));
    return -q.z > 0.0 && std::abs(q.x) <= -q.z && std::abs(q.y) <= -q.z;
}

LightView fitLightView(const Light& light, const GBuffer& receivers, const WorldGeometry& world,
                       const LightFitOptions& options) {
    if (light.type == LightType::Disk || light.type == LightType::Rectangle) {
        throw std::invalid_argument("light view: an area light has no single view; use its centre (pointLightFor)");
    }
    if (light.type != LightType::Directional) {
        // Aim along options.axis or at the centre of the receivers' bounding box, then fit the
        // sides around them.
        const BoundsResult box = servedBounds(light, receivers, kWorldBox, glm::dmat4(1.0), options.simd);
        const glm::dvec3 lo(box.lo[0], box.lo[1], box.lo[2]), hi(box.hi[0], box.hi[1], box.hi[2]);
        if (lo.x > hi.x) throw std::invalid_argument("light view: no receivers (no pixel has hit = 1, or none in the spot's cone)");
        const glm::dvec3 axis = options.axis != glm::dvec3(0.0) ? options.axis : 0.5 * (lo + hi) - glm::dvec3(light.position);
        return perspectiveView(light, glm::normalize(axis), receivers, world, options);
    }
    LightView view;
    view.orthographic = true;
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(light.direction));
    // The eye sits anywhere on the light's side; depths are then measured from it.
    view.viewFromWorld = glm::lookAtRH(glm::dvec3(0.0), -towardsLight, lookAtUp(towardsLight));
    // Depths here may be negative (the eye is anywhere on the light's side): the farthest is
    // the largest of them, not of them and 0.
    Bounds b = receiverBounds(light, receivers, view.viewFromWorld, true, options.simd);
    widen(b, options);
    fitDepthRange(view, b, world, options);
    view.clipFromView = glm::orthoRH_NO(b.x0, b.x1, b.y0, b.y1, view.zNear, view.zFar);
    return view;
}

LightView fitLightViewToWorld(const Light& light, const WorldGeometry& world, const LightFitOptions& options) {
    LightViewScratch own;
    LightViewScratch& scratch = options.scratch ? *options.scratch : own;
    // Every vertex a receiver: the sides hold the world's outermost vertices.
    GBuffer& everyVertex = scratch.everyVertex;
    everyVertex.width = int(world.positions.size()), everyVertex.height = 1;
    everyVertex.hit.assign(world.positions.size(), 1);
    everyVertex.position.assign(world.positions.begin(), world.positions.end());
    // The near plane at the world's box (its nearest point inside the sides), which holds every
    // vertex: a caster that moves inside the box does not move it.
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : world.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    WorldGeometry& box = scratch.worldBox;
    box.positions.clear();
    for (int c = 0; c < 8; ++c) box.positions.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    box.triangles.assign({{0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}, {0, 1, 5}, {0, 5, 4},
                          {2, 6, 7}, {2, 7, 3}, {0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}});   // two per face
    return fitLightView(light, everyVertex, box, options);
}

glm::dmat4 cubeFaceViewFromWorld(const glm::dvec3& apex, int face) {
    static const glm::dvec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::dvec3 kUps[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return glm::lookAtRH(apex, apex + kAxes[face], kUps[face]);
}

bool fitCubeFace(const Light& light, int face, const GBuffer& receivers, const WorldGeometry& world,
                 const LightFitOptions& options, LightView& view) {
    const glm::dvec3 apex(light.position);
    view = {};
    view.viewFromWorld = cubeFaceViewFromWorld(apex, face);
    // The face's receivers: those inside its 90-degree pyramid.
    const auto add = [&](Bounds& b, size_t k) {
        const glm::dvec3 P(receivers.position[k]);
        if (insideCubeFace(view, P)) {
            const double depth = -(view.viewFromWorld * glm::dvec4(P, 1.0)).z;
            b.nearest = std::min(b.nearest, depth), b.farthest = std::max(b.farthest, depth);
        }
    };
    Bounds b = overServedPixels(light, receivers, Bounds{}, add, merged);   // a point light serves every surface
    b.x0 = b.y0 = -1.0, b.x1 = b.y1 = 1.0;
    if (!(b.farthest > 0.0)) {
        if (options.cullCubeFaces) return false;
        b.nearest = b.farthest = farthestVertex(world, apex);
    }
    fitDepthRange(view, b, world, options);
    view.clipFromView = glm::frustumRH_NO(-view.zNear, view.zNear, -view.zNear, view.zNear, view.zNear, view.zFar);
    return true;
}

std::string LightViews::suffix(size_t v) const {
    return faces.empty() ? "" : std::string("-face-") + kCubeFaceNames[faces[v]];
}

LightViews fitLightViews(const Light& light, const GBuffer& receivers, const WorldGeometry& world,
                         const LightFitOptions& options) {
    LightViews out;
    try {
        out.views.push_back(fitLightView(light, receivers, world, options));
        return out;
    } catch (const std::invalid_argument&) {
        if (light.type != LightType::Point) throw;   // no receivers, or a spot light's cone is too wide
    }
    for (int face = 0; face < 6; ++face) {   // receivers all around the light
        LightView view;
        if (!fitCubeFace(light, face, receivers, world, options, view)) continue;
        out.views.push_back(view);
        out.faces.push_back(face);
    }
    return out;
}

}  // namespace shadowlab
