#include "shadows/maps/cascades.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/portable_math.h"
#include "scenes/bounds.h"
#include "scenes/camera.h"
#include "shadows/maps/receiver_ranges.h"
#include "shadows/technique.h"

namespace shadowlab {
namespace {

glm::dvec3 viewAxis(const Camera& camera) {
    return glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
}

// The smallest sphere around the slice's eight corners, centred on the view axis: the
// corners at distance d lie r(d) = d sqrt(tan^2 + (aspect tan)^2) off the axis; the centre
// t balances the near and far corner distances, clamped to the slice.
Sphere sliceSphere(const Camera& camera, double d0, double d1) {
    const double tanY = portable::tan(0.5 * double(camera.fovyDeg) * std::numbers::pi / 180.0);
    const double aspect = double(camera.width) / camera.height;
    const double spread = tanY * std::sqrt(1.0 + aspect * aspect);
    const double r0 = d0 * spread, r1 = d1 * spread;
    const double t = std::clamp((d1 * d1 + r1 * r1 - d0 * d0 - r0 * r0) / (2.0 * (d1 - d0)), d0, d1);
    const double radius = std::max(portable::hypot(t - d0, r0), portable::hypot(d1 - t, r1));
    return {glm::dvec3(camera.eye) + t * viewAxis(camera), radius};
}

// The receivers of cascade k, as a G-buffer for fitLightView (hit and position only): its
// positions are copied once, and `hit` is refilled for each cascade.
void selectCascadeReceivers(const GBuffer& g, const Camera& camera, const std::vector<Cascade>& cascades, int k,
                            GBuffer& subset) {
    if (subset.position.empty()) {
        subset.width = g.width, subset.height = g.height;
        subset.hit.resize(g.pixelCount());
        subset.position = g.position;
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount(), 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t p = r.begin(); p != r.end(); ++p) {
            subset.hit[p] = g.hit[p] && cascadeOf(cascades, viewDepth(camera, glm::dvec3(g.position[p]))) == k;
        }
    });
}

// A sample bound rounded outwards to the ladder 2^(k/8), steps of about 9%: a small camera
// move then leaves the splits, the slices' spheres and so the texel size unchanged, and
// snapping keeps the texel grid in place with sample bounds too.
double boundOnLadder(double distance, bool up) {
    constexpr double kStepsPerOctave = 8.0;
    const double step = portable::log2(distance) * kStepsPerOctave;
    return portable::exp2((up ? std::ceil(step) : std::floor(step)) / kStepsPerOctave);
}

}  // namespace

std::vector<double> cascadeSplits(double n, double f, int count, SplitScheme scheme, double lambda) {
    const double weight = scheme == SplitScheme::Logarithmic ? 1.0 : scheme == SplitScheme::Uniform ? 0.0 : lambda;
    std::vector<double> d(count + 1);
    for (int i = 0; i <= count; ++i) {
        const double x = double(i) / count;
        d[i] = weight * n * portable::pow(f / n, x) + (1.0 - weight) * (n + (f - n) * x);
    }
    d.front() = n, d.back() = f;
    return d;
}

double viewDepth(const Camera& camera, const glm::dvec3& P) {
    return glm::dot(P - glm::dvec3(camera.eye), viewAxis(camera));
}

int cascadeOf(const std::vector<Cascade>& cascades, double depth) {
    for (size_t k = 0; k + 1 < cascades.size(); ++k) {
        if (depth < cascades[k].farDistance) return int(k);
    }
    return int(cascades.size()) - 1;
}

std::vector<Cascade> fitCascades(const Light& sun, const Camera& camera, const GBuffer& g, const WorldGeometry& world,
                                 const CascadeSettings& s, raster::SimdLevel simd) {
    if (sun.type != LightType::Directional) throw std::invalid_argument("csm: needs a directional light");
    double n = camera.zNear, f = camera.zFar;
    if (s.sampleBounds) {
        // The nearest and farthest receivers (none, or none in front: no receivers).
        const Range depth = receiverRanges<1>(g, [&](const glm::dvec3& p) { return glm::dvec1(viewDepth(camera, p)); })[0];
        n = depth.lo, f = depth.hi;
        if (!(f > 0.0)) throw std::invalid_argument("csm: no receivers (no pixel has hit = 1)");
        n = std::max(n, 1e-3 * f), f *= 1.0 + 1e-6;
        n = boundOnLadder(n, false), f = boundOnLadder(f, true);
    }
    const std::vector<double> d = cascadeSplits(n, f, s.count, s.scheme, s.lambda);
    std::vector<Cascade> cascades(s.count);
    for (int k = 0; k < s.count; ++k) cascades[k].nearDistance = d[k], cascades[k].farDistance = d[k + 1];

    // One light rotation for all cascades and all frames: fitLightView's, so its depths apply.
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(sun.direction));
    const glm::dmat4 lightFromWorld = glm::lookAtRH(glm::dvec3(0.0), -towardsLight, lookAtUp(towardsLight));
    LightFitOptions options;
    options.resolution = s.resolution, options.marginTexels = s.marginTexels, options.simd = simd;
    GBuffer receivers;
    for (int k = 0; k < s.count; ++k) {
        Cascade& c = cascades[k];
        selectCascadeReceivers(g, camera, cascades, k, receivers);
        c.hasReceivers = anySurface(receivers);
        if (!c.hasReceivers) continue;
        // Near and far along the light from the receivers and what lies in front of them.
        const LightView depthFit = fitLightView(sun, receivers, world, options);
        const Sphere sphere = sliceSphere(camera, c.nearDistance, c.farDistance);
        const double half = sphere.radius * s.resolution / (s.resolution - 2.0 * s.marginTexels);
        const double texel = 2.0 * half / s.resolution;
        glm::dvec2 centre(lightFromWorld * glm::dvec4(sphere.centre, 1.0));
        if (s.snap) centre = glm::round(centre / texel) * texel;
        c.view.orthographic = true;
        c.view.viewFromWorld = lightFromWorld;
        c.view.zNear = depthFit.zNear, c.view.zFar = depthFit.zFar;
        c.view.clipFromView = glm::orthoRH_NO(centre.x - half, centre.x + half, centre.y - half, centre.y + half,
                                              c.view.zNear, c.view.zFar);
    }
    return cascades;
}

}  // namespace shadowlab
