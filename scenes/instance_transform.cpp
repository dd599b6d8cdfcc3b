#include "scenes/instance_transform.h"

#include <glm/gtc/matrix_transform.hpp>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// A turn of `degrees` about world axis `axis` (0: x, 1: y, 2: z), counter-clockwise seen
// from the axis' positive end.
glm::mat4 rotationAbout(int axis, float degrees) {
    const double radians = double(glm::radians(degrees));
    const float c = float(portable::cos(radians)), s = float(portable::sin(radians));
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;   // the plane turned: u towards v
    glm::mat4 rotation(1.0f);
    rotation[u][u] = c, rotation[u][v] = s;
    rotation[v][u] = -s, rotation[v][v] = c;
    return rotation;
}

}  // namespace

glm::mat4 translateRotateScale(const InstancePose& pose) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), pose.translate);
    m = m * rotationAbout(2, pose.rotateDeg.z) * rotationAbout(1, pose.rotateDeg.y) * rotationAbout(0, pose.rotateDeg.x);
    return glm::scale(m, pose.scale);
}

glm::mat4 posedWorldFromObject(const PathInstance& instance, const InstancePose& pose) {
    const glm::mat4 placed = translateRotateScale(pose) * instance.fit;
    return instance.shift ? glm::translate(glm::mat4(1.0f), *instance.shift) * placed : placed;
}

}  // namespace shadowlab
