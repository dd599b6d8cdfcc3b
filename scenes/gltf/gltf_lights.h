// Stage 6 of the glTF reader: KHR_lights_punctual (docs/scene-format.md, "glTF files";
// conventions.md, "Lights"). A light hangs from a node and shines along the node's -Z;
// its position is the node's origin (scale ignored, as the extension says). Intensities
// are taken 1:1, as a renderer at unit exposure takes them: candela (lm/sr) as our W/sr for
// point and spot lights, lux (lm/m^2) as our W/m^2 for directional ones, times the colour.
// A spot keeps the extension's smooth falloff between innerConeAngle and outerConeAngle
// (our coneAngleDeg) and a light its range window (shading/lights.h).
#pragma once

#include "scenes/gltf/gltf_document.h"
#include "scenes/scene.h"

namespace shadowlab {

// The light node `node` carries, placed by its world transform; none if it has none.
std::optional<Light> readNodeLight(const GltfDocument& document, size_t node, const glm::dmat4& worldFromNode);

}  // namespace shadowlab
