// A frame of differential rendering seen from above (docs/differential-rendering.md): the
// receivers in plan, those the traversal listed filled, the leaf shafts the object's box
// touched drawn from each of their source patches to their receiver node, each source
// coloured by the cluster that holds it, each cluster's light ringed, and the objects'
// boxes: the "shafts the object touches" and "the clusters" of Gibson et al. 2003
// (sections 6.1 and 8).
#pragma once

#include <string>

#include "differential/composite.h"

namespace shadowlab {

// x to the right and z downwards, fitted to the receivers and the object's box (sources
// farther out, such as a sky dome, are cut off at the frame).
std::string formatPlanSvg(const DifferentialModel& model, const CompositeFrame& frame,
                          const std::vector<Aabb>& objectBoxes);

}  // namespace shadowlab
