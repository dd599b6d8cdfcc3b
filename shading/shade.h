// Deferred shading of a G-buffer with one selected light and its visibility buffer.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

// Outgoing radiance towards the camera for every pixel (linear, W/(m^2 sr)):
//   L = ambient * albedo + V * f(wi, wo) * E * max(0, N.wi)
// with E and wi from lightArrival() for scene.lights[lightIndex] (shading/lights.h), f the
// material's BRDF (Lambert, or normalised Blinn-Phong) and V[pixel] the visibility of that
// light (per channel where the coloured visibility colouredV is given: the light a tinted
// caster lets through, conventions.md); the viewer (for wo) is scene.camera.eye, the camera
// the G-buffer was built with.
// Only the selected light is shaded: the other lights of the scene are ignored, so
// the image shows exactly the shadow being studied. Background pixels (hit = 0) get 0.
// Throws std::out_of_range for a bad lightIndex or material index and
// std::invalid_argument if V or a G-buffer array does not have one entry per pixel.
std::vector<glm::vec3> shade(const Scene& scene, const GBuffer& gbuffer, size_t lightIndex,
                             const std::vector<float>& V, std::span<const glm::vec3> colouredV = {});

// BRDF of a material, f(wi, wo) in 1/sr, for unit vectors N (normal), wi (to the light)
// and wo (to the viewer): albedo / pi plus the model's specular lobe.
//   Blinn-Phong  specular (s + 8) / (8 pi) max(0, N.H)^s, H = normalize(wi + wo)
//                (Akenine-Moeller, Haines, Hoffman, Real-Time Rendering, 3rd ed., section 7.6);
//   Phong        specular (s + 2) / (2 pi) max(0, R.wi)^s, R = 2 (N.wo) N - wo the mirror
//                direction (normalised Phong, Lafortune and Willems 1994: seen along N it
//                reflects exactly specular);
//   GGX          D G2 F / (4 (N.wi) (N.wo)) of shading/microfacet_ggx.h, alpha = roughness,
//                F0 = specular; 0 when wi or wo is below the surface.
glm::vec3 brdf(const Material& material, const glm::vec3& N, const glm::vec3& wi,
               const glm::vec3& wo);

}  // namespace shadowlab
