#include "shadows/deep/light_layers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "raster/rasterizer.h"
#include "shading/luminance.h"
#include "shadows/volume_march.h"
#include "shadows/world_draw.h"

namespace shadowlab {
namespace {

// The casters' triangles as the two passes draw them (world triangle indices); a cut-out
// is drawn with its holes in either (world_draw.h).
struct CasterSplit {
    std::vector<uint32_t> opaque, translucent;
};

CasterSplit splitCasters(const WorldGeometry& world, const CasterTransmission& transmission) {
    CasterSplit split;
    for (uint32_t t = 0; t < world.triangles.size(); ++t) {
        (transmission.materialOf(t).translucent() ? split.translucent : split.opaque).push_back(t);
    }
    return split;
}

struct Event {
    float near, far, opticalDepth;
    glm::vec3 passed;
    uint32_t triangle;
};

bool nearerEvent(const Event& a, const Event& b) {
    if (a.near != b.near) return a.near < b.near;
    if (a.triangle != b.triangle) return a.triangle < b.triangle;   // a surface before a volume piece
    return a.far < b.far;
}

// The translucent surfaces per texel, each texel's in (depth, triangle) order: a counting
// sort of every tile's list, then a sort within each texel (the tile lists are in drawing
// order, which is the same on every thread count, but a texel wants front to back). A
// tile's fragments lie on its own texels, so the tiles count and fill in parallel, each
// writing only its texels' entries, in its list's order: the same bytes for any thread count.
struct TexelSurfaces {
    std::vector<uint32_t> start;
    std::vector<Event> events;
};

TexelSurfaces gatherSurfaces(const raster::Framebuffer& fb, const CasterTransmission& transmission) {
    const int size = fb.width(), tiles = fb.tilesX() * fb.tilesY();
    TexelSurfaces out;
    out.start.assign(size_t(size) * size_t(size) + 1, 0);
    const auto texelIndex = [&](const raster::Fragment& f) {
        return raster::rowMajorIndexOf(f.pixel, fb.tilesX(), size);
    };
    tbb::parallel_for(0, tiles, [&](int tile) {
        for (const raster::Fragment& f : fb.tileFragments(tile)) ++out.start[texelIndex(f) + 1];
    });
    for (size_t k = 1; k < out.start.size(); ++k) out.start[k] += out.start[k - 1];
    out.events.resize(out.start.back());
    std::vector<uint32_t> next(out.start.begin(), out.start.end() - 1);
    tbb::parallel_for(0, tiles, [&](int tile) {
        for (const raster::Fragment& f : fb.tileFragments(tile)) {
            const uint32_t triangle = f.primitiveId;
            const glm::vec3 passed = transmission.materialOf(triangle).passed();
            const double y = std::max(double(luminance(passed)), 1e-12);
            out.events[next[texelIndex(f)]++] = {f.depth, f.depth, float(-portable::log(y)), passed, triangle};
        }
    });
    tbb::parallel_for(size_t(0), out.start.size() - 1, [&](size_t t) {
        std::sort(out.events.begin() + out.start[t], out.events.begin() + out.start[t + 1], nearerEvent);
    });
    return out;
}

// Where each texel's march through the volumes starts and how it is cut. The near plane is
// fitted to triangles, not to volumes, so the march starts in front of it: for a
// directional light at the window depth of the volumes' nearest corner (depth is affine in
// distance there); for a point or spot light at a hundredth of the way from the light to
// the near plane (its window depth is finite, about -99 for a far plane far beyond).
struct VolumeMarch {
    std::span<const DensityVolume> volumes;
    bool perspective = false;
    glm::dvec3 apex{0.0};     // the light, for a perspective view
    double startDepth = 0.0;  // window depth where an orthographic march starts
};

VolumeMarch volumeMarch(const DepthMap& map, std::span<const DensityVolume> volumes) {
    VolumeMarch march{volumes, !map.view.orthographic, glm::dvec3(glm::inverse(map.view.viewFromWorld)[3]), 0.0};
    for (const DensityVolume& v : volumes) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p(corner & 1 ? v.max.x : v.min.x, corner & 2 ? v.max.y : v.min.y,
                               corner & 4 ? v.max.z : v.min.z);
            const glm::dvec4 q = map.texelFromWorld * glm::dvec4(p, 1.0);
            march.startDepth = std::min(march.startDepth, q.z / q.w);
        }
    }
    return march;
}

