// The irregular z-buffer: exact hard shadows by rasterizing occluders at the camera's own
// samples (Aila and Laine 2004, "Alias-Free Shadow Maps", EGSR; Johnson et al. 2005,
// "The irregular Z-buffer", ACM TOG 24(4); Real-Time Rendering, 4th ed., section 7.9).
//
// A shadow map samples the light's view on a regular grid and then asks it questions at
// other points, the camera's samples, which is where its aliasing and bias come from. The
// irregular z-buffer asks the questions at the camera's samples themselves:
//   1. receivers  (receivers.cpp): every G-buffer point that faces the light becomes a
//      shadow-ray origin; points facing away are shadowed without a test (Wyman et al.'s
//      culling, RTR4 7.9);
//   2. light grid (light_grid.cpp): the light's view fitted to the receivers (one
//      frustum, or the cube faces around a point light that is surrounded), each receiver
//      projected into it once (placeReceivers), and a resolution chosen from the
//      receivers' density;
//   3. lists      (lists.cpp): each texel lists the receivers that project into it,
//      built by a counting sort, so every list is in pixel order (RTR4 Figure 7.30, lower
//      left); the receivers are then copied in list order, so a texel's, and a row of
//      texels', are consecutive;
//   4. coverage   (coverage.cpp): each occluder's conservative footprint in the grid,
//      every texel whose closed square its projection touches (RTR4 Figure 7.30, lower
//      right);
//   5. binning    (binning.cpp): occluders sorted into tiles of the grid;
//   6. occlusion  (occlusion.inl): the exact test of receivers against one triangle
//      (is the triangle on the segment from the receiver to the light?), a run of
//      consecutive receivers at once in SIMD lanes; a cut-out's triangle (a foliage card)
//      blocks only where its alpha texture is solid at the point the segment meets it,
//      the reference's own rule (caster_transmission.h);
//   7. traversal  (traversal.cpp): tiles in parallel, each testing its texels' receivers
//      against the occluders binned to it, one row of covered texels per kernel call.
// The result equals a ray tracer's up to floating-point ties, since it asks the same
// question per receiver: "It's really just a different ordering of the loops" (Lehtinen,
// Real-time shadows lecture, 2015).
//
// Determinism: a receiver's result is the OR of booleans over triangles, which no order can
// change; each tile owns its texels' receivers, so no two tasks write the same byte, and
// every count is an integer sum.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/framebuffer.h"
#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/caster_transmission.h"
#include "shadows/depth_map.h"
#include "shadows/izb/kernels.h"
#include "shadows/light_view.h"
#include "shadows/settings_table.h"
#include "shadows/technique.h"

