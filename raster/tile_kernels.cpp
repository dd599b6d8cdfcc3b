#include "raster/tile_kernels.h"

#include <stdexcept>

namespace shadowlab::raster {

bool simdLevelSupported(SimdLevel level) {
    switch (level) {
        case SimdLevel::Scalar: return true;
        case SimdLevel::Avx2: return __builtin_cpu_supports("avx2");
        case SimdLevel::Avx512: return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw");
    }
    return false;
}

SimdLevel bestSimdLevel() {
    if (simdLevelSupported(SimdLevel::Avx512)) return SimdLevel::Avx512;
    if (simdLevelSupported(SimdLevel::Avx2)) return SimdLevel::Avx2;
    return SimdLevel::Scalar;
}

void requireSimdLevel(SimdLevel level) {
    if (!simdLevelSupported(level)) {
        throw std::invalid_argument(std::string("this CPU does not support SIMD level ") + simdLevelName(level));
    }
}

const RasterKernels& rasterKernels(SimdLevel level) {
    return forSimdLevel(level, rasterKernelsScalar, rasterKernelsAvx2, rasterKernelsAvx512);
}

const char* simdLevelName(SimdLevel level) {
    switch (level) {
        case SimdLevel::Avx2: return "avx2";
        case SimdLevel::Avx512: return "avx512";
        default: return "scalar";
    }
}

SimdLevel parseSimdLevel(const std::string& name) {
    if (name == "auto") return bestSimdLevel();
    for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Avx2, SimdLevel::Avx512}) {
        if (name == simdLevelName(level)) return level;
    }
    throw std::invalid_argument("unknown SIMD level '" + name + "' (scalar, avx2, avx512 or auto)");
}

}  // namespace shadowlab::raster
