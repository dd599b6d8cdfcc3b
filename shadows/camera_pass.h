// The camera pass: every pixel's nearest triangle (no culling, so open meshes show both
// sides), then the exact G-buffer from it (shading/gbuffer_build.h). The frame runs it once
// per view (frame/render.h); a technique that samples its shadows at a lower resolution runs
// it again with a smaller camera of the same view.
#pragma once

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

GBuffer renderGBuffer(const WorldGeometry& world, const Camera& camera, raster::SimdLevel simd);

}  // namespace shadowlab
