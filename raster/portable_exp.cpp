#include "raster/portable_exp.h"

namespace shadowlab::portable {

void expRun(raster::SimdLevel simd, const double* x, double* out, size_t count) {
    const ExpKernel vector = raster::forSimdLevel(simd, expKernelScalar, expKernelAvx2, expKernelAvx512);
    const size_t body = count / size_t(vector.width) * size_t(vector.width);
    vector.run(x, out, body);
    expKernelScalar().run(x + body, out + body, count - body);
}

}  // namespace shadowlab::portable
