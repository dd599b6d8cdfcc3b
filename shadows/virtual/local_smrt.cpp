#include "shadows/virtual/local_smrt.h"

#include <atomic>

namespace shadowlab::vsm {
namespace {

// Window depth w of a face's frustum (glm::frustumRH_NO between n and f, window depth
// (z_ndc + 1) / 2) back to the distance along its axis: d = 2 n f / (f + n - z_ndc (f - n)).
struct AxisDistance {
    double n, f;
    double operator()(double w) const { return 2.0 * n * f / (f + n - (2.0 * w - 1.0) * (f - n)); }
};

// A sample and what its texel holds.
struct LocalRead {
    LocalRaySample sample;
    float stored = 0.0f;
    bool missing = false, empty = false, behind = false;
    double storedDistance = 0.0;   // the stored surface on the sample's beam, m from the apex
    double texelM = 0.0;           // the texel's side there, m
};

LocalRead readAt(const PageTexels& texels, PageTexels::Cursor& cursor, const AxisDistance& axis, const LocalRaySample& s) {
    LocalRead r{s, texels.at(s.level, s.x, s.y, cursor)};
    r.missing = r.stored == PageTexels::kMissingTexel;
    r.empty = r.stored >= 1.0f;
    if (r.missing || r.empty) return r;
    r.behind = s.depth > double(r.stored);
    const double storedAlong = axis(r.stored);
    r.storedDistance = s.distance * storedAlong / s.along;
    r.texelM = s.texelM * storedAlong / s.along;
    return r;
}

// One ray's depth history over the reads it is fed.
class RayHistory {
public:
    RayHistory(double maxSlope, const LocalRead& origin)
        : history_(maxSlope, origin.storedDistance, origin.empty, origin.behind), last_(origin) {}
    DepthHistory::Crossing feed(const LocalRead& r) {
        // The step across, as a chord between the two beams at the surface the ray was last
        // behind or beside (the sample's own distance where that texel is empty).
        const double at = last_.empty ? last_.sample.distance : last_.storedDistance;
        const double step = glm::length(r.sample.beam - last_.sample.beam) * at;
        last_ = r;
        return history_.next(r.storedDistance, r.empty, r.behind, step, r.texelM);
    }
    bool behind() const { return history_.behind(); }

private:
    DepthHistory history_;
    LocalRead last_;
};

}  // namespace

SmrtResult traceLocalShadowMapRays(const GBuffer& g, const Light& light, const LocalRaySamples& samples,
                                   const SmrtSettings& smrt, const std::vector<PixelLevel>& levels,
                                   const PageTable& table, const PagePool& pool) {
    const MipChain& chain = samples.chain();
    const PageTexels texels(chain.pageTexels, table, pool);
    const AxisDistance axis{chain.range.zNear, chain.range.zFar};
    SmrtResult out{{}, std::vector<float>(g.pixelCount(), 0.0f)};
    std::atomic<size_t> missingReads = 0;   // a sum: the same for any thread count
    out.lookup = lookUpEachPixel(g, light, levels, [&](size_t k, const PixelLevel& p, bool& missing) {
        const MapReceiver r = samples.receiver(p, g.position[k], g.normal[k]);
        PageTexels::Cursor cursor;
        LocalRead origin = readAt(texels, cursor, axis, samples.originOf(p, r));
        if (origin.missing) {
            missing = true;
            return 1.0f;
        }
        origin.behind = !r.litByStored(origin.stored, origin.sample.x, origin.sample.y);   // the hard lookup's
        int hits = 0, escapes = 0;
        size_t reads = 0;
        samples.forEachRay(k, p, r, [&](LocalRaySamples::RayWalk& ray) {
            RayHistory history(smrt.maxSlope, origin);
            LocalRead previous = origin;
            RayEnd end;
            ray.walk([&](const LocalRaySample& s) {
                const LocalRead now = readAt(texels, cursor, axis, s);
                DepthHistory::Crossing crossing;
                if (now.missing) {
                    end.missing = true;
                    return false;
                }
                if (previous.behind && !now.behind && refinable(previous.sample, s)) {
                    // Out in front again: halved towards where (the pages between the two
                    // are marked: pagesBetween).
                    LocalRead lo = previous, hi = now;
                    const auto halfway = [&](const LocalRead& a, const LocalRead& b) {
                        return readAt(texels, cursor, axis, ray.between(a.sample, b.sample));
                    };
                    refineCrossing(smrt.refinements, lo, hi, halfway, end.missing);
                    if (end.missing) return false;
                    if (lo.sample.t != previous.sample.t) history.feed(lo);
                    crossing = history.feed(hi);
                } else {
                    crossing = history.feed(now);
                }
                previous = now;
                end.hit = crossing == DepthHistory::Crossing::Hit;
                end.escaped |= crossing == DepthHistory::Crossing::Escaped;
                return !end.hit;
            });
            // A ray still behind at its last sample (or where it left every face) is hit.
            end.hit |= !end.missing && history.behind();
            hits += end.hit, escapes += end.escaped, missing |= end.missing;
            reads += end.missing;
        });
        if (reads) missingReads += reads;
        out.escapedRays[k] = float(double(escapes) / double(smrt.rays));
        return float(double(smrt.rays - hits) / double(smrt.rays));
    });
    out.missingReads = missingReads;
    return out;
}

}  // namespace shadowlab::vsm
