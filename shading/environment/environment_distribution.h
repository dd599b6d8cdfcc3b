// Importance sampling of an environment map (Pharr, Jakob and Humphreys, Physically Based
// Rendering, 4th ed., section 12.5, the piecewise-constant 2D distribution): a texel is
// chosen with probability proportional to its luminance times its solid angle, a row from
// the rows' marginal sums and a column within it, then a direction uniformly over the texel's
// region of the sphere (uniform in azimuth and in cos theta between its edges), so the
// density of a direction d is
//
//     p(d) = luminance(L_t) dOmega_t / (sum over texels of luminance dOmega) / dOmega_t
//
// for the texel t whose region holds d: the map's own piecewise-constant function
// (environment_map.h), normalised. A map of no luminance anywhere has no distribution:
// empty() is true and the sampler may not be used.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"

namespace shadowlab {

struct EnvironmentSample {
    glm::dvec3 direction{0.0, 1.0, 0.0};   // unit, world space (rotation included)
    double pdf = 0.0;                      // per steradian
};

class EnvironmentDistribution {
public:
    // Keeps a reference to the map, which must outlive the distribution.
    explicit EnvironmentDistribution(const EnvironmentMap& map);

    bool empty() const { return total_ <= 0.0; }
    // A direction from four uniform numbers in [0, 1): row, column, azimuth, height.
    EnvironmentSample sample(const glm::dvec4& u) const;
    // p(d) for any direction (not empty()).
    double pdf(const glm::dvec3& direction) const;

private:
    const EnvironmentMap& map_;
    std::vector<double> rowCdf_;       // height + 1 entries, from 0 to total
    std::vector<double> columnCdf_;    // per row, width + 1 entries from 0 to the row's sum
    std::vector<double> weight_;       // per texel: luminance times solid angle
    double total_ = 0.0;
};

}  // namespace shadowlab
