#include "shading/environment/prefiltered_lobe.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"
#include "shading/microfacet_ggx.h"

namespace shadowlab {
namespace {

constexpr double kTolerance = 1e-3;   // the error budget of a texel, relative to the map (LobeIntegrator)
constexpr double kOutputTexelsPerWidth = 3.0;

struct PhongWeight {
    double shininess;
    double operator()(double c) const { return c > 0.0 ? portable::pow(c, shininess) : 0.0; }
};

// D(h) (r . l) with cos^2(theta_h) = (1 + c) / 2, h halfway between r and l.
struct GgxWeight {
    double alpha2;
    double operator()(double c) const { return c > 0.0 ? ggxDistributionFromCos2(0.5 * (1.0 + c), alpha2) * c : 0.0; }
};

struct WeightedSum {
    glm::dvec3 radiance{0.0};
    double weight = 0.0;
};

// The cosines from r of the nearest and farthest points within angle s of a point at cosine
// c from r: cos(d - s) and cos(d + s), clamped at 0 and pi.
void cosineRange(double c, double cosExtent, double sinExtent, double& nearest, double& farthest) {
    const double sinD = std::sqrt(std::max(0.0, 1.0 - c * c));
    nearest = c >= cosExtent ? 1.0 : c * cosExtent + sinD * sinExtent;
    farthest = c <= -cosExtent ? -1.0 : c * cosExtent - sinD * sinExtent;
}

// The sum of w(r . l) L dOmega over a tiling of the sphere by pyramid texels, for one r. A
// texel is split while the midpoint rule could be off on it by enough to matter: w is
// monotone in the angle from r, so |w(nearest) + w(farthest) - 2 w(centre)| estimates its
// curvature across the texel, and the texel is split while that times its solid angle and
// its brightness exceeds kTolerance times the lobe's integral and the map's mean luminance
// (an error budget relative to the map: a sun far in the tail is refined as far as it can
// move P). The brightness is the brightest map texel's luminance but never below the mean,
// so the weights are resolved in dark regions too and their sum, the normaliser, is right.
template <class Weight>
struct LobeIntegrator {
    const EnvironmentPyramid& pyramid;
    const Weight& weight;
    double meanLuminance, threshold;   // threshold: kTolerance * integral of w * mean luminance

    // wCentre: weight(c), which the caller needs for the texel anyway.
    bool split(double c, double wCentre, double cosExtent, double sinExtent, double solidAngle, double brightest) const {
        double nearest, farthest;
        cosineRange(c, cosExtent, sinExtent, nearest, farthest);
        const double curvature = std::abs(weight(nearest) + weight(farthest) - 2.0 * wCentre);
        return curvature * solidAngle * std::max(brightest, meanLuminance) > threshold;
    }

