// The shadow-map lookup's vector core (lookup_kernel.h), written once against the SIMD value
// types. Included by the per-ISA units (cmake/isa_kernels.cmake) inside a namespace where
// `simd` names one of raster/simd/'s sets; each lane does the same float operations in the
// same order at every width. Three stages over a run of receivers: whether the light
// reaches each (reachRun), each projected into the map serving it with the bias
// (projectRun), and the filter's taps there (filterRun).

using simd::F32;
using simd::I32;
using simd::Mask;
using simd::kWidth;

// The receiver plane's tolerance (receiver_plane_tolerance.h), in float.
constexpr float kRasterPositionErrorTexels = float(receiver_plane::kRasterPositionErrorTexels);
constexpr float kDepthTolerance = float(receiver_plane::kDepthErrorSteps * receiver_plane::kDepthStep);

struct Vec3 {
    F32 x, y, z;
};

inline F32 dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline F32 abs(F32 a) { return simd::max(a, simd::splat(0.0f) - a); }
inline Mask isFinite(F32 a) { return simd::cmpEq(a - a, simd::splat(0.0f)); }

// Row r of M (p, 1) for a column-major 4x4 matrix.
inline F32 transformRow(const float* m, int r, const Vec3& p) {
    return simd::splat(m[r]) * p.x + simd::splat(m[4 + r]) * p.y + simd::splat(m[8 + r]) * p.z + simd::splat(m[12 + r]);
}

// M (p, 1) divided by w: for texelFromWorld, (texel x, texel y, window depth).
inline Vec3 project(const float* m, const Vec3& p, F32& w) {
    w = transformRow(m, 3, p);
    return {transformRow(m, 0, p) / w, transformRow(m, 1, p) / w, transformRow(m, 2, p) / w};
}
inline Vec3 project(const float* m, const Vec3& p) {
    F32 w;
    return project(m, p, w);
}

// floor(c) as an integer, saturated to +-2^30 (NaN to -2^30) so that every lane converts;
// the map clamps it afterwards (DepthMap::at, texelIndexOf in double).
inline I32 texelIndexOf(F32 c) {
    const F32 limit = simd::splat(1073741824.0f);
    const F32 saturated = simd::select(simd::cmpLt(simd::splat(0.0f) - limit, c),
                                       simd::select(simd::cmpLt(c, limit), c, limit), simd::splat(0.0f) - limit);
    const I32 truncated = simd::truncateToInt(saturated);
    return truncated - simd::select(simd::cmpLt(saturated, simd::toFloat(truncated)), simd::splat(int32_t(1)),
                                    simd::splat(int32_t(0)));
}

// Storage index of texel (x, y), clamped to the map: raster::blockLinearIndex lane by lane.
inline I32 texelStorageIndex(const LookupMap& map, I32 x, I32 y) {
    using raster::kBlockShift;
    using raster::kTileShift;
    const I32 last = simd::splat(int32_t(map.size - 1)), zero = simd::splat(int32_t(0));
    x = simd::min(simd::max(x, zero), last);
    y = simd::min(simd::max(y, zero), last);
    const I32 lowBits = simd::splat(int32_t(raster::kBlockSize - 1));
    const I32 blockBits = simd::splat(int32_t(raster::kBlocksPerTileSide - 1));
    const I32 tile = simd::shiftRight<kTileShift>(y) * simd::splat(int32_t(map.tilesX)) + simd::shiftRight<kTileShift>(x);
    const I32 block = (simd::shiftRight<kBlockShift>(y) & blockBits) * simd::splat(int32_t(raster::kBlocksPerTileSide)) +
                      (simd::shiftRight<kBlockShift>(x) & blockBits);
    return tile * simd::splat(int32_t(raster::kPixelsPerTile)) + simd::shiftLeft<2 * kBlockShift>(block) +
           simd::shiftLeft<kBlockShift>(y & lowBits) + (x & lowBits);
}

// A receiver as the map sees it (MapReceiver in float): where it falls, its biased depth,
// and for receiver planes the plane's depth slope per texel and the compare's tolerance.
struct Receiver {
    F32 texelX, texelY, depth;
    F32 slopeX, slopeY, tolerance;
    F32 distance;   // clip w (texelFromWorld's fourth row)
};

// The world-space width of one texel at P: the distance to the point one texel over in x
// at the same depth (texelWorldSize in shadow_bias.h).
inline F32 texelWorldSize(const LookupMap& map, const Vec3& P) {
    const Vec3 t = project(map.texelFromWorld, P);
    const Vec3 q = project(map.worldFromTexel, {t.x + simd::splat(1.0f), t.y, t.z});
    const Vec3 d{q.x - P.x, q.y - P.y, q.z - P.z};
    return simd::sqrt(dot(d, d));
}

// The receiver plane (N, p) in texel space solved for depth, z = z0 + s . (t - t0): planes
// transform by the inverse transpose, pi_texel = worldFromTexel^T pi_world (Isidoro 2006;
// RTR 7.5, Figure 7.24). A plane that contains the light rays has no depth function.
inline void receiverPlaneSlope(const LookupMap& map, const Vec3& p, const Vec3& N, Receiver& r) {
    const F32 w = simd::splat(0.0f) - dot(N, p);
    const float* m = map.worldFromTexel;
    auto planeComponent = [&](int c) {
        return simd::splat(m[4 * c]) * N.x + simd::splat(m[4 * c + 1]) * N.y + simd::splat(m[4 * c + 2]) * N.z +
               simd::splat(m[4 * c + 3]) * w;
    };
    const F32 a = planeComponent(0), b = planeComponent(1), c = planeComponent(2);
    const F32 sx = (simd::splat(0.0f) - a) / c, sy = (simd::splat(0.0f) - b) / c;
    const Mask finite = isFinite(sx) & isFinite(sy);
    r.slopeX = simd::select(finite, sx, simd::splat(0.0f));
    r.slopeY = simd::select(finite, sy, simd::splat(0.0f));
    r.tolerance = (abs(r.slopeX) + abs(r.slopeY)) * simd::splat(kRasterPositionErrorTexels) +
                  simd::splat(kDepthTolerance);
}

