#include "shadows/deep/transmittance_curve.h"

#include <algorithm>

#include "raster/portable_math.h"

namespace shadowlab {

void ExactCurves::build(const VolumetricLayers& layers, size_t texel, std::vector<CurveVertex>& out) {
    out.clear();
    std::vector<Breakpoint>& points = points_;
    points.clear();
    for (uint32_t e = layers.start[texel]; e < layers.start[texel + 1]; ++e) {
        const float near = layers.depthNear[e], far = layers.depthFar[e];
        const double tau = layers.opticalDepth[e];
        if (far > near) {
            const double slope = tau / (double(far) - double(near));
            points.push_back({near, 0.0, slope}), points.push_back({far, 0.0, -slope});
        } else {
            points.push_back({near, tau, 0.0});
        }
    }
    std::stable_sort(points.begin(), points.end(),
                     [](const Breakpoint& a, const Breakpoint& b) { return a.depth < b.depth; });
    double tau = 0.0, slope = 0.0;
    float at = points.empty() ? 0.0f : points.front().depth;
    const auto emit = [&](float depth) {
        const float value = float(portable::exp(-tau));
        if (!out.empty() && out.back().depth == depth && out.back().transmittance == value) return;
        out.push_back({depth, value});
    };
    for (size_t k = 0; k < points.size();) {
        const float depth = points[k].depth;
        tau += slope * (double(depth) - double(at));
        at = depth;
        emit(depth);   // the value arriving at this depth
        for (; k < points.size() && points[k].depth == depth; ++k) {
            tau += points[k].jump, slope += points[k].slopeChange;
        }
        emit(depth);   // and leaving it
    }
}

double opticalDepthBefore(const VolumetricLayers& layers, size_t texel, double z) {
    double tau = 0.0;
    for (uint32_t e = layers.start[texel]; e < layers.start[texel + 1]; ++e) {
        const double near = layers.depthNear[e], far = layers.depthFar[e];
        if (near >= z) break;   // the events are nearest first
        const double share = far <= z || far == near ? 1.0 : (z - near) / (far - near);
        tau += double(layers.opticalDepth[e]) * share;
    }
    return tau;
}

float transmittanceAt(std::span<const CurveVertex> curve, float z) {
    // The first vertex at or behind z; the value in front of it is what reaches z.
    const auto behind = std::lower_bound(curve.begin(), curve.end(), z,
                                         [](const CurveVertex& v, float depth) { return v.depth < depth; });
    if (behind == curve.begin()) return 1.0f;
    if (behind == curve.end()) return curve.back().transmittance;
    const CurveVertex& a = *(behind - 1);
    const CurveVertex& b = *behind;
    const float t = (z - a.depth) / (b.depth - a.depth);
    return a.transmittance + t * (b.transmittance - a.transmittance);
}

}  // namespace shadowlab
