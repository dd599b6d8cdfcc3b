// An instance's transform from translate, rotate and scale (docs/scene-format.md,
// "transform"): what a scene file's instance or model entry gives, and what a fly-through's
// keyframe gives for each instance it moves (scenes/camera_path.h), so that both place an
// instance with the same bits.
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// translate * rotateZ * rotateY * rotateX * scale: scaled, then turned about x, y and z
// (world axes, in that order, degrees, counter-clockwise seen from the axis' positive end),
// then moved. Sines and cosines from raster/portable_math.h, so that transformed vertices
// are the same bits on every CPU.
glm::mat4 translateRotateScale(const InstancePose& pose);

// Where a path puts an instance it moves: shift * translateRotateScale(pose) * fit
// (scene.h, PathInstance), with the operations of the scene file's reader, so that a pose
// equal to the file's transform gives the file's worldFromObject bit for bit.
glm::mat4 posedWorldFromObject(const PathInstance& instance, const InstancePose& pose);

}  // namespace shadowlab
