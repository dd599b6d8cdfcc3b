// The exact reference's rays for a prepared scene's casters: one Embree BVH, built by the
// first frame that asks and kept with the scene for every later frame, light and technique
// (PreparedScene::derived), as the edge adjacency is. A PreparedScene's meshes and
// instances are fixed (scenes/prepared_scene.h), so the BVH never needs a refit or a
// rebuild; geometry that moves is another PreparedScene, with a BVH of its own.
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
