// Shadow-map ray tracing (SMRT) through a virtual shadow map (docs/virtual-shadow-maps.md):
// soft shadows of a sun of angular radius theta from the pages alone, after the public
// description in Epic Games' "Virtual Shadow Maps" documentation ("Shadow Map Ray
// Tracing": a few rays per pixel towards the light's area, each sampled at a few steps
// against the map, occluders extrapolated from the depth history, a tolerance that grows
// along the ray). Our reading of it, from that description only:
//
// Each pixel sends `rays` rays from its receiver (the hard lookup's, with its bias) in
// directions of the sun's cone (stratified over the disk of directions, jittered per pixel
// by a PCG32 stream of its index), up to the top of the light's depth range. A ray climbs;
// sample k at height h_k = H ((k + xi) / steps)^2 (denser near the receiver, where contact
// shadows are; xi jittered per ray) reads the stored depth at its texel of the level
// rayLevel gives (page_marking.h: the pixel's own, coarser once the drift across the beam
// passes `reach` texels; then heldRayLevel's, coarser again where that level's window does
// not hold the pixel's rays' box, as marking marks it), through the page table. A receiver
// whose bias lifts it above the depth range's top sends no rays: the hard lookup's answer.
//
// The map is a height field seen from the light: a sample deeper than the stored depth is
// behind an occluder's front, which says nothing of whether the ray passes through the
// occluder or beneath it. The depth history decides: a ray behind an occluder that comes
// out in front of it again crossed the occluder, and is hit, where the stored depth at the
// sample it comes out at continues the surface it was behind (the depths of the samples
// before, extrapolated along the ray with their slope, within a tolerance of max-slope
// times the distance stepped across the beam and a texel of the level read: it grows along
// the ray). It escaped past the occluder's edge where the stored depth there is deeper
// than that: the inner penumbra. A ray still behind at its last sample is hit.
// V = the fraction of rays not hit. The hard lookup's receiver starts each ray, so that a
// pixel in the hard shadow's umbra is hit by every ray that never escapes.
//
// A read in a page without memory is counted and ends the ray unhit (lit, as the hard
// lookup reads a missing page). Deterministic: per pixel, a fixed PCG32 stream.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "shadows/virtual/page_lookup.h"

namespace shadowlab::vsm {

// The rays' jitter: pixel k draws from PCG32 stream k of this seed, the reference's.
inline constexpr uint64_t kSmrtSeed = 0x5eed5eed5eedull;

struct SmrtSettings {
    int rays = 0;             // per pixel; 0: the hard lookup's bytes
    int steps = 8;            // samples per ray
    double reachTexels = 4;   // drift across a level's texels before reading the next coarser
    // The depth history's slope bound, m along the beam per m across: a tolerance too tight
    // lets rays escape through an occluder's own curve (light leaks), too loose keeps them
    // from escaping past its edge (no inner penumbra). With crossings refined
    // (refineCrossing), 8 had the least RMS summed over soft/'s ten cases with 16 rays at
    // 160 x 100 (0.351; 4: 0.355, 16: 0.358, 32: 0.430; docs/virtual-shadow-maps.md).
    double maxSlope = 8.0;
    // Halvings of a crossing's step (refineCrossing): 4 find where the ray came out within
    // 1/16 of the step; 0 judges the samples as they fall.
    int refinements = 4;
};

// One ray's depth history (the header's comment): whether a sample that comes out in front
// of the stored surface again, after being behind it, crossed the occluder (hit) or passed
// its edge (escaped). Depths are in any unit that grows away from the light (the sun's
// window depth, a local light's metres from it); steps and texels across the beam in m.
class DepthHistory {
public:
    enum class Crossing { None, Hit, Escaped };

    // slopeLimit: depth units per m across; the receiver's texel's stored depth, whether it
    // is empty, and whether the receiver lies behind it.
    DepthHistory(double slopeLimit, double stored, bool empty, bool behind)
        : slopeLimit_(slopeLimit), previous_(stored), previousEmpty_(empty), behind_(behind) {}