    void accumulate(size_t level, int i, int j, const glm::dvec3& r, WeightedSum& sum) const {
        const PyramidLevel& texels = pyramid.levels[level];
        const size_t k = texels.index(i, j);
        const double c = r.x * texels.x[k] + r.y * texels.y[k] + r.z * texels.z[k];
        const double wCentre = weight(c);
        if (level > 0 && split(c, wCentre, texels.cosExtent[k], texels.sinExtent[k], texels.solidAngle[k], texels.brightest[k])) {
            const PyramidLevel& children = pyramid.levels[level - 1];
            for (int cj = 2 * j; cj < std::min(2 * j + 2, children.height); ++cj) {
                for (int ci = 2 * i; ci < std::min(2 * i + 2, children.width); ++ci) accumulate(level - 1, ci, cj, r, sum);
            }
            return;
        }
        const double w = wCentre * texels.solidAngle[k];
        sum.radiance += w * texels.radiance[k];
        sum.weight += w;
    }
};

// integral of w over the sphere, 2 pi integral_0^pi w(cos d) sin d dd, by the midpoint rule
// (only the error budget uses it).
template <class Weight>
double lobeIntegral(const Weight& weight) {
    constexpr int kSteps = 1 << 14;
    double sum = 0.0;
    for (int k = 0; k < kSteps; ++k) {
        const double d = kPi * (k + 0.5) / kSteps;
        sum += weight(portable::cos(d)) * portable::sin(d);
    }
    return 2.0 * kPi * sum * kPi / kSteps;
}

template <class Weight>
EnvironmentMap prefilterWith(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, double sigma,
                             const Weight& weight) {
    EnvironmentMap out;
    out.height = std::clamp(int(std::ceil(kOutputTexelsPerWidth * kPi / sigma)), 8, std::max(map.height, 8));
    out.width = std::min(2 * out.height, std::max(map.width, 16));
    out.rotationRadians = map.rotationRadians;
    out.source = map.source;
    out.radiance.resize(size_t(out.width) * size_t(out.height));
    const double meanLuminance = luminance(environmentPower(map)) / (4.0 * kPi);
    if (meanLuminance == 0.0) return out;   // a black map: P is 0 everywhere
    const LobeIntegrator<Weight> integrator{pyramid, weight, meanLuminance, kTolerance * lobeIntegral(weight) * meanLuminance};
    const PyramidLevel& top = pyramid.levels.back();
    tbb::parallel_for(0, out.height, [&](int j) {
        for (int i = 0; i < out.width; ++i) {
            const glm::dvec3 r = out.direction((i + 0.5) / out.width, (j + 0.5) / out.height);
            WeightedSum sum;
            for (int tj = 0; tj < top.height; ++tj) {
                for (int ti = 0; ti < top.width; ++ti) integrator.accumulate(pyramid.levels.size() - 1, ti, tj, r, sum);
            }
            out.radiance[size_t(j) * size_t(out.width) + size_t(i)] = glm::vec3(sum.radiance / sum.weight);
        }
    });
    return out;
}

const char* lobeName(GlossyLobe lobe) { return lobe == GlossyLobe::NormalisedPhong ? "Phong shininess" : "GGX roughness"; }

// The narrowest lobe the map's texels resolve: four texel heights.
double narrowestLobe(const EnvironmentMap& map) { return 4.0 * kPi / map.height; }

}  // namespace

double lobeWidth(GlossyLobe lobe, double parameter) {
    return lobe == GlossyLobe::NormalisedPhong ? 1.0 / std::sqrt(parameter) : parameter;
}

void checkLobe(GlossyLobe lobe, double parameter, const EnvironmentMap& map) {
    const bool inRange = lobe == GlossyLobe::NormalisedPhong ? parameter >= 1.0 && std::isfinite(parameter)
                                                              : parameter > 0.0 && parameter <= 1.0;
    if (!inRange) {
        throw std::invalid_argument(std::string(lobeName(lobe)) + " must be " +
                                    (lobe == GlossyLobe::NormalisedPhong ? "at least 1" : "in (0, 1]") + ", not " +
                                    std::to_string(parameter));
    }
    const double narrowest = narrowestLobe(map);
    if (lobeWidth(lobe, parameter) < narrowest) {
        throw std::invalid_argument(std::string(lobeName(lobe)) + " " + std::to_string(parameter) +
                                    " gives a lobe narrower than four texels of the " + std::to_string(map.width) +
                                    " x " + std::to_string(map.height) + " map " + map.source +
                                    " (its width must be at least 4 pi / " + std::to_string(map.height) + " radians)");
    }
}

EnvironmentMap prefilterLobe(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, GlossyLobe lobe,
                             double parameter) {
    checkLobe(lobe, parameter, map);
    const double sigma = lobeWidth(lobe, parameter);
    if (lobe == GlossyLobe::NormalisedPhong) return prefilterWith(map, pyramid, sigma, PhongWeight{parameter});
    return prefilterWith(map, pyramid, sigma, GgxWeight{parameter * parameter});
}

glm::dvec3 samplePrefiltered(const EnvironmentMap& prefiltered, const glm::dvec3& direction) {
    const glm::dvec2 uv = prefiltered.coordinates(direction);
    const double x = uv.x * prefiltered.width - 0.5, y = uv.y * prefiltered.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y), tx = x - x0, ty = y - y0;
    const int i0 = (int(x0) + prefiltered.width) % prefiltered.width, i1 = (i0 + 1) % prefiltered.width;
    const int j0 = std::max(int(y0), 0), j1 = std::min(int(y0) + 1, prefiltered.height - 1);
    const auto at = [&](int i, int j) { return glm::dvec3(prefiltered.at(i, j)); };
    return (1.0 - ty) * ((1.0 - tx) * at(i0, j0) + tx * at(i1, j0)) + ty * ((1.0 - tx) * at(i0, j1) + tx * at(i1, j1));
}

std::vector<double> defaultLobeLadder(GlossyLobe lobe, const EnvironmentMap& map) {
    const double narrowest = narrowestLobe(map);
    std::vector<double> ladder;
    if (lobe == GlossyLobe::NormalisedPhong) {
        for (double n = 1.0; lobeWidth(lobe, n) >= narrowest; n *= 2.0) ladder.push_back(n);
    } else {
        for (int k = 0; lobeWidth(lobe, portable::exp2(-0.5 * k)) >= narrowest; ++k) ladder.insert(ladder.begin(), portable::exp2(-0.5 * k));
    }
    return ladder;
}

PrefilteredLobes prefilterLobes(const EnvironmentMap& map, GlossyLobe lobe, std::vector<double> parameters) {
    for (double parameter : parameters) checkLobe(lobe, parameter, map);
    std::sort(parameters.begin(), parameters.end());
    parameters.erase(std::unique(parameters.begin(), parameters.end()), parameters.end());
    if (parameters.empty()) throw std::invalid_argument(std::string("a prefiltered table needs at least one ") + lobeName(lobe));
    PrefilteredLobes table;
    table.lobe = lobe;
    table.parameters = parameters;
    const EnvironmentPyramid pyramid = buildPyramid(map);
    for (double parameter : parameters) table.maps.push_back(prefilterLobe(map, pyramid, lobe, parameter));
    return table;
}

glm::dvec3 lookupPrefiltered(const PrefilteredLobes& table, double parameter, const glm::dvec3& direction) {
    const std::vector<double>& p = table.parameters;
    const size_t upper = size_t(std::lower_bound(p.begin(), p.end(), parameter) - p.begin());
    if (upper == p.size()) return samplePrefiltered(table.maps.back(), direction);
    if (upper == 0 || p[upper] == parameter) return samplePrefiltered(table.maps[upper], direction);
    const double t = (portable::log(parameter) - portable::log(p[upper - 1])) / (portable::log(p[upper]) - portable::log(p[upper - 1]));
    return (1.0 - t) * samplePrefiltered(table.maps[upper - 1], direction) + t * samplePrefiltered(table.maps[upper], direction);
}

}  // namespace shadowlab