// The bias of shadow_bias.h in float: constant and normal-offset move the receiver towards
// the light, normal-offset also along N by texels times the sine of the light angle
// (Holbert; RTR 7.4); slope-scaled was applied when the map was drawn.
template <bool kPlane>
Receiver projectReceiver(const LookupConstants& c, const LookupMap& map, const Vec3& P, const Vec3& N) {
    Vec3 p = P;
    if (c.bias == kLookupConstant || c.bias == kLookupNormalOffset) {
        const Vec3 light{simd::splat(c.light[0]), simd::splat(c.light[1]), simd::splat(c.light[2])};
        Vec3 u = light;
        if (!c.directional) {
            const Vec3 d{light.x - P.x, light.y - P.y, light.z - P.z};
            const F32 length = simd::sqrt(dot(d, d));
            u = {d.x / length, d.y / length, d.z / length};
        }
        const F32 move = simd::splat(c.constantMetres);
        p = {p.x + u.x * move, p.y + u.y * move, p.z + u.z * move};
        if (c.bias == kLookupNormalOffset) {
            const F32 cosine = dot(N, u);
            const F32 sine = simd::sqrt(simd::max(simd::splat(0.0f), simd::splat(1.0f) - cosine * cosine));
            const F32 along = simd::splat(c.normalOffsetTexels) * texelWorldSize(map, P) * sine;
            p = {p.x + N.x * along, p.y + N.y * along, p.z + N.z * along};
        }
    }
    F32 w;
    const Vec3 t = project(map.texelFromWorld, p, w);
    Receiver r{t.x, t.y, t.z, simd::splat(0.0f), simd::splat(0.0f), simd::splat(0.0f), w};
    if constexpr (kPlane) receiverPlaneSlope(map, p, N, r);
    return r;
}

inline F32 oneWhere(Mask m) { return simd::select(m, simd::splat(1.0f), simd::splat(0.0f)); }

// The depth texel (x, y) of the map stores, clamped to its border.
inline F32 storedDepth(const LookupMap& map, I32 x, I32 y) { return simd::gather(map.depth, texelStorageIndex(map, x, y)); }

// Lit by texel (x, y), which stores `stored`: the receiver is not farther from the light
// than that, or the texel is empty (the cleared 1 holds no occluder). For a receiver plane
// the receiver's depth is the plane's at the texel centre, and the tolerance is added.
template <bool kPlane>
Mask litBy(const Receiver& r, I32 x, I32 y, F32 stored) {
    const Mask empty = simd::cmpLe(simd::splat(1.0f), stored);
    if constexpr (!kPlane) return empty | simd::cmpLe(r.depth, stored);
    const F32 half = simd::splat(0.5f);
    const F32 depthAt = r.depth + r.slopeX * ((simd::toFloat(x) + half) - r.texelX) +
                        r.slopeY * ((simd::toFloat(y) + half) - r.texelY);
    return empty | simd::cmpLe(depthAt, stored + r.tolerance);
}

template <bool kPlane>
Mask litBy(const LookupMap& map, const Receiver& r, I32 x, I32 y) {
    return litBy<kPlane>(r, x, y, storedDepth(map, x, y));
}

// The Poisson disk (taps on the unit disk) rotated by (cosine, sine) per pixel and scaled
// per axis: the fraction of its taps that are lit.
template <bool kPlane>
F32 poissonLitFraction(const LookupMap& map, const Receiver& r, F32 cosine, F32 sine, F32 radiusX, F32 radiusY,
                       const float* diskX, const float* diskY, int taps) {
    F32 sum = simd::splat(0.0f);
    for (int k = 0; k < taps; ++k) {
        const F32 dx = simd::splat(diskX[k]), dy = simd::splat(diskY[k]);
        const F32 x = r.texelX + radiusX * (cosine * dx - sine * dy);
        const F32 y = r.texelY + radiusY * (sine * dx + cosine * dy);
        sum = sum + oneWhere(litBy<kPlane>(map, r, texelIndexOf(x), texelIndexOf(y)));
    }
    return sum / simd::splat(float(taps));
}

// The filters of pcf.h, each the fraction of its weight that is lit.
struct Nearest {
    template <bool kPlane>
    static F32 lit(const LookupConstants&, const LookupMap& map, const Receiver& r, const LookupRow&, int) {
        return oneWhere(litBy<kPlane>(map, r, texelIndexOf(r.texelX), texelIndexOf(r.texelY)));
    }
};

