#include "shadows/fins/illuminance_buffer.h"

#include <algorithm>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// Pixels a task takes through the kernels at a time: its working columns stay in L1/L2.
constexpr uint32_t kChunkPixels = 512;

fins::IlluminanceKernels illuminanceKernels(raster::SimdLevel simd) {
    return raster::forSimdLevel(simd, fins::illuminanceKernelsScalar, fins::illuminanceKernelsAvx2,
                                fins::illuminanceKernelsAvx512);
}

// One chunk's working columns: where each pixel's receiver falls, and the maps' values there.
struct ChunkColumns {
    double x[kChunkPixels], y[kChunkPixels], depthAtCentre[kChunkPixels], lightDistance[kChunkPixels];
    double hard[kChunkPixels], innerDepth[kChunkPixels], innerWeight[kChunkPixels];
    double outerDepth[kChunkPixels], outerWeight[kChunkPixels];

    fins::PlacedColumns placed(uint32_t from) { return {x + from, y + from, depthAtCentre + from, lightDistance + from}; }
    fins::TexelColumns texels(uint32_t from, bool inner) const {
        return {hard + from, inner ? innerDepth + from : nullptr, inner ? innerWeight + from : nullptr, outerDepth + from,
                outerWeight + from};
    }
};

// The maps at each placed texel (inside the map: place clamps). Every map of a frame shares
// one view and resolution (fin_shadows.cpp), and all are block-linear, so one storage index
// serves them all. A pixel whose I is 0 already stays 0 (min(0, local) = 0 for any local in
// [0, 1], and a NaN local keeps I), so its texels are not read: it is given an empty one.
void readTexels(const LayerMaps& maps, const float* values, uint32_t count, ChunkColumns& c) {
    for (uint32_t k = 0; k < count; ++k) {
        if (values[k] == 0.0f) {
            c.hard[k] = c.innerDepth[k] = c.outerDepth[k] = 1.0, c.innerWeight[k] = c.outerWeight[k] = 0.0;
            continue;
        }
        const size_t texel = raster::blockLinearIndex(int(c.x[k]), int(c.y[k]), maps.hard.tilesX);
        c.hard[k] = maps.hard.depth[texel];
        if (maps.inner) c.innerDepth[k] = maps.inner->depth[texel], c.innerWeight[k] = maps.inner->weight[texel];
        c.outerDepth[k] = maps.outer.depth[texel], c.outerWeight[k] = maps.outer.weight[texel];
    }
}

void requireOneLayout(const LayerMaps& maps) {
    const auto same = [&](const PenumbraMap& m) { return m.size == maps.hard.size && m.tilesX == maps.hard.tilesX; };
    if (!same(maps.outer) || (maps.inner && !same(*maps.inner)))
        throw std::logic_error("illuminance buffer: a layer's maps differ in size");
}

}  // namespace

fins::PlaceConstants placeConstants(const DepthMap& hard, const LightPlane& light) {
    fins::PlaceConstants c{};
    std::copy_n(glm::value_ptr(hard.texelFromWorld), 16, c.texelFromWorld);
    c.lastTexel = double(hard.size - 1);
    for (int i = 0; i < 3; ++i) c.lightCentre[i] = light.centre[i], c.lightNormal[i] = light.normal[i];
    return c;
}

IlluminanceBuffer::IlluminanceBuffer(const GBuffer& gbuffer, const std::vector<uint8_t>& lit)
    : gbuffer_(gbuffer), values_(lit.begin(), lit.end()) {}

void IlluminanceBuffer::combineLayer(const LayerMaps& maps, const IlluminanceSettings& s) {
    requireOneLayout(maps);
    const fins::IlluminanceKernels vector = illuminanceKernels(s.simd), scalar = fins::illuminanceKernelsScalar();
    const fins::PlaceConstants place = placeConstants(maps.hard, s.light);
    const fins::IlluminateConstants illuminate{s.view.clipFromView[2][2], s.view.clipFromView[3][2], s.referenceDistance,
                                               double(s.edgeWeight), s.falloff == Falloff::Bernstein};
    const float* positions = &gbuffer_.position.data()->x;   // x, y, z per pixel
    const bool inner = maps.inner != nullptr;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, values_.size(), kChunkPixels), [&](const tbb::blocked_range<size_t>& r) {
        ChunkColumns c;
        for (size_t first = r.begin(); first < r.end(); first += kChunkPixels) {
            const uint32_t count = uint32_t(std::min<size_t>(kChunkPixels, r.end() - first));
            // The vector kernels take whole vectors, the scalar twin the tail.
            const uint32_t body = count / uint32_t(vector.width) * uint32_t(vector.width);
            vector.place(place, positions + 3 * first, body, c.placed(0));
            scalar.place(place, positions + 3 * (first + body), count - body, c.placed(body));
            readTexels(maps, &values_[first], count, c);
            vector.illuminate(illuminate, c.placed(0), c.texels(0, inner), body, &values_[first]);
            scalar.illuminate(illuminate, c.placed(body), c.texels(body, inner), count - body, &values_[first + body]);
        }
    });
}

}  // namespace shadowlab
