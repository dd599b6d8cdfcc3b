// The depth map an area light's soft-shadow techniques share (pcss, vsm, esm, evsm, msm):
// one perspective map drawn from the light's centre (Real-Time Rendering, 4th ed., 7.6:
// PCSS and the filtered maps "treat the light as a point for the map and widen the filter
// for its area"), fitted to the visible receivers (light_view.h), plus what they need on
// top of window depth:
//
//   linear depth  the view-space distance d of each texel, and its normalised form
//                 z = (d - near) / (far - near) in [0, 1], which the filtered maps store
//                 (RTR 7.7: "z-depths can be generated so that they are linear"). Empty
//                 texels (window depth 1) get z = 1, the far plane, behind every receiver.
//   light width   w_light of eq. 7.6 in map texels: the light's extent along the map's
//                 x and y axes (its support width: for a disk 2 r sqrt(1 - (n.e)^2), for a
//                 rectangle 2 (|U.e| + |V.e|)), projected at unit distance.
//
// Eq. 7.6 gives the sample width on the occluder's plane, w_sample = w_light (d_r - d_o)
// / d_r (metres); seen from the light's centre at distance d_o it spans w_sample / d_o
// radians of the map, so in texels w = lightTexels (d_r - d_o) / (d_r d_o). The blocker
// search region is the same cone cut at the near plane (Fernando 2005, section 3.1:
// "the search region ... depends on the light size and the distance to the receiver"):
// the width for d_o = near, which holds every texel an occluder can shadow P from.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "raster/tile_kernels.h"
#include "shading/gbuffer.h"
#include "shading/lights.h"
#include "shadows/depth_map.h"
#include "shadows/technique.h"

namespace shadowlab {

// The `resolution` these techniques default to. A disk light of radius 0.5 m over the
// built-in scenes casts penumbrae 5 to 40 texels wide at this size, so the filters, not the
// texels, set the shadow's softness.
inline constexpr int kSoftMapResolution = 1024;

struct SoftShadowMap {
    DepthMap map;                      // window depth from the light's centre
    std::vector<float> linear;         // normalised linear depth z in [0, 1] per texel
    glm::dvec2 lightTexels{0.0};       // w_light in texels at unit distance, per map axis
    Light light;                       // the area light
    glm::dvec3 lightCentre{0.0};       // world space, the map's eye

    double zNear() const { return map.view.zNear; }
    double zFar() const { return map.view.zFar; }
    // Normalised linear depth of a view-space distance d (metres).
    double normalised(double distance) const { return (distance - zNear()) / (zFar() - zNear()); }
    // View-space distance (metres) of a stored window depth.
    double distanceOf(float windowDepth) const;
};

// A camera pixel's surface point as the map sees it.
struct SoftReceiver {
    glm::dvec2 texel{0.0};             // where it falls, texel units
    double distance = 0.0;             // d_r: view-space distance from the light's centre, m
};

// Throws std::invalid_argument naming the technique unless the light is a disk or a
// rectangle: what every technique of this family needs, checked before any other work.
void requireAreaLight(const Light& light, const std::string& technique);

// Throws std::invalid_argument unless the light is a disk or a rectangle. The receivers
// stay marginTexels inside the map's sides, and with coverBlockerSearch also the widest
// blocker search region (whose taps would otherwise read clamped border texels). The map is
// the technique's state (in.kept(), technique_history.h): each frame draws it into the last
// frame's memory, so a steady state allocates neither the map nor its linear depth.
const SoftShadowMap& renderSoftShadowMap(const ShadowInputs& in, int resolution, const raster::PolygonOffset& offset,
                                         double marginTexels, bool coverBlockerSearch);

SoftReceiver softReceiver(const SoftShadowMap& soft, const glm::dvec3& P);

// Calls perPixel(row, k, P, N, receiver) for every camera pixel k whose surface faces the
// light's centre (lightReaches: dot(N, centre - P) > 0; the others keep V = 0), rows in
// parallel, then endOfRow(row): the pixels of a row share one RowState, so a pass can finish
// them together (the map lookups of the whole row, then a run of the moments' visibility).
// Each thread works in its own RowState of `perThread` (resized to the arena's threads),
// emptied (row.clear(), which keeps the memory) before each row: a caller that keeps them
// between frames (technique_history.h) allocates no row buffers in a steady state. perPixel
// and endOfRow must not wait on parallel work (another row could then take the thread's
// RowState). Each call writes only its own pixels' outputs, so the results are the same for
// any thread count.
template <class RowState, class PerPixel, class EndOfRow>
void forEachReceiverFacingLight(const GBuffer& g, const SoftShadowMap& soft, std::vector<RowState>& perThread,
                                PerPixel perPixel, EndOfRow endOfRow) {
    const LightReach reaches(soft.light);
    perThread.resize(size_t(tbb::this_task_arena::max_concurrency()));
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        RowState& row = perThread[size_t(tbb::this_task_arena::current_thread_index())];
        for (int j = rows.begin(); j < rows.end(); ++j) {
            row.clear();
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                if (!g.hit[k] || !reaches(g.position[k], g.normal[k])) continue;
                const glm::dvec3 P(g.position[k]), N(g.normal[k]);
                perPixel(row, k, P, N, softReceiver(soft, P));
            }
            endOfRow(row);
        }
    });
}

// Eq. 7.6 in texels per map axis: the width of the light's cone from a receiver at
// distance dr, on the plane at distance dOccluder (both m, 0 < dOccluder < dr).
glm::dvec2 sampleWidthTexels(const SoftShadowMap& soft, double dr, double dOccluder);

// Texels [x0, x1] x [y0, y1], inclusive.
struct TexelRect {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};

// The texels of that cone about a receiver at texel position `texel`, clamped to the map:
// the region a blocker search reads (dOccluder = near plane: every texel that can shadow it).
TexelRect coneTexels(const SoftShadowMap& soft, const glm::dvec2& texel, double dr, double dOccluder);

}  // namespace shadowlab
