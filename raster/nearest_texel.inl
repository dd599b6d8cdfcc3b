// The texel a texture coordinate reads: the nearest texel of the wrapped coordinate (u right,
// v up, as in OBJ; row 0 at the top). The one rule every texture here is read by, written
// once against the SIMD interface (raster/simd/): the rasterizer's alpha test compiles it
// per instruction set (tile_raster.inl), and raster/nearest_texel.h with the scalar types
// for everything outside the kernels (the surface's albedo, the references' and the
// irregular z-buffer's cut-outs), so every path agrees on every texel, bit for bit.

// s wrapped into [0, 1] (OpenGL 4.6 section 8.14.2, in normalized coordinates):
//   ClampToEdge:    s itself (clamped by the caller);
//   Repeat:         s - floor(s): an integer reads as 0 (texel 0), -0.25 as 0.75;
//   MirroredRepeat: t = s - 2 floor(s / 2), in [0, 2), then min(t, 2 - t): even integers
//                   read as 0, odd ones as 1 (the last texel), -0.25 as 0.25, 1.25 as 0.75.
// Exact for s >= 0. For s < 0 the sum may round up to the period's end (s = -1e-10:
// Repeat gives 1, MirroredRepeat t = 2, i.e. 0), the texel beside the edge either way.
// NaN and infinities give NaN, which the clamp below reads as 0.
inline simd::F32 wrapTextureCoordinate(TextureWrap wrap, simd::F32 s) {
    switch (wrap) {
        case TextureWrap::Repeat: return s - simd::floor(s);
        case TextureWrap::MirroredRepeat: {
            const simd::F32 half = simd::floor(s * simd::splat(0.5f));
            const simd::F32 t = s - (half + half);
            return simd::min(t, simd::splat(2.0f) - t);
        }
        case TextureWrap::ClampToEdge: break;
    }
    return s;
}

// The row-major index of the texel (u, v) reads in a width x height texture: each
// coordinate wrapped, clamped to [0, 1] (max first, so NaN reads as 0), then column
// floor(u W) and row floor((1 - v) H), the edge's texel at 1.
inline simd::I32 nearestTexelIndex(int width, int height, UvWrap wrap, simd::F32 u, simd::F32 v) {
    const simd::F32 zero = simd::splat(0.0f), one = simd::splat(1.0f);
    const simd::F32 s = simd::min(simd::max(wrapTextureCoordinate(wrap.u, u), zero), one);
    const simd::F32 t = simd::min(simd::max(wrapTextureCoordinate(wrap.v, v), zero), one);
    const simd::I32 column =
        simd::min(simd::truncateToInt(s * simd::splat(float(width))), simd::splat(int32_t(width - 1)));
    const simd::I32 row =
        simd::min(simd::truncateToInt((one - t) * simd::splat(float(height))), simd::splat(int32_t(height - 1)));
    return row * simd::splat(int32_t(width)) + column;
}
