// A shaft: the region of line space between two axis-aligned boxes, every segment from a
// point of one to a point of the other (Haines, "A shaft culling tool", JGT 2000). Gibson
// et al. 2003 (section 6) build a hierarchy of them between the source and the receiver
// patches and, per frame, test a synthetic object's bounding box against it to find the
// transfers the object may occlude (section 6.1).
//
// The shaft is the box bounding both, cut by the planes through the parallel edges of the
// two boxes where one box sticks out past the other on one axis and falls behind it on
// another: in the projection onto those two axes, the line through the two corners. Both
// boxes lie inside every plane, so the shaft holds their convex hull and the test misses
// no segment; it may accept a box near the shaft's corners that no segment reaches.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scenes/bounds.h"

namespace shadowlab {

// A plane n . p + d <= 0 inside.
struct ShaftPlane {
    glm::dvec3 n{0.0};
    double d = 0.0;
};

struct Shaft {
    Aabb bounds;                      // the box bounding both ends
    std::vector<ShaftPlane> planes;   // at most 12 (two per pair of axes and side), outward normals
};

Shaft makeShaft(const Aabb& a, const Aabb& b);

// True if the box may hold a point of a segment from one end to the other: it overlaps the
// bounds and no plane has it wholly outside. Never false for a box a segment passes through.
bool shaftMayTouch(const Shaft& shaft, const Aabb& box);

}  // namespace shadowlab
