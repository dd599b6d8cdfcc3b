// A debug view of the silhouette edges (silhouette.h) as the camera sees them: 1 on every
// pixel a silhouette edge passes through, 0 elsewhere, occluded or not. The edges are
// clipped to the near plane in clip space and to the image, then walked in steps of at
// most one pixel.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shadows/silhouettes/silhouette.h"

namespace shadowlab {

std::vector<float> silhouetteImage(const Camera& camera, std::span<const glm::vec3> positions,
                                   std::span<const SilhouetteEdge> edges);

}  // namespace shadowlab
