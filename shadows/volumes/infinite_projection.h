// The camera's projection with the far plane at infinity (Everitt and Kilgard 2002,
// "Practical and Robust Stenciled Shadow Volumes", the section on the infinite view
// frustum projection P_inf). It is OpenGL's perspective matrix in the limit far -> inf:
//
//   (f + n) / (n - f)  ->  -1        2 f n / (n - f)  ->  -2 n
//
// so a point at infinity (w = 0) in front of the camera has z_clip = w_clip, i.e. window
// depth exactly 1, and is never clipped by a far plane. Shadow volumes extruded to
// infinity are then drawn whole, and the z-fail dark cap lands on depth 1.
//
// Rows x, y and w are computed exactly as clipFromWorldD() computes them (only row z
// differs), so every vertex gets the same window x and y bits, hence the same coverage,
// as in the camera pass that built the G-buffer.
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

glm::dmat4 clipFromViewInfiniteD(const Camera& camera);
glm::mat4 clipFromWorldInfinite(const Camera& camera);

}  // namespace shadowlab
