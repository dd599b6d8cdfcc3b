// Stage 7 of the glTF reader: a perspective camera (glTF 2.0, section 3.10) as ours: the
// node's origin is the eye, its -Z the viewing direction and its +Y the up vector; yfov
// (radians) becomes fovyDeg, znear and zfar the clip planes. The image is
// kGltfImageHeight pixels high and aspectRatio times that wide (1280 x 800 without an
// aspect ratio); the command line's --width and --height replace both. An orthographic
// camera is refused by name.
#pragma once

#include <optional>

#include "scenes/gltf/gltf_document.h"
#include "scenes/scene.h"

namespace shadowlab {

inline constexpr int kGltfImageHeight = 800;

// The camera node `node` carries, placed by its world transform; none if it has none.
// zFar is 0 for a camera without zfar (an infinite projection in glTF, ours is finite):
// the caller sets it from the scene's bounds.
std::optional<Camera> readNodeCamera(const GltfDocument& document, size_t node, const glm::dmat4& worldFromNode);

}  // namespace shadowlab
