#include "scenes/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

glm::mat4 viewFromWorld(const Camera& camera) {
    return glm::lookAtRH(camera.eye, camera.target, camera.up);
}

glm::mat4 clipFromView(const Camera& camera) {
    const float aspect = float(camera.width) / float(camera.height);
    return glm::perspectiveRH_NO(glm::radians(camera.fovyDeg), aspect, camera.zNear, camera.zFar);
}

glm::dmat4 clipFromWorldD(const Camera& camera) {
    const double aspect = double(camera.width) / double(camera.height);
    const glm::dmat4 view = glm::lookAtRH(glm::dvec3(camera.eye), glm::dvec3(camera.target),
                                          glm::dvec3(camera.up));
    const glm::dmat4 proj = glm::perspectiveRH_NO(glm::radians(double(camera.fovyDeg)), aspect,
                                                  double(camera.zNear), double(camera.zFar));
    return proj * view;
}

RayD pixelRay(const Camera& camera, int i, int j) {
    // Pixel centre to normalised device coordinates; row 0 is the top (NDC y = +1).
    const double ndcX = (i + 0.5) / camera.width * 2.0 - 1.0;
    const double ndcY = 1.0 - (j + 0.5) / camera.height * 2.0;
    const glm::dmat4 worldFromClip = glm::inverse(clipFromWorldD(camera));
    glm::dvec4 nearPoint = worldFromClip * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    glm::dvec4 farPoint = worldFromClip * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 b = glm::dvec3(farPoint) / farPoint.w;
    return {glm::dvec3(camera.eye), b - a};
}

}  // namespace shadowlab