// The four texel centres around the receiver, weighted bilinearly (RTR 7.5).
struct Bilinear {
    template <bool kPlane>
    static F32 lit(const LookupConstants&, const LookupMap& map, const Receiver& r, const LookupRow&, int) {
        const F32 half = simd::splat(0.5f), one = simd::splat(1.0f);
        const F32 baseX = r.texelX - half, baseY = r.texelY - half;
        const I32 x0 = texelIndexOf(baseX), y0 = texelIndexOf(baseY), step = simd::splat(int32_t(1));
        const F32 fx = baseX - simd::toFloat(x0), fy = baseY - simd::toFloat(y0);
        const F32 top = (one - fx) * oneWhere(litBy<kPlane>(map, r, x0, y0)) + fx * oneWhere(litBy<kPlane>(map, r, x0 + step, y0));
        const F32 bottom = (one - fx) * oneWhere(litBy<kPlane>(map, r, x0, y0 + step)) +
                           fx * oneWhere(litBy<kPlane>(map, r, x0 + step, y0 + step));
        return (one - fy) * top + fy * bottom;
    }
};

// N x N taps one texel apart centred on the receiver, equal weights (RTR Figure 7.23).
struct Grid {
    template <bool kPlane>
    static F32 lit(const LookupConstants& c, const LookupMap& map, const Receiver& r, const LookupRow&, int) {
        const int n = c.gridSize;
        const float first = -0.5f * float(n - 1);
        F32 sum = simd::splat(0.0f);
        for (int b = 0; b < n; ++b) {
            const I32 y = texelIndexOf(r.texelY + simd::splat(first + float(b)));
            for (int a = 0; a < n; ++a) sum = sum + oneWhere(litBy<kPlane>(map, r, texelIndexOf(r.texelX + simd::splat(first + float(a))), y));
        }
        return sum / simd::splat(float(n * n));
    }
};

// The Poisson disk rotated per pixel (the row's cos and sin) and scaled per axis.
struct Poisson {
    template <bool kPlane>
    static F32 lit(const LookupConstants& c, const LookupMap& map, const Receiver& r, const LookupRow& row, int i) {
        return poissonLitFraction<kPlane>(map, r, simd::load(row.rotationCos + i), simd::load(row.rotationSin + i),
                                          simd::splat(c.radiusTexels), simd::splat(c.radiusTexels), c.diskX,
                                          c.diskY, c.diskTaps);
    }
};

// The 2 x 2 nodes of the map's min/max hierarchy that hold the texels [x0, x1] x [y0, y1],
// lane by lane as MinMaxHierarchy::over: the first level whose nodes are as wide as the
// rectangle. A node's index on an axis is c / 2^l, exact in float for every texel index.
struct HierarchyNodes {
    I32 index[4];            // into the level arrays (a node may repeat)
    F32 centreX[4], centreY[4];
    F32 halfWidth;           // from a node's centre to its outermost texel centre, (2^l - 1) / 2
};
inline HierarchyNodes nodesOver(const LookupHierarchy& h, I32 x0, I32 y0, I32 x1, I32 y1) {
    const I32 span = simd::max(x1 - x0, y1 - y0);
    F32 width = simd::splat(float(1 << h.firstLevel));
    I32 offset = simd::splat(int32_t(h.offset[0])), size = simd::splat(int32_t(h.size[0]));
    for (int l = h.firstLevel; l < h.levels; ++l) {   // level l + 1 where span >= 2^l
        const Mask wider = simd::cmpGt(span, simd::splat(int32_t((1 << l) - 1)));
        const int k = l + 1 - h.firstLevel;
        width = simd::select(wider, simd::splat(float(2 << l)), width);
        offset = simd::select(wider, simd::splat(int32_t(h.offset[k])), offset);
        size = simd::select(wider, simd::splat(int32_t(h.size[k])), size);
    }
    const F32 scale = simd::splat(1.0f) / width, half = simd::splat(0.5f);
    const auto node = [&](I32 c) { return simd::toFloat(simd::truncateToInt(simd::toFloat(c) * scale)); };
    const F32 nx[2] = {node(x0), node(x1)}, ny[2] = {node(y0), node(y1)};
    HierarchyNodes out;
    for (int k = 0; k < 4; ++k) {
        const F32 x = nx[k % 2], y = ny[k / 2];
        out.index[k] = offset + simd::truncateToInt(y) * size + simd::truncateToInt(x);
        out.centreX[k] = (x + half) * width, out.centreY[k] = (y + half) * width;
    }
    out.halfWidth = (width - simd::splat(1.0f)) * half;
    return out;
}

