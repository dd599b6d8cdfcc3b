#include "shadows/virtual/smrt.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "raster/portable_math.h"
#include "shading/light_sampling.h"

namespace shadowlab::vsm {
namespace {

constexpr uint64_t kSeed = 0x5eed5eed5eedull;   // the reference's: pixel k draws from PCG32 stream k

// What every ray of every pixel shares.
struct Marcher {
    const PageTexels& texels;
    const ClipmapSettings& clipmap;
    RayReach reach;
    double depthPerM;   // window depth per m along the beam
    const SmrtSettings& smrt;
    std::vector<double> texelM;   // per level from the first: its texel, m
};

// A pixel's receiver: its level, texel there, biased window depth, and what the hard
// lookup read at its texel.
struct Origin {
    int level;
    glm::dvec2 texel;
    double depth;
    float stored;
    bool behind;
};

struct RayEnd {
    bool hit = false, escaped = false, missing = false;
};

// One ray climbing across the beam by `slope` (m per m, the frame's x and y), its steps
// jittered by xi.
RayEnd marchRay(const Marcher& m, const Origin& o, const glm::dvec2& slope, double xi) {
    const double height = o.depth / m.depthPerM;   // m up to the depth range's top
    const double slopeLimit = m.smrt.maxSlope * m.depthPerM;
    double previous = o.stored, previousSlope = 0.0;   // the depth history, window depth per m across
    glm::dvec2 previousAcross(0.0);
    bool behind = o.behind;
    RayEnd end;
    PageTexels::Cursor cursor;
    const double originTexel = m.texelM[size_t(o.level - m.clipmap.firstLevel)];
    int level = o.level;
    for (int k = 0; k < m.smrt.steps; ++k) {
        const double s = (k + xi) / m.smrt.steps, h = height * s * s;
        const glm::dvec2 across = slope * h;
        level = rayLevel(m.clipmap, level, h, m.reach);   // from the last sample's: h only grows
        const double texel = m.texelM[size_t(level - m.clipmap.firstLevel)];
        // The receiver's texel at this level (an exact power-of-two scaling), moved across.
        const glm::dvec2 t = o.texel * (originTexel / texel) + glm::dvec2(across.x, -across.y) / texel;
        const float stored = m.texels.at(level, texelIndexOf(t.x), texelIndexOf(t.y), cursor);
        if (stored == PageTexels::kMissingTexel) {
            end.missing = true;
            return end;
        }
        const bool empty = stored >= 1.0f;
        const bool nowBehind = !empty && o.depth - h * m.depthPerM > double(stored);
        const double step = glm::length(across - previousAcross);
        if (behind && !nowBehind) {
            // Out in front again: through the surface it was behind (hit), or past its edge.
            const double extrapolated = previous + previousSlope * step;
            const double tolerance = slopeLimit * (step + texel);
            if (!empty && double(stored) <= extrapolated + tolerance) {
                end.hit = true;
                return end;
            }
            end.escaped = true;
        }
        const bool emptyBefore = previous >= 1.0;
        previousSlope = empty || emptyBefore || step <= 0.0
                            ? 0.0
                            : std::clamp((double(stored) - previous) / step, -slopeLimit, slopeLimit);
        previous = stored, previousAcross = across, behind = nowBehind;
    }
    end.hit = behind;
    return end;
}

}  // namespace

RayReach smrtReach(const SmrtSettings& smrt, double halfAngle, const DepthRange& range) {
    // portable::tan, not libm's, whose bits depend on the CPU it dispatches to.
    return {smrt.rays > 0 ? portable::tan(halfAngle) : 0.0, smrt.reachTexels, range.zNear};
}

SmrtResult traceShadowMapRays(const GBuffer& g, const Light& sun, double halfAngle, const LightFrame& frame,
                              const ClipmapSettings& clipmap, const DepthRange& range, const BiasSettings& bias,
                              const SmrtSettings& smrt, const std::vector<PixelLevel>& levels, const PageTable& table,
                              const PagePool& pool) {
    const std::vector<DepthMap> maps = levelMaps(frame, clipmap, range);
    const PageTexels texels(clipmap.pageTexels, table, pool);
    Marcher marcher{texels, clipmap, smrtReach(smrt, halfAngle, range), 1.0 / (range.zFar - range.zNear), smrt, {}};
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
        const Origin origin{level, r.texel, r.depth, stored, !r.litByStored(stored, tx, ty)};
        // Directions stratified over the cone's disk (a shifted (0, 2)-sequence).
        Pcg32 rng(kSeed, k);
        const glm::dvec2 shift(rng.nextDouble(), rng.nextDouble());
        int hits = 0, escapes = 0;
        size_t reads = 0;
        for (int ray = 0; ray < smrt.rays; ++ray) {
            const glm::dvec2 disk = concentricSquareToDisk(shiftedSobol02(uint32_t(ray), shift));
            const RayEnd end = marchRay(marcher, origin, marcher.reach.tanHalfAngle * disk, rng.nextDouble());
            hits += end.hit, escapes += end.escaped, missing |= end.missing;
            reads += end.missing;
        }
        if (reads) missingReads += reads;
        out.escapedRays[k] = float(double(escapes) / double(smrt.rays));
        return float(double(smrt.rays - hits) / double(smrt.rays));
    });
    out.missingReads = missingReads;
    return out;
}

}  // namespace shadowlab::vsm
