// One shadow map per cluster of sources (Gibson et al. 2003, section 8): a point light at the
// centre of the cluster's most energetic patch, looking at the synthetic object, which is
// all that casts (the real scene's own shadows are already in the photograph and in the
// transfers' visibility). The frustum is the cone around the object's bounding sphere, so
// every texel of the map is spent on the object, and the map is drawn from the object's
// simplified level (object_levels.h).
#pragma once

#include <glm/glm.hpp>

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shadows/depth_map.h"

namespace shadowlab {

struct ClusterMap {
    glm::dvec3 light{0.0};
    DepthMap map;
};

ClusterMap clusterShadowMap(const glm::dvec3& light, const glm::dvec3& sphereCentre, double sphereRadius,
                            const WorldGeometry& casters, int size, raster::SimdLevel simd);

// M_ij at a point: whether the object hides the cluster's light from P. A point behind the
// light, outside the map or where no caster was drawn is lit; otherwise it is shadowed when
// its window depth lies behind the drawn one.
bool occluded(const ClusterMap& cluster, const glm::dvec3& P);

}  // namespace shadowlab
