#include "differential/shaft.h"

namespace shadowlab {
namespace {

// The box's corner on side s (+1: max, -1: min) of an axis.
double side(const Aabb& box, int axis, int s) { return s > 0 ? box.max[axis] : box.min[axis]; }

// How far the box sticks out on side s of the axis: larger is further out.
double reach(const Aabb& box, int axis, int s) { return s * side(box, axis, s); }

// The plane through the edges of `ahead` and `behind` at (side si of axis i, side sj of
// axis j), running along the third axis, when `ahead` reaches further on i and `behind`
// further on j: the two corners' line in the (i, j) projection, its normal turned outward.
void addPlane(const Aabb& ahead, const Aabb& behind, int i, int j, int si, int sj, Shaft& shaft) {
    if (!(reach(ahead, i, si) > reach(behind, i, si) && reach(behind, j, sj) > reach(ahead, j, sj))) return;
    const glm::dvec2 p(side(ahead, i, si), side(ahead, j, sj)), q(side(behind, i, si), side(behind, j, sj));
    glm::dvec2 normal(q.y - p.y, p.x - q.x);   // perpendicular to q - p
    if (normal.x * si + normal.y * sj < 0.0) normal = -normal;   // towards the outside corner
    ShaftPlane plane;
    plane.n[i] = normal.x, plane.n[j] = normal.y;
    plane.d = -(normal.x * p.x + normal.y * p.y);
    shaft.planes.push_back(plane);
}

}  // namespace

Shaft makeShaft(const Aabb& a, const Aabb& b) {
    Shaft shaft{{glm::min(a.min, b.min), glm::max(a.max, b.max)}, {}};
    for (int i = 0; i < 3; ++i) {
        for (int j = i + 1; j < 3; ++j) {
            for (int si : {-1, 1}) {
                for (int sj : {-1, 1}) {
                    addPlane(a, b, i, j, si, sj, shaft);
                    addPlane(b, a, i, j, si, sj, shaft);
                }
            }
        }
    }
    return shaft;
}

bool shaftMayTouch(const Shaft& shaft, const Aabb& box) {
    for (int axis = 0; axis < 3; ++axis) {
        if (box.max[axis] < shaft.bounds.min[axis] || box.min[axis] > shaft.bounds.max[axis]) return false;
    }
    for (const ShaftPlane& plane : shaft.planes) {
        // The box's corner furthest inside the plane: if even it is outside, all are.
        const glm::dvec3 inner(plane.n.x > 0.0 ? box.min.x : box.max.x, plane.n.y > 0.0 ? box.min.y : box.max.y,
                               plane.n.z > 0.0 ? box.min.z : box.max.z);
        if (glm::dot(plane.n, inner) + plane.d > 0.0) return false;
    }
    return true;
}

}  // namespace shadowlab
