#include "shadows/virtual/local_ray_samples.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadows/texel_index.h"

namespace shadowlab::vsm {

LocalRaySamples::LocalRaySamples(const MipChain& chain, const Light& light, const BiasSettings& bias,
                                 const SmrtSettings& smrt)
    : chain_(chain), bias_(bias), smrt_(smrt),
      area_(light.type == LightType::Disk || light.type == LightType::Rectangle),
      areaFrame_(area_ ? areaLightFrame(light) : AreaLightFrame{}), maps_(levelMaps(chain)),
      texelFromView_(texelFromClip(chain.resolution) * chain.clipFromView()) {}

MapReceiver LocalRaySamples::receiver(const PixelLevel& p, const glm::vec3& P, const glm::vec3& N) const {
    return mapReceiverFromPoint(maps_[size_t(p.level)], glm::dvec3(P), glm::dvec3(N), chain_.apex, bias_);
}

glm::dvec3 LocalRaySamples::originPoint(const PixelLevel& p, const MapReceiver& r) const {
    // The biased receiver back in the world: a normal offset or a constant bias moved it
    // towards the light, and its rays start there.
    const glm::dvec4 h = maps_[size_t(p.level)].worldFromTexel * glm::dvec4(r.texel, r.depth, 1.0);
    return glm::dvec3(h) / h.w;
}

LocalRaySample LocalRaySamples::originOf(const PixelLevel& p, const MapReceiver& r) const {
    const glm::dvec3 P = originPoint(p, r);
    const int face = chain_.faceOfLevel(p.level);
    LocalRaySample s = sampleOf(0.0, P - chain_.apex, glm::dvec3(chain_.faces[size_t(face)] * glm::dvec4(P, 1.0)), face,
                                chain_.mipOfLevel(p.level));
    // The hard lookup's texel and depth, not the point's round trip through the matrices.
    const int last = chain_.mipTexels(chain_.mipOfLevel(p.level)) - 1;
    s.x = std::clamp(texelIndexOf(r.texel.x), 0, last), s.y = std::clamp(texelIndexOf(r.texel.y), 0, last);
    s.depth = r.depth;
    return s;
}

glm::dvec3 LocalRaySamples::lightPoint(const glm::dvec2& u) const {
    return area_ ? areaLightPoint(areaFrame_, u) : chain_.apex;
}

LocalRaySamples::Ray LocalRaySamples::rayOf(const glm::dvec3& origin, const glm::dvec3& L, int level, double xi) const {
    Ray ray;
    ray.fromApex = origin - chain_.apex, ray.towardsLight = L - origin;
    const double distance = glm::length(ray.fromApex);
    ray.originBeam = distance > 0.0 ? ray.fromApex / distance : glm::dvec3(0.0);
    ray.xi = xi, ray.mip = chain_.mipOfLevel(level);
    // t_top: where the ray enters the region nearer than zNear along every face's axis (an
    // intersection of half-spaces, so [enter, leave] along the ray); one that never enters it
    // runs to L.
    const double zNear = chain_.range.zNear;
    double enter = 0.0, leave = 1.0;
    for (size_t f = 0; f < chain_.faces.size(); ++f) {
        ray.viewOrigin[f] = glm::dvec3(chain_.faces[f] * glm::dvec4(origin, 1.0));
        ray.viewStep[f] = glm::dvec3(chain_.faces[f] * glm::dvec4(ray.towardsLight, 0.0));
        const double a = -ray.viewOrigin[f].z, b = a - ray.viewStep[f].z;
        if (a > zNear && b > zNear) enter = 1.0;   // never nearer along this axis
        if ((a > zNear) == (b > zNear)) continue;
        const double crossing = (a - zNear) / (a - b);
        if (a > b)
            enter = std::max(enter, crossing);
        else
            leave = std::min(leave, crossing);
    }
    const double tTop = enter < leave ? enter : 1.0;
    const size_t face = size_t(chain_.faceOfLevel(level));
    ray.along = -ray.viewOrigin[face].z;
    ray.alongLight = std::max(ray.along - ray.viewStep[face].z, 2.0 * zNear);
    ray.sigmaTop = tTop * ray.along / ((1.0 - tTop) * ray.along + tTop * ray.alongLight);
    return ray;
}

LocalRaySample LocalRaySamples::sampleOf(double t, const glm::dvec3& fromApex, const glm::dvec3& q, int face,
                                         int mip) const {
    LocalRaySample s;
    s.t = t, s.face = face, s.mip = mip, s.level = chain_.levelOf(face, mip);
    const glm::dvec4 h = texelFromView_ * glm::dvec4(q, 1.0);
    const double perW = 1.0 / h.w;
    s.texel0 = glm::dvec2(h.x * perW, h.y * perW);
    const double scale = 1.0 / double(1 << mip);   // exact: mip m's texels are 2^m of mip 0's
    const int last = chain_.mipTexels(mip) - 1;
    s.x = std::clamp(texelIndexOf(s.texel0.x * scale), 0, last);
    s.y = std::clamp(texelIndexOf(s.texel0.y * scale), 0, last);
    s.depth = h.z * perW;
    s.along = -q.z;
    s.fromApex = fromApex;
    return s;
}

LocalRaySample LocalRaySamples::pointOf(const Ray& ray, double t, int face, int mip) const {
    const glm::dvec3 q = ray.viewOrigin[size_t(face)] + t * ray.viewStep[size_t(face)];
    return sampleOf(t, ray.fromApex + t * ray.towardsLight, q, face, mip);
}

bool LocalRaySamples::sampleAt(Ray& ray, int k, LocalRaySample& out) const {
    // sigma's inverse: t = sigma a / (a + sigma (a - b)).
    const double s = (k + ray.xi) / smrt_.steps, sigma = ray.sigmaTop * s * s;
    const double t = sigma * ray.along / (ray.along + sigma * (ray.along - ray.alongLight));
    int face = 0;
    glm::dvec3 q;
    for (; face < chain_.faceCount(); ++face) {
        q = ray.viewOrigin[size_t(face)] + t * ray.viewStep[size_t(face)];
        if (chain_.pyramidHolds(q)) break;
    }
    if (face == chain_.faceCount()) return false;
    // The drift across the receiver's beam, in mip-0 texels at the sample's distance along
    // its face's axis; the finest mip, from the last sample's, that holds it within reach.
    // Compared squared: |across| resolution > reach 2^m 2 along tan(half-angle).
    const glm::dvec3 fromApex = ray.fromApex + t * ray.towardsLight;
    const glm::dvec3 across = fromApex - glm::dot(fromApex, ray.originBeam) * ray.originBeam;
    const double drift = glm::dot(across, across) * double(chain_.resolution) * double(chain_.resolution);
    const double reachM = smrt_.reachTexels * 2.0 * -q.z * chain_.tanHalf;   // at mip 0
    while (ray.mip < chain_.mipCount - 1 && drift > reachM * reachM * double(1 << (2 * ray.mip))) ++ray.mip;
    out = sampleOf(t, fromApex, q, face, ray.mip);
    return true;
}

PageBox pagesBetween(const MipChain& chain, const LocalRaySample& a, const LocalRaySample& b) {
    const double scale = 1.0 / double(1 << b.mip);
    const glm::dvec2 lo = glm::min(a.texel0, b.texel0) * scale, hi = glm::max(a.texel0, b.texel0) * scale;
    const int32_t last = chain.pagesPerSide(b.mip) - 1, lastTexel = chain.mipTexels(b.mip) - 1;
    // Clamped as a read clamps its texel, then to pages.
    const auto page = [&](double c) {
        return std::clamp(int32_t(std::clamp(texelIndexOf(c), 0, lastTexel) / chain.pageTexels), int32_t(0), last);
    };
    return {page(lo.x), page(lo.y), page(hi.x), page(hi.y)};
}

void markLocalRayPages(const GBuffer& g, const LocalRaySamples& samples, const std::vector<PixelLevel>& levels,
                       PageTable& table) {
    const MipChain& chain = samples.chain();
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        BoxRequests requests(table);
        for (int j = rows.begin(); j < rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                const PixelLevel& p = levels[k];
                if (p.level == kNoLevel) continue;   // unlit, unreached or in no face
                const MapReceiver r = samples.receiver(p, g.position[k], g.normal[k]);
                const LocalRaySample origin = samples.originOf(p, r);
                samples.forEachRay(k, p, r, [&](LocalRaySamples::RayWalk& ray) {
                    LocalRaySample previous = origin;
                    ray.walk([&](const LocalRaySample& s) {
                        requests.request(s.level, pagesBetween(chain, refinable(previous, s) ? previous : s, s));
                        previous = s;
                        return true;
                    });
                });
            }
        }
    });
}

}  // namespace shadowlab::vsm
