// Where shadow-map ray tracing's rays towards a spot, point or area light read its mip
// chains (docs/virtual-shadow-maps.md; smrt.h for the sun's): one generator of sample
// points that marking and tracing both walk, so that every texel a ray reads lies in a page
// marking marked, by construction.
//
// Each pixel sends `rays` rays from its receiver (the hard lookup's, with its bias, as a
// world point) to points of the light (stratified over a disk's or a rectangle's area by a
// shifted (0, 2)-sequence, light_sampling.h, as reference-soft samples it; the apex itself
// for a point or spot light, one ray), jittered per pixel by a PCG32 stream of its index. A
// ray P -> L stops where no caster can be: at t_top, where P + t (L - P) enters the region
// nearer the apex than the depth range's near plane along every face's axis (so along the
// axis of the face that would hold it); a ray that never enters it runs to L. A point of
// the ray moves across the map in proportion to sigma(t) = t a / ((1 - t) a + t b), a and
// b P's and L's distances along the axis of P's face (the projection divides by the
// distance along the axis): sample k sits at sigma_k = sigma(t_top) ((k + xi) / steps)^2,
// so that, as the sun's rays climb, the samples move across the map in steps that grow
// from the receiver, where a perspective map would otherwise see the last steps near the
// light leap over an occluder's whole face. b is taken as at least 2 zNear,
// depthRangeAround's lower bound on any caster's distance along a face's axis (zNear is
// half of it): nearer the light no occluder needs finer steps, and sigma stays finite for a
// light wider than zNear. (Against t = t_top s^2 and against b >= zNear / 2, it had the
// least RMS on soft/'s cases but one, within 0.0015 of the best there; 16 rays, 160 x 100.)
//
// A sample reads its texel in the face that holds it (faceHolding; a sample in no face ends
// its ray) at the finest mip, from the pixel's own and never finer than the sample before,
// at which its drift across the receiver's beam is at most `reach` texels: a beam from the
// apex drifts by t |(L - apex) across| while the texel at axis distance d is
// 2 d tan(half-angle) 2^m / resolution m wide, so far samples read coarse mips that many
// pixels share, as the sun's rays read coarser levels (rayLevel).
//
// Where a ray comes out in front of the stored surface between two samples of one face,
// tracing halves that step a few times (local_smrt.h). Marking marks, for each sample, the
// pages of its mip under the box of its texel and the sample before's (pagesBetween): a
// face's projection takes the segment between them to a segment, inside that box, so
// those halvings too read only marked pages.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/light_sampling.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_table.h"
#include "shadows/virtual/smrt.h"

namespace shadowlab::vsm {

struct LocalRaySample {
    double t = 0.0;           // on its ray, P + t (L - P)
    int face = 0, mip = 0;
    int level = 0;            // mip * faces + face
    glm::dvec2 texel0{0.0};   // its texel coordinate at mip 0 (mip m's is 2^-m of it)
    int x = 0, y = 0;         // its texel at `mip`, clamped to the mip as a lookup clamps
    double depth = 0.0;       // the point's window depth in that face
    double along = 0.0;       // its distance along the face's axis, m
    glm::dvec3 fromApex{0.0}; // the point less the apex
};

class LocalRaySamples {
    // P + t (L - P) is affine in t in the world and in every face's view space, so a sample
    // is a few multiply-adds from what its ray keeps.
    struct Ray {
        glm::dvec3 fromApex, towardsLight;   // P - apex, and L - P
        glm::dvec3 originBeam;               // unit, from the apex to P
        std::array<glm::dvec3, 6> viewOrigin, viewStep;   // per face: P and L - P in its view space
        double sigmaTop, xi;                 // sigma at t_top (the header's comment), the jitter
        double along, alongLight;            // P's and L's distances along P's face's axis (L's at least 2 zNear)
        int mip;                             // the last sample's: samples never read finer
    };

public:
    // `light` as the scene has it (an area light's area is sampled); `chain` made for it.
    LocalRaySamples(const MipChain& chain, const Light& light, const BiasSettings& bias, const SmrtSettings& smrt);

    const MipChain& chain() const { return chain_; }

