// The camera pass: every pixel's nearest triangle (no culling, so open meshes show both
// sides), then the exact G-buffer from it (shading/gbuffer_build.h). The frame runs it once
// per view (frame/render.h); a technique that samples its shadows at a lower resolution runs
// it again with a smaller camera of the same view.
#pragma once

#include <span>

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

GBuffer renderGBuffer(const WorldGeometry& world, const Camera& camera, raster::SimdLevel simd);
// The same drawn in full, built only where a triangle from `firstKept` on is the nearest;
// elsewhere hit = 0 as for the background. For a frame that moves a few triangles in front
// of a static scene whose own G-buffer it keeps (differential/composite.h).
GBuffer renderGBuffer(const WorldGeometry& world, const Camera& camera, raster::SimdLevel simd, uint32_t firstKept);

// The G-buffer with every surface point moved along its geometric normal, to the camera's
// side, by its instance's entry of `liftM` (m; indexed like Scene::instances). Against
// simplified casters (scenes/caster_lod.h) the whole receivers are not on the casters'
// surface: where a coarse caster's face cuts outside its own surface (a concave region),
// that surface lies up to about the simplification error beneath it and would shadow
// itself. Lifting each receiver by its own instance's error before the shadow test is a
// normal offset (Holbert; RTR 7.4) sized by the geometry instead of a texel; a receiver whose
// mesh kept its shape (a ground) stays put, so contact shadows on it do not move. The price:
// shadows cast onto a lifted receiver by other casters move by its lift, and a point whose
// light lies within lift / distance of its tangent plane (the terminator's band) may be
// taken as facing away from the light.
GBuffer liftedReceivers(GBuffer g, const WorldGeometry& world, std::span<const float> liftM);

}  // namespace shadowlab
