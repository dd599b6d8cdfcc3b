// Stage 5 of the glTF reader: a material (glTF 2.0, section 3.9) as ours (scenes/scene.h,
// Material; docs/scene-format.md, "glTF files"):
//   baseColorFactor rgb -> albedo (Lambert; metallic and roughness are not read);
//   baseColorTexture rgb -> the albedo texture, decoded from sRGB to linear (section 3.9.2:
//   the surface's albedo is the factor times the texture), at the nearest texel of (u, v)
//   wrapped by the texture's sampler (wrapS, wrapT: CLAMP_TO_EDGE, MIRRORED_REPEAT or
//   REPEAT, REPEAT without a sampler; its filters are not read), as the cut-outs' alpha is;
//   alphaMode OPAQUE -> opaque; MASK -> a cut-out whose alpha is the base colour texture's
//   alpha times the factor's alpha, with alphaCutoff (without a texture the factor's alpha
//   alone decides: at or above the cutoff opaque, below it the surface is not drawn);
//   BLEND -> translucency, opacity = the factor's alpha (the texture's alpha not read);
//   doubleSided is read and has no effect: every surface here is drawn and casts from both
//   sides (the camera pass does not cull).
#pragma once

#include <optional>

#include "scenes/gltf/gltf_document.h"
#include "scenes/scene.h"

namespace shadowlab {

struct GltfMaterial {
    Material material;
    std::optional<AlphaTexture> alphaTexture;   // for a MASK with a texture; its index is set by the caller
    std::optional<AlbedoTexture> albedoTexture; // for a base colour texture; its index is set by the caller
    bool invisible = false;                     // a MASK whose constant alpha is below the cutoff
};

// Material `index` of the file, or glTF's default material (section 3.9.6) for -1.
GltfMaterial readGltfMaterial(const GltfDocument& document, int index);

}  // namespace shadowlab
