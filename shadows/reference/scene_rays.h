// The exact reference's rays for a prepared scene's casters: one Embree BVH, built by the
// first frame that asks and kept with the scene for every later frame, light and technique
// (PreparedScene::derived), as the edge adjacency is, until an instance moves
// (PreparedScene::setInstanceTransforms): the BVH is then dropped with the rest of what
// derives from world geometry, and the next frame that asks builds it again. A refit would
// give the same answers (robust traversal is exact for any tree), but Embree 3.13.5 refits
// a geometry of RTC_BUILD_QUALITY_REFIT only in a dynamic scene of low build quality: in a
// static or medium-quality scene its commit rebuilds the whole BVH (measured on a 3.9 M
// triangle grid, 6 December 2026). Whether that scene's two-level BVH traces as fast is
// not measured, so a move rebuilds.
#pragma once

#include <optional>

#include "scenes/prepared_scene.h"
#include "shadows/reference/reference.h"

namespace shadowlab {

// The rays through the casters of `casters` (ShadowInputs::casters()), through their
// cut-outs' holes, translucent surfaces and volumes as every reference sees them.
// `builtMs`, if given, gets the build's wall time on the call that built it, and nothing on
// every other.
const ReferenceVisibility& sceneRays(const PreparedScene& casters, std::optional<double>* builtMs = nullptr);

}  // namespace shadowlab