    // A pixel's receiver at the level marking chose for it, as the hard lookup maps it, and
    // that receiver as a sample (its texel, depth and place), where every ray starts.
    MapReceiver receiver(const PixelLevel& p, const glm::vec3& P, const glm::vec3& N) const;
    LocalRaySample originOf(const PixelLevel& p, const MapReceiver& r) const;

    // One ray's samples, in order: walk(visit) calls visit(sample) until it returns false,
    // the ray leaves every face or its samples are done.
    class RayWalk {
    public:
        template <class Visit>
        void walk(const Visit& visit) {
            LocalRaySample sample;
            for (int k = 0; k < samples_.smrt_.steps; ++k)
                if (!samples_.sampleAt(ray_, k, sample) || !visit(sample)) return;
        }
        // The point halfway between two samples of this ray on one face (the pyramid is
        // convex: it holds it), read at b's mip; marking marks the pages between them
        // (pagesBetween), so a refinement of a crossing reads only marked pages.
        LocalRaySample between(const LocalRaySample& a, const LocalRaySample& b) const {
            return samples_.pointOf(ray_, (a.t + b.t) / 2.0, b.face, b.mip);
        }

    private:
        friend class LocalRaySamples;
        RayWalk(const LocalRaySamples& samples, const Ray& ray) : samples_(samples), ray_(ray) {}
        const LocalRaySamples& samples_;
        Ray ray_;
    };

    // onRay(walk) for each ray of pixel k, in order; `r` is receiver()'s at level p.level. A
    // point or spot light gets one ray (all would follow one beam); a receiver that its bias
    // took to or behind the light's plane facing its face, none.
    template <class OnRay>
    void forEachRay(size_t k, const PixelLevel& p, const MapReceiver& r, const OnRay& onRay) const {
        const glm::dvec3 origin = originPoint(p, r);
        const glm::dmat4& face = chain_.faces[size_t(chain_.faceOfLevel(p.level))];
        if (!(-(face * glm::dvec4(origin, 1.0)).z > 0.0)) return;
        Pcg32 rng(kSmrtSeed, k);
        const glm::dvec2 shift(rng.nextDouble(), rng.nextDouble());
        const int rays = area_ ? smrt_.rays : 1;
        for (int ray = 0; ray < rays; ++ray) {
            RayWalk walk(*this, rayOf(origin, lightPoint(shiftedSobol02(uint32_t(ray), shift)),
                                      p.level, rng.nextDouble()));
            onRay(walk);
        }
    }

private:
    glm::dvec3 originPoint(const PixelLevel& p, const MapReceiver& r) const;
    glm::dvec3 lightPoint(const glm::dvec2& u) const;
    Ray rayOf(const glm::dvec3& origin, const glm::dvec3& L, int level, double xi) const;
    bool sampleAt(Ray& ray, int k, LocalRaySample& out) const;   // false: in no face
    // The sample at t, fromApex = X - apex, q = X in face `face`'s view space, at `mip`.
    LocalRaySample sampleOf(double t, const glm::dvec3& fromApex, const glm::dvec3& q, int face, int mip) const;
    LocalRaySample pointOf(const Ray& ray, double t, int face, int mip) const;

    const MipChain& chain_;
    BiasSettings bias_;
    SmrtSettings smrt_;
    bool area_;
    AreaLightFrame areaFrame_;
    std::vector<DepthMap> maps_;   // per level, only the matrices
    glm::dmat4 texelFromView_;     // mip 0's, for every face; mip m's is 2^-m of it in x and y
};

// Whether a crossing between samples a and b (in this order) is refined (local_smrt.h):
// only on one face.
inline bool refinable(const LocalRaySample& a, const LocalRaySample& b) { return a.face == b.face; }

// The pages of b's mip under the box of a's and b's texels: every point between them on
// one face reads a texel in it.
PageBox pagesBetween(const MipChain& chain, const LocalRaySample& a, const LocalRaySample& b);

// Marks the page of every texel a pixel's rays read (after markLocalPages, whose levels
// they start from); rows in parallel, the same for any thread count.
void markLocalRayPages(const GBuffer& g, const LocalRaySamples& samples, const std::vector<PixelLevel>& levels,
                       PageTable& table);

}  // namespace shadowlab::vsm
