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
// Background pixels get hit = 0, P = N = Ns = 0, material 0, triangle kNoTriangle and
// depth 1. Throws std::invalid_argument if the buffer sizes do not match the camera, the
// world has corner normals but not three per triangle, a triangle index is out of range,
// or a pixel ray is parallel to its triangle's plane (a rasterizer never covers a pixel
// centre with an edge-on triangle).
GBuffer buildGBuffer(const WorldGeometry& world, const Camera& camera,
                     const std::vector<uint32_t>& visibleTriangle,
                     const std::vector<float>& depth);

// Throws std::invalid_argument (starting with `who`) unless every per-pixel array of the
// G-buffer has width * height entries; stages that read a G-buffer they did not build
// call it first.
void requireConsistent(const GBuffer& gbuffer, const char* who);

}  // namespace shadowlab
