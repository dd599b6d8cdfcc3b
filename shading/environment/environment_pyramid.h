// The environment map as a pyramid of ever coarser latitude-longitude grids, for integrals
// that need the map finely only near one direction (prefiltered_lobe.h). Level 0 is the map;
// texel (i, j) of level l + 1 is the union of texels 2i..2i+1 by 2j..2j+1 of level l (one
// column or row where the finer level's count is odd), so every level tiles the sphere
// exactly as the map does. A coarse texel's radiance is its children's sum of L dOmega over
// their solid angle, the mean of the piecewise-constant map over the region (environment_map.h),
// so the integral of radiance over any tiling of the sphere by texels of mixed levels is the
// map's integral.
//
// Each texel keeps, structure of arrays, what an integrator needs: the unit direction of its
// centre (the midpoint of its rows' polar angles and its columns' azimuths, rotation
// included), its exact solid angle, its mean radiance, the luminance of its brightest map
// texel, and the cosine and sine of its angular extent s, the larger of its height in radians
// and its width along the parallel nearest the equator, (theta_1 - theta_0) and
// sin(theta*) (phi_1 - phi_0): every point of the texel is within s of its centre.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"

namespace shadowlab {

struct PyramidLevel {
    int width = 0, height = 0;
    std::vector<double> x, y, z;         // centre direction per texel, row-major
    std::vector<double> solidAngle;      // exact, per texel
    std::vector<double> cosExtent, sinExtent;
    std::vector<glm::dvec3> radiance;    // the map's mean over the texel
    std::vector<double> brightest;       // the largest luminance of the map's texels in it

    size_t index(int i, int j) const { return size_t(j) * size_t(width) + size_t(i); }
};

struct EnvironmentPyramid {
    std::vector<PyramidLevel> levels;    // levels[0] is the map; the last is at most 8 x 4 texels
};

// Halves the grid until it is at most 8 texels wide or 4 high. Rows of each level are built
// in parallel, each by one task, so the same bits for any thread count.
EnvironmentPyramid buildPyramid(const EnvironmentMap& map);

}  // namespace shadowlab
