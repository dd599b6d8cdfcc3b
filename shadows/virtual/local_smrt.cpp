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
    double distance = 0.0;         // the sample's from the apex, m
    glm::dvec3 beam{0.0};          // the unit direction from the apex to it
    double storedDistance = 0.0;   // the stored surface on the sample's beam, m from the apex
    double texelM = 0.0;           // the texel's side there, m
};

// What tracing every ray shares.
struct Tracer {
    const PageTexels& texels;
    AxisDistance axis;
    double texelPerAlong;   // a mip-0 texel's side per m along a face's axis
    const SmrtSettings& smrt;

    LocalRead read(PageTexels::Cursor& cursor, const LocalRaySample& s) const {
        LocalRead r{s, texels.at(s.level, s.x, s.y, cursor)};
        r.missing = r.stored == PageTexels::kMissingTexel;
        r.empty = r.stored >= 1.0f;
        r.distance = glm::length(s.fromApex);
        r.beam = r.distance > 0.0 ? s.fromApex * (1.0 / r.distance) : glm::dvec3(0.0);
        if (r.missing || r.empty) return r;
        r.behind = s.depth > double(r.stored);
        const double storedAlong = axis(r.stored);
        r.storedDistance = r.distance * storedAlong / s.along;
        r.texelM = texelPerAlong * storedAlong * double(1 << s.mip);
        return r;
    }
};

// One ray's depth history over the reads it is fed.
class RayHistory {
public:
    RayHistory(double maxSlope, const LocalRead& origin)
        : history_(maxSlope, origin.storedDistance, origin.empty, origin.behind), last_(origin) {}
    DepthHistory::Crossing feed(const LocalRead& r) {
        // The step across, as a chord between the two beams at the surface the ray was last
        // behind or beside (the sample's own distance where that texel is empty).
        const double at = last_.empty ? last_.distance : last_.storedDistance;
        const double step = glm::length(r.beam - last_.beam) * at;
        last_ = r;
        return history_.next(r.storedDistance, r.empty, r.behind, step, r.texelM);
    }
    bool behind() const { return history_.behind(); }

private:
    DepthHistory history_;
    LocalRead last_;
};

// One ray from `origin` along its walk's samples.
RayEnd traceRay(const Tracer& t, LocalRaySamples::RayWalk& ray, const LocalRead& origin) {
    RayHistory history(t.smrt.maxSlope, origin);
    PageTexels::Cursor cursor;
    const auto feed = [&](const LocalRead& r) { return history.feed(r); };
    // Halvings between two samples of one face: pagesBetween marked the pages between them.
    const auto halfway = [&](const LocalRead& a, const LocalRead& b) {
        return t.read(cursor, ray.between(a.sample, b.sample));
    };
    LocalRead previous = origin;
    RayEnd end;
    ray.walk([&](const LocalRaySample& s) {
        const LocalRead now = t.read(cursor, s);
        const DepthHistory::Crossing crossing =
            now.missing ? DepthHistory::Crossing::None
                        : judgeStep(t.smrt.refinements, previous, now, refinable(previous.sample, s), halfway, feed,
                                    end.missing);
        end.missing |= now.missing;
        previous = now;
        return !end.missing && end.goesOn(crossing);
    });
    // A ray still behind at its last sample (or where it left every face) is hit.
    end.hit |= !end.missing && history.behind();
    return end;
}

}  // namespace

SmrtResult traceLocalShadowMapRays(const GBuffer& g, const Light& light, const LocalRaySamples& samples,
                                   const SmrtSettings& smrt, const std::vector<PixelLevel>& levels,
                                   const PageTable& table, const PagePool& pool) {
    const MipChain& chain = samples.chain();
    const PageTexels texels(chain.pageTexels, table, pool);
    const Tracer tracer{texels, {chain.range.zNear, chain.range.zFar}, 2.0 * chain.tanHalf / double(chain.resolution),
                        smrt};
    SmrtResult out{{}, std::vector<float>(g.pixelCount(), 0.0f)};
    std::atomic<size_t> missingReads = 0;   // a sum: the same for any thread count
    out.lookup = lookUpEachPixel(g, light, levels, [&](size_t k, const PixelLevel& p, bool& missing) {
        const MapReceiver r = samples.receiver(p, g.position[k], g.normal[k]);
        PageTexels::Cursor cursor;
        LocalRead origin = tracer.read(cursor, samples.originOf(p, r));
        if (origin.missing) {
            missing = true;
            return 1.0f;
        }
        origin.behind = !r.litByStored(origin.stored, origin.sample.x, origin.sample.y);   // the hard lookup's
        RayTally tally;
        samples.forEachRay(k, p, r, [&](LocalRaySamples::RayWalk& ray) { tally.add(traceRay(tracer, ray, origin)); });
        // A receiver whose bias took it behind the light sends none: the hard lookup's answer.
        if (tally.rays == 0) return origin.behind ? 0.0f : 1.0f;
        return tally.finish(k, out.escapedRays, missingReads, missing);
    });
    out.missingReads = missingReads;
    return out;
}

}  // namespace shadowlab::vsm