// What the hierarchy proves about every tap of a disk of radius (radiusX, radiusY) texels
// around the receiver: that litBy answers lit at each, or (kShadowed) shadowed at each (RTR 7.6,
// "rapidly determine fully lit and fully shadowed conditions"), from each node's plane and
// residuals (min_max_hierarchy.h), so that a receiver lying in the map is proved too:
//  - the taps land in the texels [floor(t - e), floor(t + e)], e = 1.0001 radius, since a
//    rotated unit-disk tap is at most 1 + a few ulps from the centre and each rounding is
//    monotone; a rectangle reaching past the map's border (clamped taps) proves nothing;
//  - over a node, stored - receiver = (node plane - receiver plane) + residual, and the
//    planes' difference g is affine, within g(centre) -+ (|dSlopeX| + |dSlopeY|) halfWidth;
//  - lit needs stored + tolerance >= the receiver's depth at every tap, shadowed the
//    reverse (and no empty texel: residualHigh is then +inf). The float evaluation of both
//    sides (litBy's and this one) errs by a few u times the magnitudes of their terms
//    (u = 2^-24); a margin of 8 u times their sum covers it, so a proof is never wrong.
struct TapProof {
    Mask lit, shadowed;
};
// The proof over the texels [x0, x1] x [y0, y1] (a rectangle past the map's border: none).
template <bool kPlane, bool kShadowed>
TapProof proveTexels(const LookupMap& map, const Receiver& r, I32 x0, I32 y0, I32 x1, I32 y1) {
    const LookupHierarchy& h = *map.hierarchy;
    const F32 zero = simd::splat(0.0f), one = simd::splat(1.0f);
    const I32 first = simd::splat(int32_t(0)), last = simd::splat(int32_t(map.size - 1));
    const auto clamp = [&](I32 c) { return simd::min(simd::max(c, first), last); };
    const Mask inside = simd::cmpEq(clamp(x0), x0) & simd::cmpEq(clamp(y0), y0) & simd::cmpEq(clamp(x1), x1) &
                        simd::cmpEq(clamp(y1), y1);
    const HierarchyNodes nodes = nodesOver(h, clamp(x0), clamp(y0), clamp(x1), clamp(y1));
    const F32 slopeX = kPlane ? r.slopeX : zero, slopeY = kPlane ? r.slopeY : zero;
    const F32 errorScale = simd::splat(0x1p-21f);   // 8 u
    TapProof proof{inside, inside};
    for (int k = 0; k < 4; ++k) {
        const F32 depth = simd::gather(h.planeDepth, nodes.index[k]);
        const F32 sx = simd::gather(h.slopeX, nodes.index[k]), sy = simd::gather(h.slopeY, nodes.index[k]);
        const F32 low = simd::gather(h.residualLow, nodes.index[k]);
        const F32 dx = nodes.centreX[k] - r.texelX, dy = nodes.centreY[k] - r.texelY;
        const F32 receiver = r.depth + slopeX * dx + slopeY * dy;
        const F32 g = depth - receiver;
        const F32 spread = (abs(sx - slopeX) + abs(sy - slopeY)) * nodes.halfWidth;
        const F32 terms = one + abs(r.depth) + abs(depth) + (abs(slopeX) + abs(sx)) * (abs(dx) + nodes.halfWidth) +
                          (abs(slopeY) + abs(sy)) * (abs(dy) + nodes.halfWidth);
        const F32 error = errorScale * terms;
        proof.lit = proof.lit & simd::cmpLe(error, g - spread + low + r.tolerance);
        if constexpr (kShadowed) {
            const F32 high = simd::gather(h.residualHigh, nodes.index[k]);
            proof.shadowed = proof.shadowed & simd::cmpLt(g + spread + high + r.tolerance, zero - error);
        }
    }
    if constexpr (!kShadowed) proof.shadowed = simd::noLanes();
    return proof;
}
template <bool kPlane, bool kShadowed>
TapProof proveTaps(const LookupMap& map, const Receiver& r, F32 radiusX, F32 radiusY) {
    const F32 margin = simd::splat(1.0001f);
    return proveTexels<kPlane, kShadowed>(map, r, texelIndexOf(r.texelX - radiusX * margin),
                                          texelIndexOf(r.texelY - radiusY * margin),
                                          texelIndexOf(r.texelX + radiusX * margin),
                                          texelIndexOf(r.texelY + radiusY * margin));
}

// Eq. 7.6 in texels on one map axis: w = w_light (d_r - d_o) / (d_r d_o) (RTR 7.6).
inline F32 penumbraTexels(const LookupConstants& c, F32 dr, F32 occluder, int axis) {
    return simd::splat(c.lightTexels[axis]) * ((dr - occluder) / (dr * occluder));
}

// The blocker search's radius on one axis: the light's cone from the receiver cut at the
// near plane (eq. 7.6 with d_o = near), times the fraction searched.
inline F32 searchRadius(const LookupConstants& c, F32 dr, int axis) {
    return simd::splat(0.5f * c.searchRegion) * penumbraTexels(c, dr, simd::splat(c.zNear), axis);
}

// PCSS's steps 1 and 2 (Fernando 2005; blocker_search.h) for the lanes `searched`: the
// rotated search disk's taps nearer the light than the receiver's plane are blockers, and
// d_o is their mean distance from the light. The offset and the plane can put the mean at
// or behind the receiver by a rounding: clamped to near .. d_r (width 0 at contact).
struct BlockerEstimate {
    Mask found;
    F32 occluder;   // d_o, m (meaningless where none was found)
};
template <bool kPlane>
BlockerEstimate searchDisk(const LookupConstants& c, const LookupMap& map, const Receiver& r, F32 cosine, F32 sine,
                           Mask searched, F32 searchX, F32 searchY) {
    // A stored window depth's distance, f n / (f - z (f - n)) (SoftShadowMap::distanceOf).
    const F32 farNear = simd::splat(c.zFar * c.zNear), far = simd::splat(c.zFar), range = simd::splat(c.zFar - c.zNear);
    const F32 zero = simd::splat(0.0f);
    F32 blockers = zero, distanceSum = zero;   // in tap order: the same sums at every width
    for (int k = 0; k < c.searchTaps; ++k) {
        const F32 dx = simd::splat(c.searchX[k]), dy = simd::splat(c.searchY[k]);
        const I32 x = texelIndexOf(r.texelX + searchX * (cosine * dx - sine * dy));
        const I32 y = texelIndexOf(r.texelY + searchY * (sine * dx + cosine * dy));
        const F32 stored = storedDepth(map, x, y);
        const Mask blocker = searched & !litBy<kPlane>(r, x, y, stored);
        blockers = blockers + oneWhere(blocker);
        distanceSum = distanceSum + simd::select(blocker, farNear / (far - stored * range), zero);
    }
    return {simd::cmpLt(zero, blockers), simd::min(simd::max(distanceSum / blockers, simd::splat(c.zNear)), r.distance)};
}

