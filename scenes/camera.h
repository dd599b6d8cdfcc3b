// Camera matrices (conventions.md, "Space and camera"): right-handed world, +Y up,
// OpenGL clip space, window depth in [0,1], pixel (i,j) centred at (i+0.5, j+0.5) with
// row 0 at the top of the image.
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// Why the camera's view frame is undefined, or nothing: the eye must differ from the target,
// and "up" must be neither zero nor parallel to the viewing direction (whose angle has a
// sine below 1e-6), which would leave the image's roll, and the view matrix, undefined.
enum class ViewFrameProblem { None, EyeAtTarget, UpParallel };
ViewFrameProblem viewFrameProblem(const Camera& camera);

glm::mat4 viewFromWorld(const Camera& camera);
// The up vector for a view along `axis` (lookAt's third argument): +Y, or +X when the axis
// is within 25.8 degrees of Y (|y| >= 0.9 of a unit axis), where +Y would make the view's
// frame ill-conditioned.
inline glm::dvec3 lookAtUp(const glm::dvec3& axis) {
    return glm::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}
// OpenGL's perspective projection (the entries of glm::perspectiveRH_NO), its tangent from
// raster/portable_math.h so that the matrix is the same bits on every CPU.
glm::dmat4 clipFromViewD(const Camera& camera);
inline glm::mat4 clipFromView(const Camera& camera) { return glm::mat4(clipFromViewD(camera)); }
glm::dmat4 clipFromWorldD(const Camera& camera);   // clipFromViewD * the view, in double precision

inline glm::mat4 clipFromWorld(const Camera& camera) {
    return glm::mat4(clipFromWorldD(camera));
}

// World-space ray through the centre of pixel (i, j), in double precision: origin at the
// eye, direction not normalised.
struct RayD {
    glm::dvec3 origin, direction;
};

// World-space rays through the pixel centres of one camera (its inverse matrix computed
// once): PixelRays(camera)(i, j).
class PixelRays {
public:
    explicit PixelRays(const Camera& camera);
    RayD operator()(int i, int j) const;

private:
    glm::dvec3 eye_;
    int width_, height_;
    glm::dmat4 worldFromClip_;
};

}  // namespace shadowlab
