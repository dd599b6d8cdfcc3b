// Irregular z-buffer, stage 1: each receiving point's shadow segment, exactly as the
// reference's shadow ray (shadows/reference/reference.cpp, shadows/ray_offset.cpp), a
// vector of points at a time in double precision. Written against the SIMD types of
// raster/simd/ (a namespace alias `simd` chosen by the including file).
//
// The origin is P moved along N by the offset and rounded to float once, as the ray's is;
// the segment ends `offset` short of a point light: tFar = 1 - offset / |L - origin|, in
// units of the direction L - origin. A directional light's segment is unbounded.

inline void computeSegments(const SegmentConstants& c, const PointColumns& p, uint32_t count, const SegmentColumns& out) {
    const simd::F64 diagonal = simd::splat64(c.sceneDiagonal), perScale = simd::splat64(c.offsetPerScale);
    const simd::F64 lx = simd::splat64(c.light[0]), ly = simd::splat64(c.light[1]), lz = simd::splat64(c.light[2]);
    const simd::F64 one = simd::splat64(1.0), unbounded = simd::splat64(__builtin_inf());
    const bool directional = c.light[3] == 0.0;
    for (uint32_t k = 0; k < count; k += simd::kWidth64) {
        const simd::F64 x = simd::load(p.x + k), y = simd::load(p.y + k), z = simd::load(p.z + k);
        const simd::F64 largest = simd::max(simd::max(simd::abs(x), simd::abs(y)), simd::abs(z));
        const simd::F64 offset = perScale * simd::max(largest, diagonal);
        const simd::F64 ox = simd::roundToFloat(x + offset * simd::load(p.nx + k));
        const simd::F64 oy = simd::roundToFloat(y + offset * simd::load(p.ny + k));
        const simd::F64 oz = simd::roundToFloat(z + offset * simd::load(p.nz + k));
        simd::store(out.x + k, ox), simd::store(out.y + k, oy), simd::store(out.z + k, oz);
        if (directional) {
            simd::store(out.tFar + k, unbounded);
            continue;
        }
        const simd::F64 dx = lx - ox, dy = ly - oy, dz = lz - oz;
        simd::store(out.tFar + k, one - offset / simd::sqrt(dx * dx + dy * dy + dz * dz));
    }
}
