// The choice of izb's vector kernels by SIMD level, and the scalar build's one-segment test
// that the tests hold every level to (kernels.h; the builds are cmake/isa_kernels.cmake's).
#include "raster/tile_kernels.h"
#include "shadows/izb/izb.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {

Kernels kernels(raster::SimdLevel simd) {
    return raster::forSimdLevel(simd, kernelsScalar, kernelsAvx2, kernelsAvx512);
}

bool segmentBlocked(const glm::dvec3& origin, const glm::dvec3& towardsLight, double tFar,
                    const glm::dvec3 (&triangle)[3]) {
    const double o[3] = {origin.x, origin.y, origin.z}, d[3] = {towardsLight.x, towardsLight.y, towardsLight.z};
    const double vertices[9] = {triangle[0].x, triangle[0].y, triangle[0].z, triangle[1].x, triangle[1].y,
                                triangle[1].z, triangle[2].x, triangle[2].y, triangle[2].z};
    return kernelsScalar().segmentBlocked(o, d, tFar, vertices);
}

}  // namespace shadowlab::izb
