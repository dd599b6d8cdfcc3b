// Rec. 709 luminance of linear RGB, in float (images, tone mapping, scoring) and in double
// (the integrators and samplers of the environment), one expression so that every user
// gets the same bits.
#pragma once

#include <glm/glm.hpp>

namespace shadowlab {

inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace shadowlab
