// Deferred shading of a G-buffer with the lights of a frame and their visibility buffers.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

// One light of a shading pass: scene.lights[light] and its visibility V per pixel (per
// channel where the coloured visibility colouredV is given: the light a tinted caster lets
// through, conventions.md).
struct ShadedLight {
    size_t light = 0;
    std::span<const float> V;
    std::span<const glm::vec3> colouredV = {};
};

// Outgoing radiance towards the camera for every pixel (linear, W/(m^2 sr)):
//   L = ambient * albedo + sum_k V_k * f(wi_k, wo) * E_k * max(0, N.wi_k)
// with albedo the surface's at the pixel (shading/surface_albedo.h), E_k and wi_k from lightArrival() for scene.lights[lights[k].light] (shading/lights.h),
// f the material's BRDF and V_k that light's visibility; the viewer (for wo) is
// scene.camera.eye, the camera the G-buffer was built with. The sum runs in the order of
// `lights`, starting from the ambient term, ((ambient + t_0) + t_1) + ..., a light behind
// the surface adding nothing, so the bytes are fixed (docs/many-lights.md); one light gives
// ambient + t_0. Lights not listed are not shaded, so an image can show exactly the shadows
// being studied. Background pixels (hit = 0) get 0.
// Throws std::out_of_range for a bad light or material index and std::invalid_argument if a
// V or a G-buffer array does not have one entry per pixel.
std::vector<glm::vec3> shade(const Scene& scene, const GBuffer& gbuffer, std::span<const ShadedLight> lights);
// One light: shade(scene, gbuffer, {{lightIndex, V, colouredV}}).
std::vector<glm::vec3> shade(const Scene& scene, const GBuffer& gbuffer, size_t lightIndex,
                             const std::vector<float>& V, std::span<const glm::vec3> colouredV = {});

// BRDF of a material, f(wi, wo) in 1/sr, for unit vectors N (normal), wi (to the light)
// and wo (to the viewer): albedo / pi plus the model's specular lobe, `albedo` the surface's
// at the point (shading/surface_albedo.h; material.albedo where it has no texture).
//   Blinn-Phong  specular (s + 8) / (8 pi) max(0, N.H)^s, H = normalize(wi + wo)
//                (Akenine-Moeller, Haines, Hoffman, Real-Time Rendering, 3rd ed., section 7.6);
//   Phong        specular (s + 2) / (2 pi) max(0, R.wi)^s, R = 2 (N.wo) N - wo the mirror
//                direction (normalised Phong, Lafortune and Willems 1994: seen along N it
//                reflects exactly specular);
//   GGX          D G2 F / (4 (N.wi) (N.wo)) of shading/microfacet_ggx.h, alpha = roughness,
//                F0 = specular; 0 when wi or wo is below the surface.
glm::vec3 brdf(const Material& material, const glm::vec3& albedo, const glm::vec3& N, const glm::vec3& wi,
               const glm::vec3& wo);

}  // namespace shadowlab
