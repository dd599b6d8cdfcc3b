// The photograph's side of the model: which patch each pixel sees, where in it, and, for
// the built-in cases whose photograph is rendered rather than taken, the photograph itself.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "differential/patch_light.h"
#include "differential/scene/compositing_scene.h"
#include "raster/tile_kernels.h"
#include "shading/gbuffer.h"
#include "shadows/reference/reference.h"

namespace shadowlab {

inline constexpr uint32_t kNoPatch = 0xffffffffu;

// Per pixel the patch the camera sees (kNoPatch where none) and the pixel centre's (u, v)
// in the patch's cell (PatchModel::pointAt), from the rasterizer's G-buffer of the model's
// triangles (patchGeometry: patch p is triangles 2p and 2p + 1).
struct PixelPatches {
    GBuffer gbuffer;
    std::vector<uint32_t> patch;
    std::vector<glm::vec2> uv;
};
PixelPatches pixelPatches(const PatchModel& model, const WorldGeometry& geometry, const Camera& camera,
                          raster::SimdLevel simd);

// The photograph rendered from the model (the room case): per pixel, what its patch emits
// plus its reflectance times the light gathered from every radiant patch (patch_light.h),
// visibility by Embree rays against the model; 0 where no patch is seen from its front.
std::vector<glm::vec3> renderBackground(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                                        const PixelPatches& pixels, const ReferenceVisibility& modelRays,
                                        const PatchSampling& sampling);

}  // namespace shadowlab