// Percentage-closer soft shadows (Fernando 2005, steps 1 to 3; RTR 7.6) on a perspective
// map from the light's centre, the receiver on its own plane (blocker_search.h says why):
//   1. blocker search: the rotated search disk over the light's cone from the receiver cut
//      at the near plane; the taps nearer the light are blockers, their mean distance d_o.
//   2. eq. 7.6 in texels: w = w_light (d_r - d_o) / (d_r d_o), per map axis.
//   3. the rotated filter disk of radius w / 2: the lit fraction. Never below half a texel,
//      where the taps all fall in the receiver's own texel: the map's resolution, not the
//      light, limits the penumbra there (contact shadows are hard).
// No blocker (or a receiver nearer than the near plane): fully lit. With the map's min/max
// hierarchy, a vector skips the search where every lane's search disk is proved lit (V = 1),
// and the filter where every lane's filter disk is proved lit or shadowed (V = 1 or 0, the
// values the taps give: n / n and 0 / n); the answers are the same bits either way.
struct Pcss {
    template <bool kPlane>
    static F32 lit(const LookupConstants& c, const LookupMap& map, const Receiver& r, const LookupRow& row, int i) {
        const F32 cosine = simd::load(row.rotationCos + i), sine = simd::load(row.rotationSin + i);
        const F32 zero = simd::splat(0.0f), half = simd::splat(0.5f), dr = r.distance;
        const F32 searchX = searchRadius(c, dr, 0), searchY = searchRadius(c, dr, 1);
        const Mask searched = simd::cmpLt(simd::splat(c.zNear), dr);
        // PCSS has one map: the lanes it serves are the served ones.
        const Mask lanes = simd::cmpGt(simd::loadU8(row.served + i), simd::splat(int32_t(0)));
        const bool proving = map.hierarchy != nullptr;
        const Mask searchKnown =
            proving ? !searched | proveTaps<kPlane, false>(map, r, searchX, searchY).lit : !searched;
        if (proving && !simd::any(lanes & !searchKnown)) {
            simd::store(row.blockerDistance + i, zero), simd::store(row.penumbraWidth + i, zero);
            simd::store(row.knownTaps + i, simd::splat(float(c.searchTaps)));
            return simd::splat(1.0f);
        }
        const BlockerEstimate blockers = searchDisk<kPlane>(c, map, r, cosine, sine, searched, searchX, searchY);
        const Mask shadowed = blockers.found;
        const F32 occluder = blockers.occluder;
        const F32 widthX = penumbraTexels(c, dr, occluder, 0), widthY = penumbraTexels(c, dr, occluder, 1);
        const F32 radiusX = simd::max(half * widthX, half), radiusY = simd::max(half * widthY, half);
        // The filter runs only where a lane found blockers (the others are lit), and only
        // for lanes whose taps the hierarchy did not prove.
        const bool filtering = simd::any(lanes & shadowed);
        TapProof filter{simd::noLanes(), simd::noLanes()};
        if (proving && filtering) filter = proveTaps<kPlane, true>(map, r, radiusX, radiusY);
        const Mask filterKnown = filter.lit | filter.shadowed;
        const bool tapsNeeded = filtering && !(proving && !simd::any(lanes & shadowed & !filterKnown));
        const F32 visibility = tapsNeeded ? poissonLitFraction<kPlane>(map, r, cosine, sine, radiusX, radiusY,
                                                                       c.diskX, c.diskY, c.diskTaps)
                                          : simd::select(filter.shadowed, zero, simd::splat(1.0f));
        simd::store(row.blockerDistance + i, simd::select(shadowed, occluder, zero));
        simd::store(row.penumbraWidth + i, simd::select(shadowed, half * (widthX + widthY), zero));
        if (proving) {
            const F32 filterTaps = simd::select(shadowed & filterKnown, simd::splat(float(c.diskTaps)), zero);
            simd::store(row.knownTaps + i, simd::select(searchKnown, simd::splat(float(c.searchTaps)), filterTaps));
        }
        return simd::select(shadowed, visibility, simd::splat(1.0f));
    }
};

// PCSS's blocker search alone (steps 1 and 2), for the filtered maps' width=pcss
// (shadows/filtered/filtered_shadow_map.cpp), which filter their own moments over the eq.
// 7.6 width: d_o into blockerDistance (0 without blockers), and V = 1 where no blocker was
// found (lit), 0 where the caller's filter decides.
struct BlockerSearch {
    template <bool kPlane>
    static F32 lit(const LookupConstants& c, const LookupMap& map, const Receiver& r, const LookupRow& row, int i) {
        const F32 dr = r.distance, zero = simd::splat(0.0f);
        const BlockerEstimate blockers =
            searchDisk<kPlane>(c, map, r, simd::load(row.rotationCos + i), simd::load(row.rotationSin + i),
                               simd::cmpLt(simd::splat(c.zNear), dr), searchRadius(c, dr, 0), searchRadius(c, dr, 1));
        simd::store(row.blockerDistance + i, simd::select(blockers.found, blockers.occluder, zero));
        return simd::select(blockers.found, zero, simd::splat(1.0f));
    }
};

