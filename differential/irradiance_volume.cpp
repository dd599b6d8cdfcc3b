#include "differential/irradiance_volume.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "differential/patch_radiance.h"
#include "scenes/float_range.h"

namespace shadowlab {
namespace {

glm::dvec3 probePosition(const IrradianceVolume& v, const glm::ivec3& p) {
    glm::dvec3 t(0.0);
    for (int a = 0; a < 3; ++a) t[a] = v.probes[a] > 1 ? double(p[a]) / double(v.probes[a] - 1) : 0.5;
    return v.bounds.min + t * (v.bounds.max - v.bounds.min);
}

// The incident radiance at x projected onto the basis: each stratum of each patch a point
// sample of solid angle A cos / r^2, seen or not by a ray (patch_light.h's strata, jitter
// and streams).
ShCoefficients incidentRadiance(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                                std::span<const uint32_t> radiant, const ReferenceVisibility& modelRays,
                                const glm::dvec3& x, const PatchSampling& sampling, uint64_t probe) {
    ShCoefficients L;
    for (const uint32_t j : radiant) {
        const Patch& patch = model.patches[j];
        // A point sample stands for its stratum's solid angle only if the stratum is small
        // against its distance: a patch near the probe (the floor under it) is cut finer,
        // into strata at most half as wide as the patch's centre is far, up to 16 per side.
        const std::array<glm::dvec3, 4> c = model.corners(j);
        const double width = std::max(glm::length(c[2] - c[0]), glm::length(c[3] - c[1]));
        const double distance = std::max(glm::length(model.centre(j) - x), 1e-9);
        const int n = std::max(sampling.samplesPerAxis(patch), int(std::min(std::ceil(2.0 * width / distance), 16.0)));
        const double stratumArea = patch.area / double(n * n);
        Pcg32 rng = strataRandom(sampling, probe, j, model.patches.size());
        for (int b = 0; b < n; ++b) {
            for (int a = 0; a < n; ++a) {
                const glm::dvec2 u = jitteredSample(a, b, n, rng);
                const glm::dvec3 d = model.pointAt(j, u.x, u.y) - x;
                const double r2 = glm::dot(d, d), r = std::sqrt(r2);
                const double cosine = -glm::dot(patch.normal, d) / r;
                if (!(cosine > 0.0)) continue;
                const glm::dvec3 w = d / r;
                if (!modelRays.pointVisible(glm::vec3(x), glm::vec3(w), x + d)) continue;
                const std::array<double, kShCoefficients> Y = shBasis(w);
                const glm::dvec3 sample = radiance[j] * (stratumArea * cosine / r2);
                for (int k = 0; k < kShCoefficients; ++k) L.c[size_t(k)] += Y[size_t(k)] * sample;
            }
        }
    }
    return L;
}

}  // namespace

glm::dvec3 IrradianceVolume::at(const glm::dvec3& x, const glm::dvec3& n) const {
    glm::ivec3 base(0);
    glm::dvec3 f(0.0);
    for (int a = 0; a < 3; ++a) {
        if (probes[a] < 2) continue;
        const double extent = bounds.max[a] - bounds.min[a];
        const double t = std::clamp((x[a] - bounds.min[a]) / extent, 0.0, 1.0) * double(probes[a] - 1);
        base[a] = std::min(int(t), probes[a] - 2);
        f[a] = t - double(base[a]);
    }
    glm::dvec3 sum(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        glm::ivec3 p = base;
        double w = 1.0;
        for (int a = 0; a < 3; ++a) {
            const int step = (corner >> a) & 1;
            if (probes[a] < 2) {
                if (step) w = 0.0;
                continue;
            }
            p[a] += step;
            w *= step ? f[a] : 1.0 - f[a];
        }
        if (w == 0.0) continue;
        sum += w * evaluateSh(irradiance[size_t((p.z * probes.y + p.y) * probes.x + p.x)], n);
    }
    // E / pi, as gatheredRadiance sums B F; order 2 can ring below 0 away from the light.
    return glm::max(sum / std::numbers::pi, glm::dvec3(0.0));
}

IrradianceVolume buildIrradianceVolume(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                                       const ReferenceVisibility& modelRays, const Aabb& bounds, double spacing,
                                       const PatchSampling& sampling) {
    if (!(spacing > 0.0) || !std::isfinite(spacing))
        throw std::invalid_argument("irradiance volume: the spacing must be positive and finite");
    if (!allFinite(bounds.min) || !allFinite(bounds.max)) {
        throw std::invalid_argument("irradiance volume: the box is not finite");
    }
    IrradianceVolume v;
    // Probes at the centres of the cells of a grid over the box, none on its faces: the
    // floor under an object is on its box's face, and a probe there would lose every ray
    // that grazes it. Points beyond the centres take the outer probes' light.
    double total = 1.0;
    v.bounds = bounds;
    for (int a = 0; a < 3; ++a) {
        const double extent = bounds.max[a] - bounds.min[a];
        const double cells = extent > 0.0 ? std::clamp(std::ceil(extent / spacing), 1.0, 1e6) : 1.0;
        v.probes[a] = int(cells);
        v.bounds.min[a] += 0.5 * extent / cells, v.bounds.max[a] -= 0.5 * extent / cells;
        total *= cells;
    }
    if (total > 1e6) throw std::invalid_argument("irradiance volume: over 10^6 probes; use a larger spacing");
    v.irradiance.resize(size_t(total));
    const std::vector<uint32_t> radiant = radiantPatches(model, radiance);
    tbb::parallel_for(size_t(0), v.irradiance.size(), [&](size_t k) {
        const int x = int(k % size_t(v.probes.x)), y = int(k / size_t(v.probes.x) % size_t(v.probes.y));
        const int z = int(k / (size_t(v.probes.x) * size_t(v.probes.y)));
        const glm::dvec3 position = probePosition(v, {x, y, z});
        v.irradiance[k] = irradianceOf(incidentRadiance(model, radiance, radiant, modelRays, position, sampling, k));
    });
    return v;
}

}  // namespace shadowlab
