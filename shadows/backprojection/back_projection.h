// Backprojection, stage 2: the occluder patches seen from the receiver, projected onto the
// light's plane, and the light samples they hide set in a bitmask (Guennebaud et al. 2006,
// section 3.2; Schwarz and Stamminger 2007, section 3, whose bitmasks replace the sum of
// covered areas, so that overlapping patches hide a sample once: occluder fusion, and no
// double counting where neighbouring patches overlap).
//
// Gaps. Neighbouring texels at different depths are squares at different distances, and
// seen from the receiver the light shows between them (Guennebaud et al., section 3.3).
// Here a patch's corners are shared with the neighbours it is joined to, those the map
// shows on one surface with it (surface_joins.h: the step between them against the steps
// beside it, so a surface steep as seen from the light still joins): at each corner
// the patches joined through the edges that meet there take the least depth among them,
// so a continuous occluder surface becomes one closed mesh and its back-projection has no
// gaps. Across an edge between two surfaces each keeps its own depth: no skirt joins them.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shading/light_sampling.h"
#include "shadows/backprojection/light_bitmask.h"
#include "shadows/backprojection/light_pyramid.h"
#include "shadows/backprojection/occluder_patches.h"
#include "shadows/backprojection/surface_joins.h"
#include "shadows/filtered/soft_shadow_map.h"

namespace shadowlab {

// Per-task working memory, reused across pixels.
struct BackProjectionScratch {
    std::vector<uint8_t> joined;            // per grid node: bit 0 joined to the right, bit 1 below
    std::vector<glm::vec2> cornerOnLight;   // (width + 1) x (height + 1) corners, 4 groups each
    std::vector<uint8_t> cornerState;       // 0 not projected yet, 1 on the light's plane, 2 invalid
};

// Sets in `mask` the samples of `samples` that the grid's occluder patches hide from P;
// returns the number of patches projected (a grid patch `pyramid` proves off the light is
// not). Stops early once every sample is hidden. With `drawn`, appends each projected
// patch's four corners in (a, b) (the debug view).
int backProjectPatches(const PatchGrid& grid, const SurfaceJoins& joins, const SoftShadowMap& soft,
                       const glm::dvec3& P, const AreaLightPlane& light, const LightPyramid& pyramid,
                       const LightGrid& samples, LightBitmask& mask, BackProjectionScratch& scratch,
                       std::vector<glm::vec2>* drawn = nullptr);

}  // namespace shadowlab
