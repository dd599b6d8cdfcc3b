#include "shadows/camera_pass.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/rasterizer.h"
#include "scenes/camera.h"
#include "shading/gbuffer_build.h"
#include "shadows/world_draw.h"

namespace shadowlab {

GBuffer renderGBuffer(const WorldGeometry& world, const Camera& camera, raster::SimdLevel simd) {
    return renderGBuffer(world, camera, simd, 0);
}

GBuffer renderGBuffer(const WorldGeometry& world, const Camera& camera, raster::SimdLevel simd, uint32_t firstKept) {
    raster::Framebuffer fb(camera.width, camera.height, {.primitiveId = true});
    fb.clearPrimitiveId(kNoTriangle);
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.output = raster::FragmentOutput::PrimitiveId;
    raster::Rasterizer rasterizer(simd);
    drawWorld(rasterizer, fb, state, world, clipFromWorld(camera));
    std::vector<uint32_t> triangles = fb.primitiveIdImage();
    if (firstKept > 0) {
        for (uint32_t& t : triangles) t = t != kNoTriangle && t < firstKept ? kNoTriangle : t;
    }
    return buildGBuffer(world, camera, triangles, fb.depthImage());
}

GBuffer liftedReceivers(GBuffer g, const WorldGeometry& world, std::span<const float> liftM) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount(), 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
            if (g.hit[k]) g.position[k] += g.normal[k] * liftM[world.triangleInstance[g.triangle[k]]];
        }
    });
    return g;
}

}  // namespace shadowlab