    // The next sample: the depth stored at its texel (empty: none), whether it lies behind
    // it, how far across the beam it is from the sample before, and its texel's side.
    Crossing next(double stored, bool empty, bool nowBehind, double step, double texel);
    bool behind() const { return behind_; }

private:
    double slopeLimit_;
    double previous_, previousSlope_ = 0.0;   // the last stored depth, its slope per m across
    bool previousEmpty_, behind_;
};

// How one ray ended: hit, escaped past an occluder's edge on the way, or stopped by a read
// without memory.
struct RayEnd {
    bool hit = false, escaped = false, missing = false;
    // Records a crossing the history judged; whether the ray goes on (it ends at a hit).
    bool goesOn(DepthHistory::Crossing crossing) {
        hit = crossing == DepthHistory::Crossing::Hit;
        escaped |= crossing == DepthHistory::Crossing::Escaped;
        return !hit;
    }
};

// Where a ray comes out in front between a sample behind the stored surface (lo) and the
// next in front (hi), their step is halved `refinements` times, keeping the last point
// behind and the first in front: the pair the depth history then judges lies within
// 2^-refinements of the step of where the ray came out, where the stored depths on either
// side tell an occluder's surface (continuous) from its edge (a jump), however far apart the
// samples were. between(lo, hi): the read halfway; Read has `missing` (no page: the
// refinement stops and sets `missing`) and `behind`. Returns whether lo moved.
template <class Read, class Between>
bool refineCrossing(int refinements, Read& lo, Read& hi, const Between& between, bool& missing) {
    bool moved = false;
    for (int i = 0; i < refinements; ++i) {
        const Read mid = between(lo, hi);
        if (mid.missing) {
            missing = true;
            return moved;
        }
        moved |= mid.behind;
        (mid.behind ? lo : hi) = mid;
    }
    return moved;
}

// The history's judgement of a ray's step from `previous` to `now`: feed(read) passes a read
// to the history and returns its Crossing. Where the ray came out in front (and the step is
// `refinable`), refineCrossing's last point behind (if it moved) and first in front are fed
// instead of `now`. A read without memory sets `missing` and judges nothing.
template <class Read, class Between, class Feed>
DepthHistory::Crossing judgeStep(int refinements, const Read& previous, const Read& now, bool refinable,
                                 const Between& between, const Feed& feed, bool& missing) {
    if (!previous.behind || now.behind || !refinable) return feed(now);
    Read lo = previous, hi = now;
    const bool moved = refineCrossing(refinements, lo, hi, between, missing);
    if (missing) return DepthHistory::Crossing::None;
    if (moved) feed(lo);
    return feed(hi);
}

// One pixel's rays, tallied: V is the fraction not hit.
struct RayTally {
    int rays = 0, hits = 0, escapes = 0, missing = 0;
    void add(const RayEnd& end) { ++rays, hits += end.hit, escapes += end.escaped, missing += end.missing; }
    // Pixel k's V (rays > 0); its escaped fraction into escapedRays, its reads without a page
    // added to missingReads (a sum: the same for any thread count) and flagged in `missing`.
    float finish(size_t k, std::vector<float>& escapedRays, std::atomic<size_t>& missingReads, bool& missing) const {
        missing |= this->missing > 0;
        if (this->missing) missingReads += size_t(this->missing);
        escapedRays[k] = float(double(escapes) / double(rays));
        return float(double(rays - hits) / double(rays));
    }
};

struct SmrtResult {
    LookupResult lookup;
    std::vector<float> escapedRays;   // per pixel, the fraction of rays that escaped past an occluder's edge
    size_t missingReads = 0;          // samples whose page had no memory
};

// The rays' reach for marking (page_marking.h) from the sun's cone.
RayReach smrtReach(const SmrtSettings& smrt, double halfAngle, const DepthRange& range);

// V per pixel from `smrt.rays` rays (at least 1) in the cone of the half-angle whose tangent
// `marking.rays` holds (smrtReach's), around the sun's direction; `marking`: the settings
// marking had, whose boxes the rays' samples read within (heldRayLevel).
SmrtResult traceShadowMapRays(const GBuffer& g, const Light& sun, const LightFrame& frame,
                              const ClipmapSettings& clipmap, const DepthRange& range, const BiasSettings& bias,
                              const SmrtSettings& smrt, const MarkingSettings& marking,
                              const std::vector<PixelLevel>& levels, const PageTable& table, const PagePool& pool);

}  // namespace shadowlab::vsm