// Contact-hardening soft shadows (shadows/filtered/contact_hardening.cpp: PCSS read on the
// levels of the min/max hierarchy; RTR 7.6, Sikachev et al.), the receiver on its plane:
//   1. blocker search over the light's cone cut at the near plane, read at the first level
//      where the cone spans at most searchNodes nodes a side (readingLevelFor, lane by
//      lane); a node whose least depth, plus the tolerance, is nearer than the receiver's
//      plane anywhere over the node holds a blocker at that depth; d_o is their mean. Where
//      the hierarchy proves the whole cone lit, the search is skipped (no blocker);
//   2. eq. 7.6 gives the filter's width, as Pcss;
//   3. an N x N grid (N = filterNodes) over that width, each tap the texel it falls in. The
//      level-by-level reading of the filter the double pass did answered every tap as its
//      texel does (a node proved lit or shadowed holds only texels that answer so), so the
//      taps read texels, and a vector whose every lane's footprint is proved lit or
//      shadowed skips them, as Pcss does.
struct Chs {
    // The level a region spanning `span` texels is read at with at most `nodes` nodes a
    // side (readingLevelFor): 0 where span < nodes, else the first l >= firstLevel with
    // (span >> l) + 2 <= nodes, capped at the top; (span >> l) + 2 > nodes is
    // span >= (nodes - 1) 2^l, which falls as l grows.
    static I32 readingLevel(const LookupHierarchy& h, I32 span, int nodes) {
        I32 level = simd::select(simd::cmpGt(span, simd::splat(int32_t(nodes - 1))),
                                 simd::splat(int32_t(h.firstLevel)), simd::splat(int32_t(0)));
        for (int l = h.firstLevel; l < h.levels; ++l) {
            const Mask deeper = simd::cmpGt(span, simd::splat(int32_t(((nodes - 1) << l) - 1)));
            level = simd::select(deeper & simd::cmpGt(level, simd::splat(int32_t(0))), simd::splat(int32_t(l + 1)), level);
        }
        return level;
    }

    // Steps 1 and 2 for lanes `searched`: the blockers' count, and the sum of their
    // distances from the light in node order (the same sums at every width).
    static void searchBlockers(const LookupConstants& c, const LookupMap& map, const Receiver& r, Mask searched,
                               I32 x0, I32 y0, I32 x1, I32 y1, I32 level, F32& blockers, F32& distanceSum) {
        const LookupHierarchy& h = *map.hierarchy;
        const I32 zeroI = simd::splat(int32_t(0));
        const Mask onNodes = simd::cmpGt(level, zeroI);
        // The level's node width, first node and nodes per side, lane by lane (nodesOver).
        F32 width = simd::splat(1.0f);
        I32 offset = zeroI, size = zeroI;
        for (int l = h.firstLevel; l <= h.levels; ++l) {
            const Mask at = simd::cmpEq(level, simd::splat(int32_t(l)));
            width = simd::select(at, simd::splat(float(1 << l)), width);
            offset = simd::select(at, simd::splat(int32_t(h.offset[l - h.firstLevel])), offset);
            size = simd::select(at, simd::splat(int32_t(h.size[l - h.firstLevel])), size);
        }
        // A node's index on an axis is c / 2^l, exact in float for every texel index.
        const F32 scale = simd::splat(1.0f) / width, half = simd::splat(0.5f), zero = simd::splat(0.0f);
        const auto node = [&](I32 t) { return simd::truncateToInt(simd::toFloat(t) * scale); };
        const I32 nx0 = node(x0), ny0 = node(y0), countX = node(x1) - nx0, countY = node(y1) - ny0;
        const F32 halfWidth = (width - simd::splat(1.0f)) * half;
        const F32 tilt = (abs(r.slopeX) + abs(r.slopeY)) * halfWidth;
        const F32 farNear = simd::splat(c.zFar * c.zNear), far = simd::splat(c.zFar), range = simd::splat(c.zFar - c.zNear);
        for (int b = 0; b < c.searchNodes; ++b) {
            const Mask row = searched & !simd::cmpGt(simd::splat(int32_t(b)), countY);
            if (!simd::any(row)) break;
            const I32 y = ny0 + simd::splat(int32_t(b));
            for (int a = 0; a < c.searchNodes; ++a) {
                const Mask valid = row & !simd::cmpGt(simd::splat(int32_t(a)), countX);
                if (!simd::any(valid)) break;
                const I32 x = nx0 + simd::splat(int32_t(a));
                // Each lane reads its node's least depth, or at level 0 the texel; the
                // others read index 0, which every array has.
                const I32 nodeIndex = simd::select(valid & onNodes, offset + y * size + x, zeroI);
                const I32 texelIndex = simd::select(valid & !onNodes, texelStorageIndex(map, x, y), zeroI);
                F32 least = simd::splat(1.0f);
                if (simd::any(valid & onNodes)) least = simd::gather(h.least, nodeIndex);
                if (simd::any(valid & !onNodes)) least = simd::select(onNodes, least, simd::gather(map.depth, texelIndex));
                // The receiver's plane at its nearest over the node (planeLeastOver).
                const F32 dx = (simd::toFloat(x) + half) * width - r.texelX;
                const F32 dy = (simd::toFloat(y) + half) * width - r.texelY;
                const F32 plane = r.depth + r.slopeX * dx + r.slopeY * dy - tilt;
                const Mask blocker = valid & simd::cmpLt(least, simd::splat(1.0f)) & simd::cmpLt(least + r.tolerance, plane);
                blockers = blockers + oneWhere(blocker);
                distanceSum = distanceSum + simd::select(blocker, farNear / (far - least * range), zero);
            }
        }
    }

