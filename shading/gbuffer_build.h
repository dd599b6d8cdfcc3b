// G-buffer reconstruction from a visibility buffer (shading/gbuffer.h explains why the
// rasterizer stores triangle indices rather than interpolated attributes).
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

// visibleTriangle[j * W + i] is the triangle the rasterizer found at the centre of pixel
// (i, j) (kNoTriangle for background), depth[j * W + i] its window depth. For each covered
// pixel, P is the intersection of PixelRays(camera)(i, j) with that triangle's plane,
// computed in double and rounded once to float, and N is the triangle's unit geometric
// normal turned to face the camera. The shading normal Ns is the triangle's corner normals
// (WorldGeometry::cornerNormals) weighted by the barycentric coordinates of P, normalised:
// P is the exact surface point, so this is the perspective-correct interpolation without
// dividing by w. Ns is turned to the side of N (it is only ever far from N on a badly
// tessellated mesh), and is N itself where the corner normals cancel or the world has none.
// The texture coordinate uv is the corner UVs (WorldGeometry::cornerUvs) weighted the same
// way, when the world has them. The G-buffer keeps uv rather than the albedo the textures
// give there: it is the surface's geometry, found where P's exact barycentric weights are,
// while the albedo is the scene's material data, which the world geometry does not carry
// (shading/surface_albedo.h reads it at uv).
// Background pixels get hit = 0, P = N = Ns = uv = 0, material 0, triangle kNoTriangle and
// depth 1. Throws std::invalid_argument if the buffer sizes do not match the camera, the
// world has corner normals or UVs but not three per triangle, a triangle index is out of range,
// or a pixel ray is parallel to its triangle's plane (a rasterizer never covers a pixel
// centre with an edge-on triangle).
GBuffer buildGBuffer(const WorldGeometry& world, const Camera& camera,
                     const std::vector<uint32_t>& visibleTriangle,
                     const std::vector<float>& depth);

// Throws std::invalid_argument (starting with `who`) unless every per-pixel array of the
// G-buffer has width * height entries (uv and the motion arrays: or none); stages that read a G-buffer they did
// not build call it first.
void requireConsistent(const GBuffer& gbuffer, const char* who);

}  // namespace shadowlab
