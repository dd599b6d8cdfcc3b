#include "shadows/virtual/smrt.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "raster/portable_math.h"
#include "shading/light_sampling.h"

namespace shadowlab::vsm {
namespace {

// What every ray of every pixel shares.
struct Marcher {
    const PageTexels& texels;
    const ClipmapSettings& clipmap;
    RayReach reach;
    double boxReach;    // marking's box about a pixel at each level its rays read (rayBoxReach)
    const std::vector<LevelWindow>& windows;
    double depthPerM;   // window depth per m along the beam
    const SmrtSettings& smrt;
    std::vector<double> texelM;   // per level from the first: its texel, m
};

// A pixel's receiver: its level, texel there, biased window depth, and what the hard
// lookup read at its texel.
struct Origin {
    int level;
    // Per level from the first: heldRayLevel's answer from there for this pixel, the level
    // its rays' samples read (-1, unread, below the pixel's own level: samples never read
    // finer than it).
    std::array<int8_t, kMaxLevelCount> heldFrom;
    glm::dvec2 texel;
    double depth;
    float stored;
    bool behind;
};

// heldRayLevel from every level at or above `level` for a pixel at `local` (the light's
// frame), from the last level down: a level whose window holds the rays' box is its own
// answer, else the next one's.
void heldLevelsFrom(const Marcher& m, int level, const glm::dvec3& local, std::array<int8_t, kMaxLevelCount>& held) {
    const int first = m.clipmap.firstLevel;
    held.fill(-1);
    held[size_t(m.clipmap.lastLevel - first)] = int8_t(m.clipmap.lastLevel);
    for (int l = m.clipmap.lastLevel - 1; l >= level; --l)
        held[size_t(l - first)] = windowHoldsBox(m.clipmap, m.windows[size_t(l - first)], local, m.boxReach)
                                      ? int8_t(l)
                                      : held[size_t(l + 1 - first)];
}

// A sample `h` m up a ray and what its texel holds.
struct SunRead {
    double h = 0.0;
    int level = 0;
    glm::dvec2 across{0.0};   // m across the beam from the receiver
    double texel = 0.0;       // its level's texel, m
    float stored = 0.0f;
    bool missing = false, empty = false, behind = false;
};

// One ray climbing across the beam by `slope` (m per m, the frame's x and y), its steps
// jittered by xi.
RayEnd marchRay(const Marcher& m, const Origin& o, const glm::dvec2& slope, double xi) {
    const double height = o.depth / m.depthPerM;   // m up to the depth range's top
    const double originTexel = m.texelM[size_t(o.level - m.clipmap.firstLevel)];
    PageTexels::Cursor cursor;
    const auto readAt = [&](double h, int level) {
        SunRead r{h, level, slope * h, m.texelM[size_t(level - m.clipmap.firstLevel)]};
        // The receiver's texel at this level (an exact power-of-two scaling), moved across.
        const glm::dvec2 t = o.texel * (originTexel / r.texel) + glm::dvec2(r.across.x, -r.across.y) / r.texel;
        r.stored = m.texels.at(level, texelIndexOf(t.x), texelIndexOf(t.y), cursor);
        r.missing = r.stored == PageTexels::kMissingTexel;
        r.empty = r.stored >= 1.0f;
        r.behind = !r.missing && !r.empty && o.depth - h * m.depthPerM > double(r.stored);
        return r;
    };
    DepthHistory history(m.smrt.maxSlope * m.depthPerM, o.stored, o.stored >= 1.0f, o.behind);
    SunRead previous{0.0, o.level, glm::dvec2(0.0), originTexel, o.stored, false, o.stored >= 1.0f, o.behind};
    SunRead fed = previous;   // the last read the history saw
    const auto feed = [&](const SunRead& r) {
        const double step = glm::length(r.across - fed.across);
        fed = r;
        return history.next(r.stored, r.empty, r.behind, step, r.texel);
    };
    const auto halfway = [&](const SunRead& a, const SunRead& b) { return readAt((a.h + b.h) / 2.0, b.level); };
    RayEnd end;
    // Each sample reads from the last sample's level (h only grows) on, at one whose window
    // holds the pixel's rays' box, where marking marked it: looked for again only where the
    // drift moves a sample coarser.
    int level = o.heldFrom[size_t(o.level - m.clipmap.firstLevel)];
    for (int k = 0; k < m.smrt.steps; ++k) {
        const double s = (k + xi) / m.smrt.steps, h = height * s * s;
        const int drifted = rayLevel(m.clipmap, level, h, m.reach);
        if (drifted != level) level = o.heldFrom[size_t(drifted - m.clipmap.firstLevel)];
        const SunRead now = readAt(h, level);
        // Halvings read at the later sample's level, whose marked box holds every point
        // below it (its drift is smaller).
        const DepthHistory::Crossing crossing =
            now.missing ? DepthHistory::Crossing::None
                        : judgeStep(m.smrt.refinements, previous, now, true, halfway, feed, end.missing);
        end.missing |= now.missing;
        if (end.missing || !end.goesOn(crossing)) return end;
        previous = now;
    }
    end.hit = history.behind();
    return end;
}

}  // namespace

DepthHistory::Crossing DepthHistory::next(double stored, bool empty, bool nowBehind, double step, double texel) {
    Crossing crossing = Crossing::None;
    if (behind_ && !nowBehind) {
        // Out in front again: through the surface it was behind (hit), or past its edge.
        const double extrapolated = previous_ + previousSlope_ * step;
        const double tolerance = slopeLimit_ * (step + texel);
        if (!empty && stored <= extrapolated + tolerance) return Crossing::Hit;
        crossing = Crossing::Escaped;
    }
    previousSlope_ = empty || previousEmpty_ || step <= 0.0
                         ? 0.0
                         : std::clamp((stored - previous_) / step, -slopeLimit_, slopeLimit_);
    previous_ = stored, previousEmpty_ = empty, behind_ = nowBehind;
    return crossing;
}

RayReach smrtReach(const SmrtSettings& smrt, double halfAngle, const DepthRange& range) {
    // portable::tan, not libm's, whose bits depend on the CPU it dispatches to.
    return {smrt.rays > 0 ? portable::tan(halfAngle) : 0.0, smrt.reachTexels, range.zNear};
}

SmrtResult traceShadowMapRays(const GBuffer& g, const Light& sun, const LightFrame& frame,
                              const ClipmapSettings& clipmap, const DepthRange& range, const BiasSettings& bias,
                              const SmrtSettings& smrt, const MarkingSettings& marking,
                              const std::vector<PixelLevel>& levels, const PageTable& table, const PagePool& pool) {
    const std::vector<DepthMap> maps = levelMaps(frame, clipmap, range);
    const PageTexels texels(clipmap.pageTexels, table, pool);
    Marcher marcher{texels, clipmap, marking.rays, rayBoxReach(marking), table.windows(),
                    1.0 / (range.zFar - range.zNear), smrt, {}};
    for (int l = clipmap.firstLevel; l <= clipmap.lastLevel; ++l) marcher.texelM.push_back(clipmap.texelM(l));
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(sun.direction));
    SmrtResult out{{}, std::vector<float>(g.pixelCount(), 0.0f)};
    std::atomic<size_t> missingReads = 0;   // a sum: the same for any thread count
    out.lookup = lookUpEachPixel(g, sun, levels, [&](size_t k, const PixelLevel& p, bool& missing) {
        const MapReceiver r = mapReceiver(maps[size_t(p.level)], glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]),
                                          towardsLight, bias);
        const int level = clipmap.firstLevel + p.level;
        const int tx = texelIndexOf(r.texel.x), ty = texelIndexOf(r.texel.y);
        const float stored = texels.at(level, tx, ty);
        if (stored == PageTexels::kMissingTexel) {
            missing = true;
            return 1.0f;
        }
        Origin origin{level, {}, r.texel, r.depth, stored, !r.litByStored(stored, tx, ty)};
        // A receiver whose bias lifted it above the depth range's top has no height to climb.
        if (!(r.depth > 0.0)) return origin.behind ? 0.0f : 1.0f;
        heldLevelsFrom(marcher, level, frame.local(glm::dvec3(g.position[k])), origin.heldFrom);
        // Directions stratified over the cone's disk (a shifted (0, 2)-sequence).
        Pcg32 rng(kSmrtSeed, k);
        const glm::dvec2 shift(rng.nextDouble(), rng.nextDouble());
        // A point-like sun's rays would all run along the beam: one is enough.
        const int rays = marcher.reach.tanHalfAngle > 0.0 ? smrt.rays : 1;
        RayTally tally;
        for (int ray = 0; ray < rays; ++ray) {
            const glm::dvec2 disk = concentricSquareToDisk(shiftedSobol02(uint32_t(ray), shift));
            tally.add(marchRay(marcher, origin, marcher.reach.tanHalfAngle * disk, rng.nextDouble()));
        }
        return tally.finish(k, out.escapedRays, missingReads, missing);
    });
    out.missingReads = missingReads;
    return out;
}

}  // namespace shadowlab::vsm