// How many pieces a voxel crossing of optical depth tau from distance d0 to d1 (from a
// perspective light) is cut into: each of optical depth at most kMaxPieceOpticalDepth, and
// from a perspective light each at most 5% longer than its distance from the light, so that
// tau, linear in distance, stays within about 1% of linear in window depth (which is affine in
// 1 / distance) across a piece. At most 256: past an optical depth of 25 no light is left.
int piecesFor(double tau, double d0, double d1, bool perspective) {
    double pieces = std::ceil(tau / kMaxPieceOpticalDepth);
    if (perspective && d0 > 0.0) pieces = std::max(pieces, std::ceil((d1 - d0) / (0.05 * d0)));
    return int(std::clamp(pieces, 1.0, 256.0));
}

// The pieces of volume along texel (x, y)'s ray, from the march's start to depth `stop`,
// appended nearest first.
void marchTexel(const DepthMap& map, const VolumeMarch& march, int x, int y, float stop, std::vector<Event>& out) {
    const auto worldAt = [&](double z) {
        const glm::dvec4 p = map.worldFromTexel * glm::dvec4(x + 0.5, y + 0.5, z, 1.0);
        return glm::dvec3(p) / p.w;
    };
    const auto depthOf = [&](const glm::dvec3& p) {
        const glm::dvec4 q = map.texelFromWorld * glm::dvec4(p, 1.0);
        return float(q.z / q.w);
    };
    const glm::dvec3 a =
        march.perspective ? march.apex + 0.01 * (worldAt(0.0) - march.apex) : worldAt(march.startDepth);
    const glm::dvec3 b = worldAt(double(stop));
    const double length = glm::length(b - a);
    const double fromApex = march.perspective ? glm::length(a - march.apex) : 0.0;
    const size_t first = out.size();
    for (const DensityVolume& volume : march.volumes) {
        marchVoxels(volume, a, b, [&](double t0, double t1, double sigma) {
            const double tau = sigma * (t1 - t0) * length;
            if (tau <= 0.0) return;
            const int pieces = piecesFor(tau, fromApex + t0 * length, fromApex + t1 * length, march.perspective);
            const float passed = float(portable::exp(-tau / pieces));
            for (int k = 0; k < pieces; ++k) {
                const double s0 = t0 + (t1 - t0) * k / pieces, s1 = t0 + (t1 - t0) * (k + 1) / pieces;
                out.push_back({depthOf(a + s0 * (b - a)), depthOf(a + s1 * (b - a)), float(tau / pieces),
                               glm::vec3(passed), VolumetricLayers::kVolumePiece});
            }
        });
    }
    std::sort(out.begin() + ptrdiff_t(first), out.end(), nearerEvent);
}

