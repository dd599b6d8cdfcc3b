// `planar`: planar projected shadows (Blinn 1988; RTR 4th ed., section 7.1.1). See
// planar.cpp.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique planarTechnique();

// RTR 7.1.1's planar projection matrix for the plane dot(n, x) + d = 0 and the homogeneous
// light l = (L, 1) (point) or (direction, 0): M = dot(pi, l) I - l pi^T with pi = (n, d).
// M p is the point where the line from the light through p meets the plane.
glm::dmat4 planarProjection(const glm::dvec4& plane, const glm::dvec4& light);

}  // namespace shadowlab
