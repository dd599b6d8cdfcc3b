// Stage 3 of the glTF reader: a mesh primitive (glTF 2.0, section 3.7.2) as one of our
// meshes: its triangles from TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN (indexed or not),
// NORMAL as corner normals and TEXCOORD_0 as corner UVs, v flipped from glTF's top-left
// texture origin to our bottom-left one (scenes/scene.h, Mesh). Morph targets are ignored
// (the mesh in its base shape, docs/scene-format.md).
#pragma once

#include <optional>

#include "scenes/gltf/gltf_document.h"
#include "scenes/scene.h"

namespace shadowlab {

// The primitive's mesh, or nothing for POINTS, LINES, LINE_LOOP and LINE_STRIP, which have
// no surface to draw.
std::optional<Mesh> readPrimitive(const GltfDocument& document, size_t mesh, size_t primitive);

// The same mesh seen through a mirroring transform (a negative determinant, section
// 3.7.4): each triangle's corners in reverse order, so that its front stays counter-clockwise,
// and its normals negated, which the mirror's transform turns back.
Mesh mirrored(Mesh mesh);

}  // namespace shadowlab