namespace shadowlab {

// The technique's entry in techniques().
Technique irregularZBufferTechnique();

struct IzbSettings {
    std::optional<int> resolution;   // light grid texels per side; empty: chosen from the receivers
};

const SettingsTable<IzbSettings>& izbSettingsTable();

// The technique with typed settings, for a technique that runs it as a stage (izb-pcss);
// `in.params` are not read.
ShadowOutputs runIrregularZBuffer(const ShadowInputs& in, const IzbSettings& settings);

namespace izb {

// The vector kernels of stages 1 and 6 (kernels.h) for a SIMD level; throws
// std::invalid_argument where this CPU lacks it.
Kernels kernels(raster::SimdLevel simd);

// ---- 1. Receivers ------------------------------------------------------------------------
// A point or directional light as a homogeneous point (shading/lights.h, homogeneousLight()).
using HomogeneousLight = glm::dvec4;

// A camera sample that faces the light. It is shadowed when a triangle meets the segment
// origin + t * (light.xyz - light.w * origin), t in [0, tFar]. One record of 24 bytes, so
// moving it into list order (listReceivers) costs one scattered load, not three.
struct Receiver {
    glm::vec3 origin;                   // P moved along N by the reference's offset (reference.cpp), in float as its ray's
    uint32_t pixel;                     // index into the G-buffer
    double tFar;                        // the reference's end of the segment
};
// The receivers in pixel order, in uninitialised storage (each is written once, and a frame
// has up to a million of them).
using Receivers = raster::BufferStorage<Receiver>;

// Fills `visibility` (one float per pixel): 0 where hit = 0, where the light is behind the
// surface (dot(N, L - P) <= 0) or outside a spot cone; 1 elsewhere, and returns the points
// still to be tested. A point light nearer than the offset is seen (as by the reference).
// `simd` picks the segments kernel; every level gives the same bytes.
Receivers gatherReceivers(const GBuffer& gbuffer, const Light& pointOrDirectional, double sceneDiagonal,
                          std::vector<float>& visibility, raster::SimdLevel simd);

// ---- 2. Light grid -------------------------------------------------------------------------
// One or six light views, each divided into resolution x resolution texels. Texel
// coordinates (u, v) run over [0, resolution]^2, u right, v down (row 0 at the top,
// conventions.md); texel (i, j) covers [i, i + 1] x [j, j + 1].
//
// Texels are numbered tile by tile: the grid is cut into tiles of kTileSize^2 texels (the
// traversal's unit of parallel work), each numbered row by row, tiles in row order, views
// one after the other. A tile's texels are then consecutive numbers and so, once the
// receivers are in list order, are its receivers: the camera samples of one small patch of
// the light's view, which lie close together in the G-buffer as well.
inline constexpr int kTileSize = 32;   // texels per side of a tile

// The tiles per side for a resolution, and texel (i, j) of `view`'s number.
inline int tilesPerSide(int resolution) { return (resolution + kTileSize - 1) / kTileSize; }
inline size_t texelIndex(int resolution, int view, int i, int j) {
    const size_t side = size_t(tilesPerSide(resolution));
    const size_t tile = (size_t(view) * side + size_t(j / kTileSize)) * side + size_t(i / kTileSize);
    return tile * kTileSize * kTileSize + size_t(j % kTileSize) * kTileSize + size_t(i % kTileSize);
}

struct LightGrid {
    std::vector<LightView> views;
    std::vector<glm::dmat4> clipFromWorld;   // per view, computed once (projectOccluder runs per tile)
    int resolution = 0;
    // Perspective views drop occluder parts nearer the light than this depth (view-space
    // -z), a thousandth of the reference's smallest offset (coverage.cpp).
    double minDepth = 0.0;
    // Texel numbers run over [0, texelCount()): the tiles at the right and bottom edges are
    // whole, so numbers of texels beyond the resolution exist but never hold a receiver.
    size_t texelCount() const {
        return views.size() * size_t(tilesPerSide(resolution)) * size_t(tilesPerSide(resolution)) * kTileSize * kTileSize;
    }
    size_t texelIndex(int view, int i, int j) const { return izb::texelIndex(resolution, view, i, j); }
};

// The views that hold every receiver: fitLightViews() (light_view.h: one frustum, or the
// cube faces when the receivers surround a point light) with the largest grid's margin.
// Throws std::invalid_argument when there are no receivers.
std::vector<LightView> fitViews(const Light& pointOrDirectional, const GBuffer& gbuffer, const WorldGeometry& world,
                               raster::SimdLevel simd);

// Where the receivers lie in the views, found once and reused by chooseResolution and the
// lists: each receiver's view and its texel coordinates over the resolution, (u, v) / R in
// [0, 1]^2, so that its texel at any resolution costs two products (Johnson et al. 2005
// store each sample's light-space position once for the same reason).
struct ReceiverPlaces {
    raster::BufferStorage<uint8_t> view;   // uninitialised storage, as Receivers
    raster::BufferStorage<glm::dvec2> unitUV;
    size_t size() const { return view.size(); }
};
ReceiverPlaces placeReceivers(const std::vector<LightView>& views, const Receivers& receivers);

// The resolution whose mean non-empty list holds about `targetListLength` receivers
// (light_grid.cpp), within [kMinMapResolution, kMaxMapResolution] (depth_map.h).
int chooseResolution(size_t viewCount, const ReceiverPlaces& places, double targetListLength);

LightGrid makeLightGrid(std::vector<LightView> views, int resolution, double sceneDiagonal);

// The texel whose closed square holds a placed receiver; a point on the far edge
// u = resolution belongs to the last texel. Receivers always lie inside a view.
raster::BufferStorage<uint32_t> receiverTexels(int resolution, const ReceiverPlaces& places);
// The same for one point, placed on the spot.
uint32_t texelOf(const LightGrid& grid, const glm::dvec3& point);

// ---- 3. Lists ------------------------------------------------------------------------------
// Items grouped by a key: bucket b holds entry[first[b]] .. entry[first[b + 1] - 1].
struct Buckets {
    // Uninitialised storage, as Receivers: the sort writes every element once.
    raster::BufferStorage<uint32_t> first;    // keyCount + 1 offsets (exclusive prefix sum of the counts)
    raster::BufferStorage<uint32_t> entry;
    uint32_t length(size_t bucket) const { return first[bucket + 1] - first[bucket]; }
};
// Counting sort: count per key, exclusive prefix sum, scatter in item order, so each bucket
// keeps its items in their original order, for any number of threads (lists.cpp sorts by
// groups of keys, then each group, both in parallel). Entries are value[k], or the item
// index k itself when `value` is empty.
Buckets countingSort(std::span<const uint32_t> key, size_t keyCount, std::span<const uint32_t> value = {});

// A texel's bucket lists its receivers (indices into Receivers), in pixel order.
using TexelLists = Buckets;
inline TexelLists buildTexelLists(std::span<const uint32_t> texelOfReceiver, size_t texelCount) {
    return countingSort(texelOfReceiver, texelCount);
}

// The receivers in list order: receiver e here is Receivers' lists.entry[e], so texel t's
// are e in [lists.first[t], lists.first[t + 1]), and a tile's, and a row of a tile's, are
// consecutive too. Structure of arrays, as the traversal's vector test reads them, each
// array followed by kKernelPadding zeros (kernels.h); no other clearing, since copying is
// this stage's whole cost and it is bound by memory traffic.
struct ListedReceivers {
    raster::BufferStorage<float> x, y, z;
    raster::BufferStorage<double> tFar;
    raster::BufferStorage<uint32_t> pixel;   // index into the G-buffer
    size_t size() const { return pixel.size(); }
};
ListedReceivers listReceivers(const Receivers& receivers, const TexelLists& lists);

// ---- 4. Coverage ---------------------------------------------------------------------------
// A triangle's part in a view, clipped and projected to texel coordinates (a convex polygon
// of up to 3 + 5 vertices; count 0 when nothing of it lies in the view).
struct LightPolygon {
    int count = 0;
    glm::dvec2 vertex[8];
};
LightPolygon projectOccluder(const LightGrid& grid, int view, const glm::dvec3 (&triangle)[3]);

// The occluders as binning and traversal read them: the world's triangles, and every vertex
// projected into each view once (its texel coordinates, when it lies inside all of the
// view's clipping half-spaces), so that a triangle wholly inside costs no clipping.
struct ProjectedOccluders {
    const WorldGeometry& world;
    size_t vertexCount;
    std::vector<glm::dvec2> texel;   // [view * vertexCount + vertex], valid where inside
    std::vector<uint8_t> inside;     // 1: inside every half-space of the view
    // projectOccluder() of the triangle, from the projected corners when all are inside.
    LightPolygon polygon(const LightGrid& grid, int view, uint32_t triangle) const;
};
ProjectedOccluders projectOccluders(const LightGrid& grid, const WorldGeometry& world);

// Half-open range of rows or columns.
struct TexelRange {
    int begin = 0, end = 0;
    bool empty() const { return begin >= end; }
};
// Rows whose closed band the polygon touches, within [0, resolution).
TexelRange coveredRows(const LightPolygon& polygon, int resolution);
// Columns whose closed squares the polygon touches within the band v in [v0, v1].
TexelRange coveredColumns(const LightPolygon& polygon, double v0, double v1, int resolution);

// ---- 5. Binning ----------------------------------------------------------------------------
// Triangle indices per tile (tile index: (view * tilesPerSide + ty) * tilesPerSide + tx, the
// texel numbers' order), in increasing order, for tiles holding at least one receiver.
struct TileBins {
    int tilesPerSide = 0;
    Buckets triangles;              // one bucket per tile
};
TileBins binOccluders(const LightGrid& grid, const TexelLists& lists, const ProjectedOccluders& occluders);

// ---- 6. Occlusion --------------------------------------------------------------------------
// True if the triangle meets the segment origin + t * towardsLight, t in [0, tFar]: the
// scalar build of the test the traversal runs over many receivers (kernels.h).
bool segmentBlocked(const glm::dvec3& origin, const glm::dvec3& towardsLight, double tFar,
                    const glm::dvec3 (&triangle)[3]);

// ---- 7. Traversal --------------------------------------------------------------------------
struct Occlusion {
    std::vector<uint8_t> blocked;          // per listed receiver
    std::vector<uint32_t> occluders;       // per texel: triangles tested against its receivers
    uint64_t texelPairs = 0;               // (texel with receivers, triangle) pairs visited
    uint64_t segmentTests = 0;             // (receiver, triangle) pairs tested
    uint64_t cutOutHits = 0;               // segments meeting a cut-out triangle, then alpha-tested
};
// `cutOuts`: the casters' materials, whose cut-out triangles (WorldGeometry::triangleCutOut)
// block only where CasterTransmission::solidAt is; null, or a world without cut-outs: every
// triangle is solid. `simd` picks the kernels; every level gives the same bytes.
Occlusion traverseOccluders(const LightGrid& grid, const HomogeneousLight& light, const ListedReceivers& receivers,
                            const TexelLists& lists, const TileBins& bins, const ProjectedOccluders& occluders,
                            const CasterTransmission* cutOuts, raster::SimdLevel simd);

}  // namespace izb
}  // namespace shadowlab
