// Directions drawn roughly in proportion to a material's BRDF times the cosine (shade.h,
// brdf()), and their densities: the BRDF strategy of the exact environment reference's
// multiple importance sampling (compositing/environment_reference.cpp; Veach and Guibas
// 1995). A mixture of two lobes, the first chosen with probability
//
//     p_diffuse = Y(albedo) / (Y(albedo) + Y(specular))   (1 for Lambert or no specular)
//
// with the material's albedo, not the texture's at the point (shading/surface_albedo.h): the
// choice is part of the density only, stated exactly below, so one per material will do.
//
//   diffuse      cosine-weighted about N, p = max(0, N . wi) / pi;
//   Phong        about the mirror direction R of wo, p = (n + 1) / (2 pi) max(0, R . wi)^n;
//   Blinn-Phong  the half vector h about N with (s + 1) / (2 pi) (N . h)^s, and
//   GGX          h with D(h) (N . h) (Walter et al. 2007, eq. 35-36), each reflected into
//                wi = 2 (wo . h) h - wo, p = p_h / (4 |wo . h|).
//
// Any density that is positive wherever the integrand is would do: these only keep the
// variance low, so they are exact in what they state (the density of the direction drawn),
// not a claim that they match the BRDF.
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct BrdfSample {
    glm::dvec3 direction{0.0, 0.0, 1.0};   // unit; may point below the surface (then f = 0)
    double pdf = 0.0;                      // per steradian, of the whole mixture
};

// From three uniform numbers in [0, 1): u.x chooses the lobe, u.y and u.z place it. N and
// wo are unit.
BrdfSample sampleBrdf(const Material& material, const glm::dvec3& N, const glm::dvec3& wo, const glm::dvec3& u);

// The mixture's density of drawing wi (unit).
double brdfPdf(const Material& material, const glm::dvec3& N, const glm::dvec3& wo, const glm::dvec3& wi);

}  // namespace shadowlab
