#include "shadows/volumes/infinite_projection.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/camera.h"

namespace shadowlab {

glm::dmat4 clipFromViewInfiniteD(const Camera& camera) {
    // Start from the camera's own matrix so that rows x, y, w are the same bits.
    glm::dmat4 proj = clipFromViewD(camera);
    proj[2][2] = -1.0;                          // (f + n) / (n - f) as f -> inf
    proj[3][2] = -2.0 * double(camera.zNear);   // 2 f n / (n - f) as f -> inf
    return proj;
}

glm::mat4 clipFromWorldInfinite(const Camera& camera) {
    const glm::dmat4 view = glm::lookAtRH(glm::dvec3(camera.eye), glm::dvec3(camera.target), glm::dvec3(camera.up));
    return glm::mat4(clipFromViewInfiniteD(camera) * view);
}

}  // namespace shadowlab
