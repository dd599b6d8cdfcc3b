#include "raster/clip.h"

#include "raster/fixed_point.h"

namespace shadowlab::raster {
namespace {

constexpr int kClipPlaneCount = 6;
enum ClipPlane { kNear, kFar, kGuardLeft, kGuardRight, kGuardBottom, kGuardTop };

// Signed distance to plane k in clip space: >= 0 inside.
float planeDistance(int plane, const glm::vec4& p, const ClipVolume& v) {
    switch (plane) {
        case kNear: return p.z + p.w;
        case kFar: return p.w - p.z;
        case kGuardLeft: return p.x + v.guardX * p.w;
        case kGuardRight: return v.guardX * p.w - p.x;
        case kGuardBottom: return p.y + v.guardY * p.w;
        default: return v.guardY * p.w - p.y;
    }
}

// The point where edge inside -> outside leaves the plane. Always computed from the
// inside vertex, so two triangles sharing the edge produce the same bits (watertight).
ClipVertex intersect(const ClipVertex& inside, float dInside, const ClipVertex& outside, float dOutside,
                     int varyingCount) {
    const float t = dInside / (dInside - dOutside);
    ClipVertex r;
    r.position = inside.position + t * (outside.position - inside.position);
    for (int k = 0; k < varyingCount; ++k) {
        r.varyings[k] = inside.varyings[k] + t * (outside.varyings[k] - inside.varyings[k]);
    }
    return r;
}

int clipAgainstPlane(int plane, const ClipVertex* in, int n, ClipVertex* out, const ClipVolume& volume,
                     int varyingCount) {
    int count = 0;
    for (int i = 0; i < n; ++i) {
        const ClipVertex& a = in[i];
        const ClipVertex& b = in[(i + 1) % n];
        const float da = planeDistance(plane, a.position, volume);
        const float db = planeDistance(plane, b.position, volume);
        if (count + 2 > kMaxClippedVertices) return 0;   // a degenerate sliver: drop it
        if (da >= 0.0f) out[count++] = a;
        if ((da >= 0.0f) != (db >= 0.0f)) {
            out[count++] = da >= 0.0f ? intersect(a, da, b, db, varyingCount) : intersect(b, db, a, da, varyingCount);
        }
    }
    return count;
}

}  // namespace

ClipVolume clipVolumeFor(int width, int height, bool clipFar) {
    // Window x = (x/w + 1) * width/2, so |window x - width/2| <= G  <=>  |x/w| <= 2G/width.
    return {clipFar, float(2.0 * kGuardBandPixels / width), float(2.0 * kGuardBandPixels / height)};
}

uint32_t clipOutcode(const glm::vec4& p, const ClipVolume& volume) {
    uint32_t code = 0;
    for (int k = 0; k < kClipPlaneCount; ++k) {
        if (k == kFar && !volume.clipFar) continue;
        if (planeDistance(k, p, volume) < 0.0f) code |= 1u << k;
    }
    return code;
}

uint32_t viewportOutcode(const glm::vec4& p, const ClipVolume& volume) {
    uint32_t code = 0;
    if (p.x < -p.w) code |= 1u;
    if (p.x > p.w) code |= 2u;
    if (p.y < -p.w) code |= 4u;
    if (p.y > p.w) code |= 8u;
    if (p.z < -p.w) code |= 16u;
    if (volume.clipFar && p.z > p.w) code |= 32u;
    return code;
}

int clipPolygon(ClipVertex* polygon, int n, uint32_t outcodes, const ClipVolume& volume, int varyingCount) {
    ClipVertex scratch[kMaxClippedVertices];
    ClipVertex* in = polygon;
    ClipVertex* out = scratch;
    for (int plane = 0; plane < kClipPlaneCount && n > 0; ++plane) {
        if (!(outcodes & (1u << plane))) continue;
        n = clipAgainstPlane(plane, in, n, out, volume, varyingCount);
        ClipVertex* swap = in;
        in = out;
        out = swap;
    }
    if (in != polygon) {
        for (int i = 0; i < n; ++i) polygon[i] = in[i];
    }
    return n;
}

}  // namespace shadowlab::raster
