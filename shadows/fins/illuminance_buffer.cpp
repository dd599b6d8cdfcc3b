#include "shadows/fins/illuminance_buffer.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// The texel holding coordinate v (texel units) of a size-texel map, clamped to its border.
int texelOf(double v, int size) { return std::clamp(texelIndexOf(v), 0, size - 1); }

}  // namespace

double refinedWeight(double s0, double edgeWeight, double Lb, double Lr, double L0) {
    const double widthRatio = ((L0 - Lb) / L0) * (Lr / (Lr - Lb));   // B_0 / B_r, eqs. 2 and 3
    return std::clamp(edgeWeight + widthRatio * (s0 - edgeWeight), 0.0, double(edgeWeight));
}

double fallOff(double s, Falloff falloff) {
    return falloff == Falloff::Linear ? s : s * s * (3.0 - 2.0 * s);
}

IlluminanceBuffer::IlluminanceBuffer(const GBuffer& gbuffer, const std::vector<uint8_t>& lit)
    : gbuffer_(gbuffer), values_(lit.begin(), lit.end()) {}

IlluminanceBuffer::PlacedReceiver IlluminanceBuffer::place(size_t k, const DepthMap& hard, const IlluminanceSettings& s) const {
    const glm::dvec3 P(gbuffer_.position[k]), N(gbuffer_.normal[k]);
    const MapReceiver receiver = mapReceiverFromPoint(hard, P, N, s.light.centre, s.bias);
    PlacedReceiver r;
    r.x = texelOf(receiver.texel.x, hard.size), r.y = texelOf(receiver.texel.y, hard.size);
    r.depthAtCentre = receiver.depthAt(glm::dvec2(r.x + 0.5, r.y + 0.5));
    r.tolerance = receiver.tolerance;
    r.lightDistance = s.light.distance(P);
    return r;
}

double IlluminanceBuffer::localIlluminance(const PlacedReceiver& r, const LayerMaps& maps, const IlluminanceSettings& s) const {
    // MapReceiver::litBy, with the receiver's depth at the texel centre found once.
    const float stored = maps.hard.at(r.x, r.y);
    double local = stored >= 1.0f || r.depthAtCentre <= double(stored) + r.tolerance ? 1.0 : 0.0;
    // All maps of the frame share one view, so the texel is the same in each.
    const size_t texel = size_t(r.y) * size_t(maps.hard.size) + size_t(r.x);
    const double Lr = r.lightDistance;
    auto adjustment = [&](const PenumbraMap& map) {
        if (!map.covered(texel)) return 0.0;
        const double Lb = lightDistanceOfDepth(s.view, map.depth[texel]);
        if (!(Lb < Lr)) return 0.0;   // the fin lies behind the receiver
        return fallOff(refinedWeight(map.weight[texel], s.edgeWeight, Lb, Lr, s.referenceDistance), s.falloff);
    };
    if (maps.inner) local += adjustment(*maps.inner);
    local -= adjustment(maps.outer);
    return std::clamp(local, 0.0, 1.0);
}

void IlluminanceBuffer::combineLayer(const LayerMaps& maps, const IlluminanceSettings& settings, bool moreLayersFollow) {
    const bool placedBefore = !placed_.empty(), keep = !placedBefore && moreLayersFollow;
    if (keep) placed_.resize(values_.size());
    tbb::parallel_for(0, gbuffer_.height, [&](int j) {
        for (int i = 0; i < gbuffer_.width; ++i) {
            const size_t k = gbuffer_.index(i, j);
            if (values_[k] == 0.0f) continue;   // no light left to take away
            const PlacedReceiver r = placedBefore ? placed_[k] : place(k, maps.hard, settings);
            if (keep) placed_[k] = r;
            values_[k] = std::min(values_[k], float(localIlluminance(r, maps, settings)));
        }
    });
}

}  // namespace shadowlab