    // Step 3: the lit fraction of the N x N grid of taps over radius (texels) per axis.
    template <bool kPlane>
    static F32 gridLitFraction(const LookupConstants& c, const LookupMap& map, const Receiver& r, F32 radiusX,
                               F32 radiusY) {
        const int n = c.filterNodes;
        const I32 first = simd::splat(int32_t(0)), last = simd::splat(int32_t(map.size - 1));
        const auto clamp = [&](I32 t) { return simd::min(simd::max(t, first), last); };
        F32 sum = simd::splat(0.0f);
        for (int b = 0; b < n; ++b) {
            const F32 v = simd::splat(float((2.0 * b + 1.0) / n - 1.0));
            const I32 y = clamp(texelIndexOf(r.texelY + radiusY * v));
            for (int a = 0; a < n; ++a) {
                const F32 u = simd::splat(float((2.0 * a + 1.0) / n - 1.0));
                const I32 x = clamp(texelIndexOf(r.texelX + radiusX * u));
                sum = sum + oneWhere(litBy<kPlane>(map, r, x, y));
            }
        }
        return sum / simd::splat(float(n * n));
    }

    template <bool kPlane>
    static F32 lit(const LookupConstants& c, const LookupMap& map, const Receiver& r, const LookupRow& row, int i) {
        const F32 zero = simd::splat(0.0f), half = simd::splat(0.5f), zNear = simd::splat(c.zNear), dr = r.distance;
        const Mask lanes = simd::cmpGt(simd::loadU8(row.served + i), simd::splat(int32_t(0)));
        // The cone's texels, clamped to the map (coneTexels).
        const I32 first = simd::splat(int32_t(0)), last = simd::splat(int32_t(map.size - 1));
        const auto clamp = [&](I32 t) { return simd::min(simd::max(t, first), last); };
        const F32 coneX = half * penumbraTexels(c, dr, zNear, 0), coneY = half * penumbraTexels(c, dr, zNear, 1);
        const I32 x0 = clamp(texelIndexOf(r.texelX - coneX)), x1 = clamp(texelIndexOf(r.texelX + coneX));
        const I32 y0 = clamp(texelIndexOf(r.texelY - coneY)), y1 = clamp(texelIndexOf(r.texelY + coneY));
        const Mask proved = proveTexels<kPlane, false>(map, r, x0, y0, x1, y1).lit;
        const Mask searched = lanes & simd::cmpLt(zNear, dr) & !proved;
        F32 blockers = zero, distanceSum = zero;
        const I32 level = readingLevel(*map.hierarchy, simd::max(x1 - x0, y1 - y0), c.searchNodes);
        if (simd::any(searched)) searchBlockers(c, map, r, searched, x0, y0, x1, y1, level, blockers, distanceSum);
        const Mask shadowed = simd::cmpLt(zero, blockers);
        const F32 occluder = simd::min(simd::max(distanceSum / blockers, zNear), dr);
        const F32 widthX = penumbraTexels(c, dr, occluder, 0), widthY = penumbraTexels(c, dr, occluder, 1);
        const F32 radiusX = simd::max(half * widthX, half), radiusY = simd::max(half * widthY, half);
        F32 visibility = simd::splat(1.0f);
        if (simd::any(lanes & shadowed)) {
            const TapProof known = proveTaps<kPlane, true>(map, r, radiusX, radiusY);
            visibility = simd::any(lanes & shadowed & !(known.lit | known.shadowed))
                             ? gridLitFraction<kPlane>(c, map, r, radiusX, radiusY)
                             : simd::select(known.shadowed, zero, simd::splat(1.0f));
        }
        simd::store(row.blockerDistance + i, simd::select(shadowed, occluder, zero));
        simd::store(row.penumbraWidth + i, simd::select(shadowed, half * (widthX + widthY), zero));
        simd::store(row.searchLevel + i, simd::select(shadowed, simd::toFloat(level), zero));
        return simd::select(shadowed, visibility, simd::splat(1.0f));
    }
};

// Lanes i .. i + kWidth - 1 of an x, y, z array.
inline Vec3 loadVec3(const float* xyz, int i) {
    Vec3 v;
    simd::loadTriples(xyz + 3 * i, v.x, v.y, v.z);
    return v;
}

// The lanes of a vector that map m serves, m = 0 .. mapCount - 1, each visited once.
// Neighbouring pixels share a map almost always; a vector across two maps' boundary (cube
// faces, cascades) is visited once for each.
template <class Visit>
void forEachServingMap(const LookupConstants& c, const uint8_t* served, Visit&& visit) {
    const I32 index = simd::loadU8(served);
    if (!simd::any(simd::cmpGt(index, simd::splat(int32_t(0))))) return;
    for (int m = 0; m < c.mapCount; ++m) {
        const Mask lanes = simd::cmpEq(index, simd::splat(int32_t(m + 1)));
        if (simd::any(lanes)) visit(c.maps[m], lanes);
    }
}

