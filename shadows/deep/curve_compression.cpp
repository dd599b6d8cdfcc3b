#include "shadows/deep/curve_compression.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

void compressCurve(std::span<const CurveVertex> exact, float tolerance, std::vector<CurveVertex>& out) {
    out.clear();
    if (exact.empty()) return;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    CurveVertex origin = exact[0];
    out.push_back(origin);
    double low = -kInfinity, high = kInfinity;   // slopes of lines from origin through every window so far
    size_t lastFit = 0;                          // the last input vertex the range holds
    bool open = false;                           // some vertex after the origin fits the range
    const auto close = [&]() {                   // the vertex on the middle line at lastFit's depth
        const double slope = 0.5 * (low + high);
        const float depth = exact[lastFit].depth;
        origin = {depth, float(double(origin.transmittance) + slope * (double(depth) - double(origin.depth)))};
        out.push_back(origin);
        low = -kInfinity, high = kInfinity, open = false;
    };
    for (size_t k = 1; k < exact.size();) {
        const double dz = double(exact[k].depth) - double(origin.depth);
        const double value = exact[k].transmittance;
        if (dz <= 0.0) {   // at the origin's depth: a step
            if (std::abs(value - double(origin.transmittance)) > tolerance) {
                origin = exact[k];
                out.push_back(origin);
                low = -kInfinity, high = kInfinity, open = false;
            }
            lastFit = k++;
            continue;
        }
        const double newLow = std::max(low, (value - tolerance - origin.transmittance) / dz);
        const double newHigh = std::min(high, (value + tolerance - origin.transmittance) / dz);
        if (newLow <= newHigh) {
            low = newLow, high = newHigh, lastFit = k++, open = true;
        } else {
            close();   // k is tried again from the new origin
        }
    }
    if (open) close();
}

float compressionError(std::span<const CurveVertex> exact, std::span<const CurveVertex> compressed) {
    float worst = 0.0f;
    for (size_t k = 0; k < exact.size(); ++k) {
        // A step's two vertices share a depth: compare the value in front with the front
        // one and the value behind with the back one.
        const bool behindStep = k > 0 && exact[k - 1].depth == exact[k].depth;
        const float z = exact[k].depth;
        float value = transmittanceAt(compressed, z);
        if (behindStep) {
            const float after = std::nextafter(z, 2.0f);
            value = transmittanceAt(compressed, after);
        }
        worst = std::max(worst, std::abs(value - exact[k].transmittance));
    }
    return worst;
}

}  // namespace shadowlab
