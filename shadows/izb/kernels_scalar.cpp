// The irregular z-buffer's kernels (segments.inl, occlusion.inl) compiled for the scalar
// SIMD types: the plain twins of the vector builds, the one-receiver test segmentBlocked()
// built from the same source, and the choice of kernels by SIMD level.
#include "raster/simd/simd_scalar.h"
#include "raster/tile_kernels.h"
#include "shadows/izb/izb.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {
namespace kernels_scalar {
namespace simd = shadowlab::simd_scalar;
#include "shadows/izb/segments.inl"
#include "shadows/izb/occlusion.inl"
}  // namespace kernels_scalar

Kernels kernelsScalar() { return {kernels_scalar::computeSegments, kernels_scalar::blockRun}; }

Kernels kernels(raster::SimdLevel simd) { return raster::forSimdLevel(simd, kernelsScalar, kernelsAvx2, kernelsAvx512); }

bool segmentBlocked(const glm::dvec3& origin, const glm::dvec3& towardsLight, double tFar,
                    const glm::dvec3 (&triangle)[3]) {
    using simd_scalar::F64;
    const auto lanes = [](const glm::dvec3& v) { return kernels_scalar::Vec3Lanes{F64{v.x}, F64{v.y}, F64{v.z}}; };
    const kernels_scalar::Vec3Lanes vertices[3] = {lanes(triangle[0]), lanes(triangle[1]), lanes(triangle[2])};
    return kernels_scalar::segmentsBlocked(lanes(origin), lanes(towardsLight), F64{tFar}, vertices).v;
}

}  // namespace shadowlab::izb
