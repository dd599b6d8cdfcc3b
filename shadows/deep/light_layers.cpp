#include "shadows/deep/light_layers.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "raster/rasterizer.h"
#include "shading/luminance.h"
#include "shadows/light_view.h"
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

// The texel of storage index `index` of a block-linear buffer (raster::blockLinearIndex).
glm::ivec2 texelOfStorage(uint32_t index, int tilesX) {
    using namespace raster;
    const uint32_t tile = index / kPixelsPerTile, inTile = index % kPixelsPerTile;
    const uint32_t block = inTile / kPixelsPerBlock, inBlock = inTile % kPixelsPerBlock;
    const int x = int(tile % uint32_t(tilesX)) * kTileSize + int(block % kBlocksPerTileSide) * kBlockSize;
    const int y = int(tile / uint32_t(tilesX)) * kTileSize + int(block / kBlocksPerTileSide) * kBlockSize;
    return {x + int(inBlock % kBlockSize), y + int(inBlock / kBlockSize)};
}

struct Event {
    float near, far, opticalDepth;
    glm::vec3 passed;
    uint32_t triangle;
};

bool nearerEvent(const Event& a, const Event& b) {
    if (a.near != b.near) return a.near < b.near;
    return a.triangle < b.triangle;   // a surface before a volume piece at the same depth
}

// The translucent surfaces per texel, each texel's in (depth, triangle) order: a counting
// sort of every tile's list, then a sort within each texel (the tile lists are in drawing
// order, which is the same on every thread count, but a texel wants front to back).
struct TexelSurfaces {
    std::vector<uint32_t> start;
    std::vector<Event> events;
};

TexelSurfaces gatherSurfaces(const raster::Framebuffer& fb, const CasterTransmission& transmission) {
    const int size = fb.width(), tiles = fb.tilesX() * fb.tilesY();
    TexelSurfaces out;
    out.start.assign(size_t(size) * size_t(size) + 1, 0);
    const auto texelIndex = [&](const raster::Fragment& f) {
        const glm::ivec2 t = texelOfStorage(f.pixel, fb.tilesX());
        return size_t(t.y) * size_t(size) + size_t(t.x);
    };
    for (int tile = 0; tile < tiles; ++tile) {
        for (const raster::Fragment& f : fb.tileFragments(tile)) ++out.start[texelIndex(f) + 1];
    }
    for (size_t k = 1; k < out.start.size(); ++k) out.start[k] += out.start[k - 1];
    out.events.resize(out.start.back());
    std::vector<uint32_t> next(out.start.begin(), out.start.end() - 1);
    for (int tile = 0; tile < tiles; ++tile) {
        for (const raster::Fragment& f : fb.tileFragments(tile)) {
            const uint32_t triangle = f.primitiveId;
            const glm::vec3 passed = transmission.materialOf(triangle).passed();
            const double y = std::max(double(luminance(passed)), 1e-12);
            out.events[next[texelIndex(f)]++] = {f.depth, f.depth, float(-portable::log(y)), passed, triangle};
        }
    }
    tbb::parallel_for(size_t(0), out.start.size() - 1, [&](size_t t) {
        std::sort(out.events.begin() + out.start[t], out.events.begin() + out.start[t + 1], nearerEvent);
    });
    return out;
}

// The pieces of volume along texel (x, y)'s ray, from the light to depth `stop`, each of
// optical depth at most kMaxPieceOpticalDepth, appended nearest first.
void marchTexel(const DepthMap& map, std::span<const DensityVolume> volumes, int x, int y, float stop,
                std::vector<Event>& out) {
    const auto worldAt = [&](double z) {
        const glm::dvec4 p = map.worldFromTexel * glm::dvec4(x + 0.5, y + 0.5, z, 1.0);
        return glm::dvec3(p) / p.w;
    };
    const auto depthOf = [&](const glm::dvec3& p) {
        const glm::dvec4 q = map.texelFromWorld * glm::dvec4(p, 1.0);
        return float(q.z / q.w);
    };
    const glm::dvec3 a = worldAt(0.0), b = worldAt(double(stop));
    const double length = glm::length(b - a);
    const size_t first = out.size();
    for (const DensityVolume& volume : volumes) {
        marchVoxels(volume, a, b, [&](double t0, double t1, double sigma) {
            const double tau = sigma * (t1 - t0) * length;
            if (tau <= 0.0) return;
            const int pieces = int(std::ceil(tau / kMaxPieceOpticalDepth));
            const float passed = float(portable::exp(-tau / pieces));
            for (int k = 0; k < pieces; ++k) {
                const double s0 = t0 + (t1 - t0) * k / pieces, s1 = t0 + (t1 - t0) * (k + 1) / pieces;
                out.push_back({depthOf(a + s0 * (b - a)), depthOf(a + s1 * (b - a)), float(tau / pieces),
                               glm::vec3(passed), LightLayers::kVolumePiece});
            }
        });
    }
    std::sort(out.begin() + ptrdiff_t(first), out.end(), nearerEvent);
}

// Every texel's surfaces and volume pieces merged, nearest first, into the layers' arrays.
void mergeEvents(const TexelSurfaces& surfaces, std::span<const DensityVolume> volumes, LightLayers& layers) {
    const int size = layers.size();
    std::vector<std::vector<Event>> rows(static_cast<size_t>(size));
    std::vector<uint32_t> counts(size_t(size) * size_t(size));
    tbb::parallel_for(0, size, [&](int y) {
        std::vector<Event> pieces;
        for (int x = 0; x < size; ++x) {
            const size_t t = size_t(y) * size_t(size) + size_t(x);
            pieces.clear();
            if (!volumes.empty()) marchTexel(layers.opaque, volumes, x, y, layers.opaque.at(x, y), pieces);
            const size_t before = rows[size_t(y)].size();
            std::merge(surfaces.events.begin() + surfaces.start[t], surfaces.events.begin() + surfaces.start[t + 1],
                       pieces.begin(), pieces.end(), std::back_inserter(rows[size_t(y)]), nearerEvent);
            counts[t] = uint32_t(rows[size_t(y)].size() - before);
        }
    });
    layers.start.assign(counts.size() + 1, 0);
    for (size_t t = 0; t < counts.size(); ++t) layers.start[t + 1] = layers.start[t] + counts[t];
    const size_t total = layers.start.back();
    layers.depthNear.reserve(total), layers.depthFar.reserve(total), layers.opticalDepth.reserve(total);
    layers.passed.reserve(total), layers.triangle.reserve(total);
    for (const std::vector<Event>& row : rows) {
        for (const Event& e : row) {
            layers.depthNear.push_back(e.near), layers.depthFar.push_back(e.far);
            layers.opticalDepth.push_back(e.opticalDepth), layers.passed.push_back(e.passed);
            layers.triangle.push_back(e.triangle);
            layers.volumePieces += e.triangle == LightLayers::kVolumePiece;
            layers.nearestDepth = std::min(layers.nearestDepth, e.near);
            layers.farthestDepth = std::max(layers.farthestDepth, e.far);
        }
    }
}

}  // namespace

LightLayers renderLightLayers(const ShadowInputs& in, const Light& light, const CasterTransmission& transmission,
                              const LightLayerSettings& settings) {
    LightFitOptions fit;
    fit.resolution = settings.resolution;
    fit.simd = in.simd;
    const LightView view = fitLightView(light, in.gbuffer, in.casterWorld(), fit);
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

    LightLayers layers;
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
