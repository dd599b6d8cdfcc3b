// One light's share of the radiance each pixel reflects towards the camera, the term every
// technique here sums or subtracts (DeCoro and Rusinkiewicz 2008, section 2, step 2c):
//
//     f(wi, wo) E max(0, Ns . wi)
//
// with f the material's BRDF (shading/shade.h), E and wi the light's irradiance and direction
// at the point (a sampled environment light: its power and direction, the same everywhere;
// a scene light: lightArrival(), shading/lights.h), Ns the shading normal and wo towards the
// camera. It is weighted by the light's visibility V at the pixel: the additive sum takes the
// lit part V, subtractive shadows the occluded part 1 - V. Pixels whose weight is 0 are not
// shaded at all; they are the fill the paper's sampling detail saves, and are counted.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

enum class LightPart { Lit, Occluded };   // weight V, or 1 - V

// Adds the light's weighted share to `sum` (one entry per pixel of g) and returns how many
// pixels had a weight other than 0. `materials` are indexed by the G-buffer's material (the
// scene's, or their lobes widened for this light: light_lobes.h), their albedo textures in
// `albedoTextures` (the scene's; shading/surface_albedo.h); `eye` is the camera the
// G-buffer was built with; `V` has one entry per pixel. The sum is the same bytes for any
// number of threads (each pixel is one task's).
uint64_t addDistantLight(const GBuffer& g, const std::vector<Material>& materials,
                         const std::vector<AlbedoTexture>& albedoTextures, const glm::vec3& eye,
                         const glm::vec3& toLight, const glm::vec3& irradiance, const std::vector<float>& V,
                         LightPart part, std::vector<glm::vec3>& sum);
uint64_t addSceneLight(const GBuffer& g, const std::vector<Material>& materials,
                       const std::vector<AlbedoTexture>& albedoTextures, const glm::vec3& eye, const Light& light,
                       const std::vector<float>& V, LightPart part, std::vector<glm::vec3>& sum);

}  // namespace shadowlab
