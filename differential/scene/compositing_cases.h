// The built-in compositing cases (Gibson et al. 2003, Figure 7 and section 9).
//
// The room: a 4 x 2.5 x 4 m room with a desk, an emitting ceiling panel and a window on the
// right wall seen as a bright source. Its "photograph" is rendered from the model itself
// (differential/background.h), so the right answer is known. The synthetic
// object is the low-resolution bunny, about 0.4 m tall, on the floor in front of the desk.
#pragma once

#include <string>
#include <vector>

#include "differential/scene/compositing_scene.h"

namespace shadowlab {

// The object's path through the frames:
//   Lift:      on the floor, then raised 0.1 m per frame to 0.6 m (Figure 7, left)
//   UnderDesk: slid in 11 steps from the open floor to under the desk, where its shadow
//              merges with the desk's (Figure 7, right)
enum class RoomPath { Lift, UnderDesk };

// `object` is the mesh to place (a 10-unit-tall bunny, scaled by 0.04, in the built-in
// cases). Throws std::invalid_argument for a size outside 16..4096 pixels per side.
CompositingScene compositingRoom(const Mesh& object, RoomPath path, int width = 640, int height = 400);

}  // namespace shadowlab
