// The irregular z-buffer's two per-receiver loops (segments.inl, occlusion.inl) for the
// instruction set `simd` names, and the table the per-ISA unit hands out
// (cmake/isa_kernels.cmake; kernels.h).
#include "shadows/izb/segments.inl"
#include "shadows/izb/occlusion.inl"

inline bool oneSegmentBlocked(const double (&origin)[3], const double (&towardsLight)[3], double tFar,
                              const double (&triangle)[9]) {
    const auto lanes = [](const double* v) {
        return Vec3Lanes{simd::splat64(v[0]), simd::splat64(v[1]), simd::splat64(v[2])};
    };
    const Vec3Lanes vertices[3] = {lanes(triangle), lanes(triangle + 3), lanes(triangle + 6)};
    const Mask64 hit = segmentsBlocked(lanes(origin), lanes(towardsLight), simd::splat64(tFar), vertices);
    return (simd::laneBits(hit) & 1u) != 0;   // every lane holds the same segment
}

inline Kernels kernels() { return {computeSegments, blockRun, crossRun, oneSegmentBlocked}; }
