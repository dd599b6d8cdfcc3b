// FLIP's feature pipeline. The 2D detectors are separable: the edge filter's x component is
// g'(x) g(y) and its y component g(x) g'(y), the point filter's g''(x) g(y) and g(x) g''(y).
// One pass along the rows makes g, g' and g'' of each row; the pass down the columns combines
// them into the four components.
#include "shading/flip_features.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "raster/portable_math.h"

namespace shadowlab::flip {
namespace {

// Scales the positive taps to sum to 1 and the negative ones to -1.
void balance(Kernel& kernel) {
    double positive = 0.0, negative = 0.0;
    for (float w : kernel) (w > 0.0f ? positive : negative) += double(w);
    for (float& w : kernel) w = float(double(w) / (w > 0.0f ? positive : -negative));
}

struct Responses {
    Plane edgeMagnitude, pointMagnitude;
};

// |(g' * Y, g' * Y transposed)| and the same of g'' at every pixel.
Responses responses(const Plane& luminance, const FeatureKernels& kernels) {
    Plane gx, dx, ddx;
    convolveRows(luminance, kernels.gaussian, gx);
    convolveRows(luminance, kernels.edge, dx);
    convolveRows(luminance, kernels.point, ddx);
    Plane edgeX, edgeY, pointX, pointY;
    convolveColumns(dx, kernels.gaussian, edgeX);
    convolveColumns(gx, kernels.edge, edgeY);
    convolveColumns(ddx, kernels.gaussian, pointX);
    convolveColumns(gx, kernels.point, pointY);
    Responses r{Plane(luminance.width, luminance.height), Plane(luminance.width, luminance.height)};
    forEachPixel(luminance.width, luminance.height, [&](size_t p) {
        r.edgeMagnitude.values[p] = std::sqrt(edgeX.values[p] * edgeX.values[p] + edgeY.values[p] * edgeY.values[p]);
        r.pointMagnitude.values[p] = std::sqrt(pointX.values[p] * pointX.values[p] + pointY.values[p] * pointY.values[p]);
    });
    return r;
}

}  // namespace

FeatureKernels featureKernels(float pixelsPerDegree) {
    if (!(pixelsPerDegree > 0.0f)) throw std::invalid_argument("FLIP: pixels per degree must be positive");
    const double sigma = 0.5 * double(kFeatureWidthDegrees) * double(pixelsPerDegree);
    const int radius = int(std::ceil(3.0 * sigma));
    FeatureKernels k;
    double sum = 0.0;
    for (int x = -radius; x <= radius; ++x) {
        const double g = portable::exp(-double(x) * double(x) / (2.0 * sigma * sigma));
        sum += g;
        k.gaussian.push_back(float(g));
        k.edge.push_back(float(-double(x) * g));   // g' up to a positive factor
        k.point.push_back(float((double(x) * double(x) / (sigma * sigma) - 1.0) * g));   // g'' likewise
    }
    for (float& w : k.gaussian) w = float(double(w) / sum);
    balance(k.edge);
    balance(k.point);
    return k;
}

Plane featureDifference(const Plane& reference, const Plane& test, float pixelsPerDegree) {
    if (reference.width != test.width || reference.height != test.height)
        throw std::invalid_argument("FLIP: the reference and the test image differ in size");
    const FeatureKernels kernels = featureKernels(pixelsPerDegree);
    const Responses r = responses(reference, kernels), t = responses(test, kernels);
    Plane difference(reference.width, reference.height);
    forEachPixel(reference.width, reference.height, [&](size_t p) {
        const float edge = std::abs(r.edgeMagnitude.values[p] - t.edgeMagnitude.values[p]);
        const float point = std::abs(r.pointMagnitude.values[p] - t.pointMagnitude.values[p]);
        static_assert(kFeatureExponent == 0.5f, "q_f = 1/2: a square root");
        difference.values[p] = std::sqrt(std::max(edge, point) / std::sqrt(2.0f));
    });
    return difference;
}

}  // namespace shadowlab::flip