// Stage 1: whether the light can reach each receiver, dot(N, A - s P) > 0 as lightReaches
// (shading/lights.h) decides it in double, here in float with a certified sign. With
// t = fl(A - s P), the float dot differs from the exact one by at most gamma_4 sum |N_i t_i|
// (about 4u, u = 2^-24; Higham, "Accuracy and Stability of Numerical Algorithms", 3.1),
// so beyond 8u sum |N_i t_i| its sign is the exact sign, which double, 2^29 times finer,
// also gets. Nearer zero the lane is marked undecided and the caller asks lightReaches.
// A spot light's lit lanes are all undecided: its cone is the caller's.
void reachRun(const LookupConstants& c, const LookupRow& row) {
    constexpr float kCertain = 8.0f / 16777216.0f;   // 8u
    constexpr float kTiny = 0x1p-100f;               // below this the bound may have underflowed
    const Vec3 anchor{simd::splat(c.reachAnchor[0]), simd::splat(c.reachAnchor[1]), simd::splat(c.reachAnchor[2])};
    for (int i = 0; i < row.count; i += kWidth) {
        const I32 served = simd::loadU8(row.served + i), none = simd::splat(int32_t(0));
        const Mask candidate = simd::cmpGt(served, none);
        if (!simd::any(candidate)) continue;
        const Vec3 P = loadVec3(row.position, i), N = loadVec3(row.normal, i);
        const Vec3 t = c.directional ? anchor : Vec3{anchor.x - P.x, anchor.y - P.y, anchor.z - P.z};
        const F32 d = dot(N, t);
        const F32 size = abs(N.x) * abs(t.x) + abs(N.y) * abs(t.y) + abs(N.z) * abs(t.z);
        const F32 bound = simd::splat(kCertain) * size;
        const Mask measurable = !simd::cmpLt(size, simd::splat(kTiny));
        const Mask lit = simd::cmpLt(bound, d) & measurable & (c.spot ? simd::noLanes() : simd::allLanes());
        const Mask dark = simd::cmpLt(d, simd::splat(0.0f) - bound) & measurable;
        const I32 undecided = served | simd::splat(int32_t(kReachUndecided));
        const I32 out = simd::select(lit, served, simd::select(dark, none, undecided));
        simd::storeU8(row.served + i, simd::select(candidate, out, none));
    }
}

// Stage 2: every served receiver of the run projected into its map, into row.receivers.
template <bool kPlane>
void projectRun(const LookupConstants& c, const LookupRow& row) {
    const ReceiverArrays& out = row.receivers;
    for (int i = 0; i < row.count; i += kWidth) {
        Receiver r{};
        forEachServingMap(c, row.served + i, [&](const LookupMap& map, Mask lanes) {
            const Receiver q = projectReceiver<kPlane>(c, map, loadVec3(row.position, i), loadVec3(row.normal, i));
            r = {simd::select(lanes, q.texelX, r.texelX),     simd::select(lanes, q.texelY, r.texelY),
                 simd::select(lanes, q.depth, r.depth),       simd::select(lanes, q.slopeX, r.slopeX),
                 simd::select(lanes, q.slopeY, r.slopeY),     simd::select(lanes, q.tolerance, r.tolerance),
                 simd::select(lanes, q.distance, r.distance)};
        });
        simd::store(out.texelX + i, r.texelX), simd::store(out.texelY + i, r.texelY), simd::store(out.depth + i, r.depth);
        if (out.distance) simd::store(out.distance + i, r.distance);
        if constexpr (kPlane) {
            simd::store(out.slopeX + i, r.slopeX), simd::store(out.slopeY + i, r.slopeY);
            simd::store(out.tolerance + i, r.tolerance);
        }
    }
}

// Stage 3: the filter's taps for every served receiver, V = 0 elsewhere. Its vectors do not
// depend on each other, so the map reads of several are in flight at once.
template <class Filter, bool kPlane>
void filterRun(const LookupConstants& c, const LookupRow& row) {
    const ReceiverArrays& in = row.receivers;
    for (int i = 0; i < row.count; i += kWidth) {
        Receiver r{};
        r.texelX = simd::load(in.texelX + i), r.texelY = simd::load(in.texelY + i), r.depth = simd::load(in.depth + i);
        if constexpr (kPlane) {
            r.slopeX = simd::load(in.slopeX + i), r.slopeY = simd::load(in.slopeY + i);
            r.tolerance = simd::load(in.tolerance + i);
        }
        if (in.distance) r.distance = simd::load(in.distance + i);
        F32 visibility = simd::splat(0.0f);
        forEachServingMap(c, row.served + i, [&](const LookupMap& map, Mask lanes) {
            visibility = simd::select(lanes, Filter::template lit<kPlane>(c, map, r, row, i), visibility);
        });
        simd::store(row.visibility + i, visibility);
    }
}

template <class Filter>
constexpr void addFilter(LookupKernels& table, int filter) {
    table.filter[filter][0] = filterRun<Filter, false>;
    table.filter[filter][1] = filterRun<Filter, true>;
}

inline const LookupKernels& kernels() {
    static const LookupKernels table = [] {
        LookupKernels t{};
        t.width = kWidth;
        t.reach = reachRun;
        t.project[0] = projectRun<false>;
        t.project[1] = projectRun<true>;
        addFilter<Nearest>(t, kLookupNearest);
        addFilter<Bilinear>(t, kLookupBilinear);
        addFilter<Grid>(t, kLookupGrid);
        addFilter<Poisson>(t, kLookupPoisson);
        addFilter<Pcss>(t, kLookupPcss);
        addFilter<Chs>(t, kLookupChs);
        addFilter<BlockerSearch>(t, kLookupBlockerSearch);
        return t;
    }();
    return table;
}
