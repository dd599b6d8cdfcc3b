// Spherical-harmonic irradiance (Ramamoorthi and Hanrahan 2001, "An Efficient Representation
// for Irradiance Environment Maps"): the environment's radiance projected onto the nine real
// spherical harmonics of bands 0 to 2, and the irradiance at a normal n as their convolution
// with the clamped cosine, E(n) = sum_lm A_l L_lm Y_lm(n), A_0 = pi, A_1 = 2 pi / 3,
// A_2 = pi / 4 (their eqs. 7 to 9; the lobe's bands above 2 are what the nine coefficients
// leave out). The real basis, in world coordinates (+Y up), index k:
//
//     0: c0                 1: c1 x      2: c1 y      3: c1 z
//     4: c2 x y             5: c2 y z    6: c20 (3 y^2 - 1)    7: c2 x z    8: c22 (x^2 - z^2)
//
// c0 = 1 / (2 sqrt(pi)), c1 = sqrt(3 / (4 pi)), c2 = sqrt(15 / (4 pi)), c20 = sqrt(5 / (16 pi)),
// c22 = sqrt(15 / (16 pi)): orthonormal within each band, which is all the convolution needs
// (Funk-Hecke: the lobe scales each band by one number).
//
// Projection is exact for the map as it is defined, piecewise constant over its texels
// (environment_map.h): each texel contributes its radiance times the integral of each basis
// function over its region, which separates into a polynomial of cos(theta) integrated over
// the row and a trigonometric integral over the column, both in closed form. So a constant
// environment has L_00 = 2 sqrt(pi) L and no other coefficient, and E = pi L, to rounding.
//
// Ringing: nine coefficients of a map with a sun overshoot and can go negative opposite it.
// The optional window scales band l by sigma_l = (sin(pi l / w) / (pi l / w))^4, w > 2 (the
// sinc^4 window of Filament's cmgen; Sloan, "Deringing Spherical Harmonics", 2017, on why
// windows help), trading sharpness for a smaller negative lobe; w = 0 is off.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"

namespace shadowlab {

inline constexpr int kShCoefficients = 9;

// Nine RGB coefficients: of radiance (projectRadiance) or of irradiance (irradianceOf).
struct ShCoefficients {
    std::array<glm::dvec3, kShCoefficients> c{};
};

// The nine basis functions at a unit direction.
std::array<double, kShCoefficients> shBasis(const glm::dvec3& direction);

// L_lm of the map: rows summed in parallel, each by one task, then added in row order, so the
// same bits for any thread count.
ShCoefficients projectRadiance(const EnvironmentMap& map);

// Throws std::invalid_argument unless the window width is 0 (off) or finite and above 2.
void checkShWindow(double windowWidth);

// A_l sigma_l L_lm: coefficients whose evaluation at n is the irradiance E(n) (checkShWindow
// first).
ShCoefficients irradianceOf(const ShCoefficients& radiance, double windowWidth = 0.0);

// sum_k c_k Y_k(direction): radiance or irradiance, as the coefficients are.
glm::dvec3 evaluateSh(const ShCoefficients& coefficients, const glm::dvec3& direction);

}  // namespace shadowlab
