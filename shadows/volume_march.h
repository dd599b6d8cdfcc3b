// The voxels a segment crosses in a density volume, in order, by the 3D DDA of Amanatides
// and Woo ("A fast voxel traversal algorithm for ray tracing", Eurographics 1987): after
// clipping the segment to the volume's box, step to whichever voxel face the segment meets
// next. The extinction sigma is constant inside a voxel, so the optical depth along the
// segment is exactly the sum of sigma times the length inside each voxel, and the light
// passing through is exp(-optical depth) (Real-Time Rendering, 4th ed., section 14.1.2,
// Beer-Lambert).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include <glm/glm.hpp>

#include "raster/portable_math.h"
#include "scenes/scene.h"

namespace shadowlab {

// Calls visit(t0, t1, sigma) for every voxel the segment a + t (b - a), t in [0, 1],
// crosses inside the volume, t0 < t1 in order along the segment.
template <class Visit>
void marchVoxels(const DensityVolume& volume, const glm::dvec3& a, const glm::dvec3& b, Visit&& visit) {
    const glm::dvec3 d = b - a, lo(volume.min), hi(volume.max);
    double tEnter = 0.0, tLeave = 1.0;
    for (int axis = 0; axis < 3; ++axis) {   // the slab test
        if (d[axis] == 0.0) {
            if (a[axis] < lo[axis] || a[axis] > hi[axis]) return;
            continue;
        }
        const double t0 = (lo[axis] - a[axis]) / d[axis], t1 = (hi[axis] - a[axis]) / d[axis];
        tEnter = std::max(tEnter, std::min(t0, t1)), tLeave = std::min(tLeave, std::max(t0, t1));
    }
    if (!(tEnter < tLeave)) return;
    const glm::dvec3 voxel = (hi - lo) / glm::dvec3(volume.resolution);
    const glm::dvec3 entry = a + 0.5 * (tEnter + tLeave) * d;   // a point surely inside, for no cell's doubt
    glm::ivec3 cell, step;
    for (int axis = 0; axis < 3; ++axis) {
        const double start = a[axis] + tEnter * d[axis];
        // The entry point's cell, the segment's midpoint deciding a point on a face.
        const double at = d[axis] == 0.0 ? entry[axis] : start;
        cell[axis] = std::clamp(int(std::floor((at - lo[axis]) / voxel[axis])), 0, volume.resolution[axis] - 1);
        step[axis] = d[axis] > 0.0 ? 1 : d[axis] < 0.0 ? -1 : 0;
    }
    // The t at which the segment leaves the current cell through its face on `axis`.
    const auto faceT = [&](int axis) {
        if (step[axis] == 0) return std::numeric_limits<double>::infinity();
        const double face = lo[axis] + double(cell[axis] + (step[axis] > 0 ? 1 : 0)) * voxel[axis];
        return (face - a[axis]) / d[axis];
    };
    double t = tEnter;
    while (t < tLeave) {
        int axis = 0;
        double next = faceT(0);
        for (int k = 1; k < 3; ++k) {
            const double tk = faceT(k);
            if (tk < next) next = tk, axis = k;
        }
        const double end = std::min(std::max(next, t), tLeave);
        if (end > t) visit(t, end, double(volume.at(cell.x, cell.y, cell.z)));
        t = end;
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= volume.resolution[axis]) break;
    }
}

// The optical depth, sum of sigma times length, along the segment a -> b through every volume.
inline double opticalDepth(std::span<const DensityVolume> volumes, const glm::dvec3& a, const glm::dvec3& b) {
    const double length = glm::length(b - a);
    double depth = 0.0;
    for (const DensityVolume& volume : volumes) {
        marchVoxels(volume, a, b, [&](double t0, double t1, double sigma) { depth += sigma * (t1 - t0) * length; });
    }
    return depth;
}

}  // namespace shadowlab
