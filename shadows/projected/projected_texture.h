// `projected-texture`: projected shadow textures on chosen receivers (RTR 4th ed.,
// section 7.2, "Shadows on Curved Surfaces"). The stages, one per file:
//
//   1. instance_roles.h: which instances are occluders and which receivers (parameters
//      `occluders` and `receivers`; by default the "ground" instances receive and the
//      rest occlude);
//   2. occluder_view.h: the light's view fitted to the occluders;
//   3. occluder_texture.h: the occluders drawn through it into a binary texture;
//   4. texture_projection.h: the texture projected onto the receiver pixels, V = 0 where
//      it is covered.
//
// Its failures are the method's, kept and asserted by the tests: no self-shadowing (an
// occluder is never shadowed, by itself or by others), shadows cast backward onto a
// receiver between the light and an occluder, and no shadow on anything not chosen.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique projectedTextureTechnique();

}  // namespace shadowlab
