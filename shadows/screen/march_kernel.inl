// The screen-space march's vector core (march_kernel.h), written once against the SIMD value
// types. Included by the per-ISA units (cmake/isa_kernels.cmake) inside a namespace where
// `simd` names one of raster/simd/'s sets. Each line is the float expression of the plain
// march (glm's operations, in their order), lane by lane.

using simd::F32;
using simd::I32;
using simd::Mask;
using simd::kWidth;

struct Vec3 {
    F32 x, y, z;
};

inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
// glm::dot of vec3: (x + y) + z.
inline F32 dot(const Vec3& a, const Vec3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
inline Vec3 splat3(const float* v) { return {simd::splat(v[0]), simd::splat(v[1]), simd::splat(v[2])}; }

// Row r of glm's mat4 * vec4(p, w): (m0 x + m1 y) + (m2 z + m3 w).
inline F32 transformRow(const float* m, int r, const Vec3& p, float w) {
    return (simd::splat(m[r]) * p.x + simd::splat(m[4 + r]) * p.y) +
           (simd::splat(m[8 + r]) * p.z + simd::splat(m[12 + r]) * simd::splat(w));
}

// Component c of the surfaces at pixels q, as three (P) or three (N) lanes' vectors.
inline Vec3 surfaceAt(const MarchSurfaces& s, int c, I32 q) {
    const I32 at = q * simd::splat(int32_t(s.stride));
    return {simd::gather(s.surface[c], at), simd::gather(s.surface[c + 1], at), simd::gather(s.surface[c + 2], at)};
}

// What a pixel's march keeps from step to step.
struct Ray {
    I32 self;                  // the pixel's index
    Vec3 P, dir;
    F32 reach;
    F32 clipX, clipY, clipW, clipDirX, clipDirY, clipDirW;
    F32 depth, depthDir;
};

inline Ray rayOf(const MarchConstants& c, const MarchSurfaces& s, I32 self) {
    Ray r;
    r.self = self;
    r.P = surfaceAt(s, 0, self);
    const Vec3 light = splat3(c.light);
    const Vec3 towards = c.directional ? light : light - r.P;
    const F32 lengthM = simd::splat(c.lengthM), squared = dot(towards, towards);
    // glm::min(lengthM, glm::length(towards)): the second where it is less.
    const F32 length = simd::sqrt(squared);
    r.reach = c.directional ? lengthM : simd::select(simd::cmpLt(length, lengthM), length, lengthM);
    // glm::normalize: v * (1 / sqrt(v . v)).
    const F32 inverse = simd::splat(1.0f) / simd::sqrt(squared);
    r.dir = {towards.x * inverse, towards.y * inverse, towards.z * inverse};
    // The projection is linear in homogeneous coordinates, so along the ray the clip
    // position and the view depth are the start's plus t times the direction's (McGuire and
    // Mara 2014 march in homogeneous clip space the same way): no matrix per sample.
    const float* m = c.clipFromWorld;
    r.clipX = transformRow(m, 0, r.P, 1.0f), r.clipY = transformRow(m, 1, r.P, 1.0f);
    r.clipW = transformRow(m, 3, r.P, 1.0f);
    r.clipDirX = transformRow(m, 0, r.dir, 0.0f), r.clipDirY = transformRow(m, 1, r.dir, 0.0f);
    r.clipDirW = transformRow(m, 3, r.dir, 0.0f);
    const Vec3 forward = splat3(c.forward);
    r.depth = dot(r.P - splat3(c.eye), forward), r.depthDir = dot(r.dir, forward);
    return r;
}

struct Sample {
    F32 distance, pixelX, pixelY, sampleDepth, bufferDepth;
    Mask onScreen;             // of the lanes asked for: the sample projects into the image
    Mask occluded;             // of those: it lies inside the buffer's surface
};

// Step `step` (from 1) of the lanes `live`; the others' figures are meaningless.
inline Sample sampleAt(const MarchConstants& c, const MarchSurfaces& s, const Ray& r, int step, Mask live) {
    Sample out;
    const F32 t = (r.reach * simd::splat(float(step))) / simd::splat(float(c.steps));
    out.distance = t;
    const Vec3 S = {r.P.x + r.dir.x * t, r.P.y + r.dir.y * t, r.P.z + r.dir.z * t};
    out.sampleDepth = r.depth + r.depthDir * t;
    // toPixel: OpenGL's window transform of the clip position, row 0 at the top.
    const F32 clipX = r.clipX + r.clipDirX * t, clipY = r.clipY + r.clipDirY * t, clipW = r.clipW + r.clipDirW * t;
    const F32 half = simd::splat(0.5f), width = simd::splat(float(c.width)), height = simd::splat(float(c.height));
    out.pixelX = (clipX / clipW * half + half) * width;
    out.pixelY = (half - clipY / clipW * half) * height;
    const F32 zero = simd::splat(0.0f);
    out.onScreen = live & simd::cmpLe(simd::splat(c.zNear), out.sampleDepth) & simd::cmpLe(zero, out.pixelX) &
                   simd::cmpLe(zero, out.pixelY) & simd::cmpLt(out.pixelX, width) & simd::cmpLt(out.pixelY, height);
    // The pixel under the sample; a lane off the screen reads its own (any pixel would do).
    const I32 i = simd::truncateToInt(simd::select(out.onScreen, out.pixelX, zero));
    const I32 j = simd::truncateToInt(simd::select(out.onScreen, out.pixelY, zero));
    const I32 q = simd::select(out.onScreen, j * simd::splat(int32_t(c.width)) + i, r.self);
    const Vec3 Pq = surfaceAt(s, 0, q), Nq = surfaceAt(s, 3, q);
    // The buffer's plane at q met by the camera ray through S: with h = (S - Pq).Nq and
    // a = (S - eye).Nq, the ray reaches the plane at the fraction 1 - h / a of the way
    // to S, so S lies h / a of its depth behind the plane when h, a < 0.
    const F32 h = dot(S - Pq, Nq), a = dot(S - splat3(c.eye), Nq);
    const Mask inFront = simd::cmpLt(a, zero);   // never where N = 0: no surface
    const F32 behind = out.sampleDepth * (h / a);
    out.bufferDepth = simd::select(inFront, out.sampleDepth - behind, simd::splat(__builtin_inff()));
    // A pixel's own plane never shadows it. Elsewhere a sample must lie behind the plane
    // by more than a pixel's footprint at its depth: a pixel on a silhouette holds a plane
    // that ends inside it, and extended past that edge it would shadow the samples just
    // above it; the margin also covers float rounding, so a plane seen through its own
    // pixels never shadows itself.
    const Mask ownPixel = simd::cmpEq(q, r.self);
    out.occluded = out.onScreen & inFront & !ownPixel &
                   simd::cmpLt(simd::splat(c.pixelFootprint) * out.sampleDepth, behind) &
                   simd::cmpLe(behind, simd::splat(c.thicknessM));
    return out;
}

inline I32 selfIndex(const MarchRow& row, int n) { return simd::splat(int32_t(row.first + n)) + simd::laneIndex(); }
inline Mask activeLanes(const MarchRow& row, int n) {
    return !simd::cmpEq(simd::loadU8(row.active + n), simd::splat(int32_t(0)));
}

// Each lane marches until its first occluded sample, or until the ray leaves the screen.
inline void maskRun(const MarchConstants& c, const MarchSurfaces& s, const MarchRow& row, const MarchMaskOut& out) {
    const I32 lit = simd::splat(int32_t(kMarchLit)), occludedEnd = simd::splat(int32_t(kMarchOccluded));
    for (int n = 0; n < row.count; n += kWidth) {
        Mask live = activeLanes(row, n);
        I32 end = lit;
        if (simd::any(live)) {
            const Ray r = rayOf(c, s, selfIndex(row, n));
            for (int step = 1; step <= c.steps && simd::any(live); ++step) {
                const Sample x = sampleAt(c, s, r, step, live);
                end = simd::select(live & !x.onScreen, simd::splat(int32_t(kMarchLeftScreen)), end);
                end = simd::select(x.occluded, occludedEnd, end);
                live = x.onScreen & !x.occluded;
            }
        }
        simd::storeU8(out.end + n, end);
        simd::store(out.visibility + n,
                    simd::select(simd::cmpEq(end, occludedEnd), simd::splat(0.0f), simd::splat(1.0f)));
    }
}

// Each lane's every step while its ray stays on the screen, occluded or not.
inline void traceRun(const MarchConstants& c, const MarchSurfaces& s, const MarchRow& row, const MarchTraceOut& out) {
    const I32 one = simd::splat(int32_t(1)), none = simd::splat(int32_t(0));
    for (int n = 0; n < row.count; n += kWidth) {
        Mask live = activeLanes(row, n);
        I32 samples = none;
        const Ray r = rayOf(c, s, selfIndex(row, n));
        for (int step = 1; step <= c.steps; ++step) {
            const Sample x = sampleAt(c, s, r, step, live);
            live = x.onScreen;
            samples = simd::select(live, samples + one, samples);
            const size_t at = size_t(step - 1) * size_t(row.count) + size_t(n);
            simd::store(out.distance + at, x.distance), simd::store(out.sampleDepth + at, x.sampleDepth);
            simd::store(out.pixelX + at, x.pixelX), simd::store(out.pixelY + at, x.pixelY);
            simd::store(out.bufferDepth + at, x.bufferDepth);
            simd::store(out.occluded + at, simd::select(x.occluded, one, none));
        }
        simd::store(out.samples + n, samples);
    }
}

// The table the per-ISA unit hands out (cmake/isa_kernels.cmake).
inline MarchKernels kernels() { return {kWidth, maskRun, traceRun}; }
