// How a sampled light's specular highlight is shaded. Median cut gives each light a region
// of the map (median_cut.h), and its power is the region's integral; the paper shades it as
// a point, the region's light arriving from one direction (`point`). Under a glossy lobe
// narrower than the regions, a point light's highlight is a bright spot where the lobe
// meets it and nothing between: additive shadowing shows the spots (the paper's "speckled"
// look, Figure 1), and subtractive shadowing subtracts them from a smooth C, leaving dark
// spots where C - S' is clamped at 0.
//
// `region` (ours, not the paper's) shades the light as its region: the region taken as a
// cap of equal solid angle Omega (angular radius rho, Omega = 2 pi (1 - cos rho)), and the
// lobe and the cap as Gaussians about their axes whose variances add: a cap's is rho^2 / 4
// per axis, a normalised lobe's 1 / n (Phong, about the mirror direction), 4 / s in the
// light's direction (Blinn-Phong, about the half vector) and alpha^2 (GGX: D ~ (1 +
// theta_h^2 / alpha^2)^-2 ~ exp(-2 theta_h^2 / alpha^2) at its peak, variance alpha^2 / 4 in
// the half vector, four times that in the light's direction), so
//
//     Phong  n' = 1 / (1/n + rho^2 / 4),  Blinn-Phong  s' = 1 / (1/s + rho^2 / 16),
//     GGX    alpha' = min(1, sqrt(alpha^2 + rho^2 / 4)).
//
// Normalised lobes keep their integral as they widen, so a light's reflected energy is
// kept; the diffuse term does not change.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/environment/median_cut.h"

namespace shadowlab {

enum class LightLobes { Point, Region };   // the `light-lobes` parameter (light_passes.h)

// The materials with their specular lobes widened for a light whose region has that solid angle.
std::vector<Material> widenedForRegion(std::vector<Material> materials, double solidAngle);

// The materials a light is shaded with: the scene's, or widened for its region.
std::vector<Material> lightMaterials(const Scene& scene, const EnvironmentLight& light, LightLobes lobes);

}  // namespace shadowlab
