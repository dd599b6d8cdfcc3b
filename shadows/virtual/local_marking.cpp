#include "shadows/virtual/local_marking.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::vsm {

int matchingMip(const MipChain& chain, double footprint, double along, int lodBias) {
    // texel(m) = 2 along tan 2^m / resolution <= footprint: m = floor(log2(footprint resolution
    // / (2 along tan))), the binary exponent, exact.
    const double scaled = footprint * double(chain.resolution) / (2.0 * along * chain.tanHalf);
    // A pixel wider than the coarsest texel reads the coarsest mip; one finer than mip 0's,
    // or at no depth (or none along the face's axis: an infinite ratio), mip 0.
    const int mip = scaled > 0.0 && std::isfinite(scaled) ? binaryExponent(scaled) - 1 + lodBias : 0;
    return std::clamp(mip, 0, chain.mipCount - 1);
}

glm::dvec2 texelIn(const glm::dmat4& texelFromWorld, const glm::dvec3& P) {
    const glm::dvec4 h = texelFromWorld * glm::dvec4(P, 1.0);
    return glm::dvec2(glm::dvec3(h) / h.w);
}

PageBox localPagesRead(const MipChain& chain, int mip, const glm::dvec2& texel, double reachTexels) {
    const PageBox box = pagesRead(texel, reachTexels, chain.pageTexels);
    const int32_t last = chain.pagesPerSide(mip) - 1;
    const auto clamp = [&](int32_t p) { return std::clamp(p, int32_t(0), last); };
    return {clamp(box.x0), clamp(box.y0), clamp(box.x1), clamp(box.y1)};
}

void markLocalPages(const GBuffer& g, const Camera& camera, const Light& light, const MipChain& chain,
                    const MarkingSettings& settings, PageTable& table, std::vector<PixelLevel>& levels) {
    const PixelFootprint footprint(camera);
    std::vector<glm::dmat4> texelFromWorld;   // per level
    for (int level = 0; level < chain.levelCount(); ++level) texelFromWorld.push_back(chain.texelFromWorld(level));
    markEachPixel(g, light, table, levels, [&](size_t k, BoxRequests& requests) {
        const glm::dvec3 P(g.position[k]);
        const int face = chain.faceHolding(P);
        if (face < 0) return PixelLevel{};
        const double along = -(chain.faces[size_t(face)] * glm::dvec4(P, 1.0)).z;
        const int mip = matchingMip(chain, footprint.at(P), along, settings.lodBias);
        const int level = chain.levelOf(face, mip);
        const glm::dvec2 texel = texelIn(texelFromWorld[size_t(level)], P);
        requests.request(level, localPagesRead(chain, mip, texel, settings.reachTexels));
        return PixelLevel{int8_t(level), texel};
    });
}

}  // namespace shadowlab::vsm
