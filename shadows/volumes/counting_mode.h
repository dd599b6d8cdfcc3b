// Choosing how the stencil pass counts shadow-volume crossings: z-pass (Heidmann 1991)
// counts the faces in front of the visible surface and needs no caps, but it is only
// right when the count starts at zero at the camera, i.e. when no shadow volume reaches
// the near-plane rectangle (the camera inside a shadow, or the near plane cutting a
// volume, make every count along the affected rays off by one). z-fail (Everitt and
// Kilgard 2002) counts the faces behind the surface instead, which is always right with
// closed volumes and an infinite far plane, at the price of drawing the caps.
//
// The test is Everitt and Kilgard's "near clip volume": a point X of the near-plane
// rectangle is in the shadow of an occluder exactly when the occluder meets the segment
// from X to the light, so some volume reaches the rectangle only if an occluder meets the
// convex hull of the rectangle and the light (for a directional light, the rectangle
// swept towards the light to infinity). Occluders are tested by their bounding boxes
// against the hull's planes and the boxes' own planes (a separating-axis test that may
// miss a separation, never invent one), so z-pass is chosen only when it is safe.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/bounds.h"
#include "scenes/scene.h"

namespace shadowlab {

// The four corners of the camera's near-plane rectangle, counter-clockwise, world space.
std::vector<glm::dvec3> nearPlaneCorners(const Camera& camera);

// True unless every occluder is separated from the hull of the near-plane rectangle and
// the light (homogeneous: w = 1 point, w = 0 direction).
bool nearPlaneMayBeShadowed(const Camera& camera, const glm::dvec4& light, std::span<const Aabb> occluders);

}  // namespace shadowlab
