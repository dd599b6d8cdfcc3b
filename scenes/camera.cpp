#include "scenes/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include "raster/portable_math.h"

namespace shadowlab {

ViewFrameProblem viewFrameProblem(const Camera& camera) {
    constexpr double kParallelSine = 1e-6;
    const glm::dvec3 forward = glm::dvec3(camera.target) - glm::dvec3(camera.eye);
    const glm::dvec3 up(camera.up);
    if (!(glm::length(forward) > 0.0)) return ViewFrameProblem::EyeAtTarget;
    if (!(glm::length(glm::cross(forward, up)) > kParallelSine * glm::length(forward) * glm::length(up)))
        return ViewFrameProblem::UpParallel;
    return ViewFrameProblem::None;
}

glm::mat4 viewFromWorld(const Camera& camera) {
    return glm::lookAtRH(camera.eye, camera.target, camera.up);
}

glm::dmat4 clipFromViewD(const Camera& camera) {
    const double aspect = double(camera.width) / double(camera.height);
    const double n = double(camera.zNear), f = double(camera.zFar);
    const double tanHalfFovy = portable::tan(0.5 * glm::radians(double(camera.fovyDeg)));
    glm::dmat4 proj(0.0);
    proj[0][0] = 1.0 / (aspect * tanHalfFovy);
    proj[1][1] = 1.0 / tanHalfFovy;
    proj[2][2] = -(f + n) / (f - n);
    proj[2][3] = -1.0;
    proj[3][2] = -(2.0 * f * n) / (f - n);
    return proj;
}

glm::dmat4 clipFromWorldD(const Camera& camera) {
    const glm::dmat4 view = glm::lookAtRH(glm::dvec3(camera.eye), glm::dvec3(camera.target),
                                          glm::dvec3(camera.up));
    return clipFromViewD(camera) * view;
}

PixelRays::PixelRays(const Camera& camera)
    : eye_(camera.eye), width_(camera.width), height_(camera.height), worldFromClip_(glm::inverse(clipFromWorldD(camera))) {}

RayD PixelRays::operator()(int i, int j) const {
    // Pixel centre to normalised device coordinates; row 0 is the top (NDC y = +1).
    const double ndcX = (i + 0.5) / width_ * 2.0 - 1.0;
    const double ndcY = 1.0 - (j + 0.5) / height_ * 2.0;
    const glm::dvec4 nearPoint = worldFromClip_ * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    const glm::dvec4 farPoint = worldFromClip_ * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 b = glm::dvec3(farPoint) / farPoint.w;
    return {eye_, b - a};
}

}  // namespace shadowlab