// Every texel's surfaces and volume pieces merged, nearest first, into the layers' arrays:
// the rows gather their events in parallel, and once every texel's count is known each row
// copies its events to their place, in parallel too. The figures over all events are
// reduced per row and combined in row order (integer sums, least and greatest: exact), so
// the bytes are the same for any thread count.
void mergeEvents(const TexelSurfaces& surfaces, std::span<const DensityVolume> volumes, VolumetricLayers& layers) {
    const VolumeMarch march = volumeMarch(layers.opaque, volumes);
    const int size = layers.size();
    std::vector<std::vector<Event>> rows(static_cast<size_t>(size));
    std::vector<uint32_t> counts(size_t(size) * size_t(size));
    tbb::parallel_for(0, size, [&](int y) {
        std::vector<Event> pieces;
        for (int x = 0; x < size; ++x) {
            const size_t t = size_t(y) * size_t(size) + size_t(x);
            pieces.clear();
            if (!volumes.empty()) marchTexel(layers.opaque, march, x, y, layers.opaque.at(x, y), pieces);
            const size_t before = rows[size_t(y)].size();
            std::merge(surfaces.events.begin() + surfaces.start[t], surfaces.events.begin() + surfaces.start[t + 1],
                       pieces.begin(), pieces.end(), std::back_inserter(rows[size_t(y)]), nearerEvent);
            counts[t] = uint32_t(rows[size_t(y)].size() - before);
        }
    });
    layers.start.assign(counts.size() + 1, 0);
    uint64_t total = 0;
    for (size_t t = 0; t < counts.size(); ++t) {
        total += counts[t];
        if (total > UINT32_MAX)
            throw std::length_error("the light's layers hold more than 2^32 events: lower the resolution");
        layers.start[t + 1] = uint32_t(total);
    }
    layers.depthNear.resize(total), layers.depthFar.resize(total), layers.opticalDepth.resize(total);
    layers.passed.resize(total), layers.triangle.resize(total);
    struct RowFigures {
        uint64_t volumePieces = 0;
        float nearest = 1.0f, farthest = 0.0f;
    };
    std::vector<RowFigures> figures(static_cast<size_t>(size));
    tbb::parallel_for(0, size, [&](int y) {
        size_t e = layers.start[size_t(y) * size_t(size)];
        RowFigures& f = figures[size_t(y)];
        for (const Event& event : rows[size_t(y)]) {
            layers.depthNear[e] = event.near, layers.depthFar[e] = event.far;
            layers.opticalDepth[e] = event.opticalDepth, layers.passed[e] = event.passed;
            layers.triangle[e] = event.triangle;
            ++e;
            f.volumePieces += event.triangle == VolumetricLayers::kVolumePiece;
            f.nearest = std::min(f.nearest, event.near), f.farthest = std::max(f.farthest, event.far);
        }
    });
    for (const RowFigures& f : figures) {
        layers.volumePieces += f.volumePieces;
        layers.nearestDepth = std::min(layers.nearestDepth, f.nearest);
        layers.farthestDepth = std::max(layers.farthestDepth, f.farthest);
    }
}

}  // namespace

VolumetricLayers renderVolumetricLayers(const ShadowInputs& in, const LightView& view,
                                        const CasterTransmission& transmission,
                                        const VolumetricLayerSettings& settings) {
    const WorldGeometry& world = in.casterWorld();
    const CasterSplit split = splitCasters(world, transmission);
    const glm::mat4 clipFromWorld(view.clipFromWorld());

    raster::Framebuffer fb(settings.resolution, settings.resolution, {.fragments = true});
    raster::Rasterizer rasterizer(in.simd);
    raster::PipelineState opaque;
    opaque.cull = raster::CullMode::None;
    opaque.offset = settings.opaqueOffset;
    if (!split.opaque.empty()) drawWorld(rasterizer, fb, opaque, world, clipFromWorld, split.opaque);
    raster::PipelineState translucent;
    translucent.cull = raster::CullMode::None;
    translucent.depth.write = false;
    translucent.output = raster::FragmentOutput::FragmentList;
    if (!split.translucent.empty()) drawWorld(rasterizer, fb, translucent, world, clipFromWorld, split.translucent);

    VolumetricLayers layers;
    DepthMap& map = layers.opaque;
    map.size = settings.resolution;
    map.tilesX = fb.tilesX();
    map.view = view;
    map.texelFromWorld = texelFromWorldOf(clipFromWorld, map.size);
    map.worldFromTexel = glm::inverse(map.texelFromWorld);
    map.depth = fb.takeDepth();
    const TexelSurfaces surfaces = gatherSurfaces(fb, transmission);
    layers.translucentFragments = surfaces.events.size();
    mergeEvents(surfaces, transmission.volumes(), layers);
    return layers;
}

}  // namespace shadowlab
