#include "shading/environment/radiance_cache.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "shading/shade.h"

namespace shadowlab {
namespace {

constexpr double kLobeTolerance = 1e-3;

// Where a pyramid texel lies in the map: texels [first, last) (each level halves indices).
struct Extent {
    glm::ivec2 first, last;
};

Extent extentOf(const EnvironmentMap& map, size_t level, int i, int j) {
    return {{i << level, j << level}, {std::min((i + 1) << level, map.width), std::min((j + 1) << level, map.height)}};
}

struct Reflection {
    const EnvironmentMap& map;
    const EnvironmentPyramid& pyramid;
    const Material& material;
    glm::dvec3 N, v;
    double meanLuminance;
    double threshold = 0.0;   // kLobeTolerance * integral of the weight's luminance * mean luminance

    glm::dvec3 weight(const glm::dvec3& l) const {
        const double cosine = glm::dot(N, l);
        return cosine > 0.0 ? glm::dvec3(brdf(material, material.albedo, glm::vec3(N), glm::vec3(l), glm::vec3(v))) * cosine : glm::dvec3(0.0);
    }

    bool split(size_t level, int i, int j, double wCentre, double solidAngle, double brightest) const {
        const Extent e = extentOf(map, level, i, j);
        double spread = 0.0;
        for (const glm::ivec2 corner : {e.first, glm::ivec2(e.last.x, e.first.y), glm::ivec2(e.first.x, e.last.y), e.last})
            spread = std::max(spread, std::abs(luminance(weight(map.direction(double(corner.x) / map.width,
                                                                                    double(corner.y) / map.height))) -
                                                wCentre));
        return spread * solidAngle * std::max(brightest, meanLuminance) > threshold;
    }

    void accumulate(size_t level, int i, int j, glm::dvec3& sum) const {
        const PyramidLevel& texels = pyramid.levels[level];
        const size_t k = texels.index(i, j);
        const glm::dvec3 w = weight({texels.x[k], texels.y[k], texels.z[k]});
        if (level > 0 && split(level, i, j, luminance(w), texels.solidAngle[k], texels.brightest[k])) {
            const PyramidLevel& children = pyramid.levels[level - 1];
            for (int cj = 2 * j; cj < std::min(2 * j + 2, children.height); ++cj) {
                for (int ci = 2 * i; ci < std::min(2 * i + 2, children.width); ++ci) accumulate(level - 1, ci, cj, sum);
            }
            return;
        }
        sum += w * texels.radiance[k] * texels.solidAngle[k];
    }

    glm::dvec3 integral() {
        const PyramidLevel& top = pyramid.levels.back();
        // The error budget from the weight's integral, by the top level's midpoint rule.
        double albedo = 0.0;
        for (size_t k = 0; k < top.solidAngle.size(); ++k) albedo += luminance(weight({top.x[k], top.y[k], top.z[k]})) * top.solidAngle[k];
        threshold = kLobeTolerance * albedo * meanLuminance;
        glm::dvec3 sum(0.0);
        for (int tj = 0; tj < top.height; ++tj) {
            for (int ti = 0; ti < top.width; ++ti) accumulate(pyramid.levels.size() - 1, ti, tj, sum);
        }
        return sum;
    }
};

}  // namespace

glm::dvec2 octahedralEncode(const glm::dvec3& n) {
    const double l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    glm::dvec2 p(n.x / l1, n.z / l1);
    if (n.y < 0.0) {   // the lower hemisphere folded over the diagonals
        p = glm::dvec2((1.0 - std::abs(p.y)) * (p.x >= 0.0 ? 1.0 : -1.0), (1.0 - std::abs(p.x)) * (p.y >= 0.0 ? 1.0 : -1.0));
    }
    return 0.5 * p + 0.5;
}

glm::dvec3 octahedralDecode(const glm::dvec2& uv) {
    const glm::dvec2 p = 2.0 * uv - 1.0;
    glm::dvec3 n(p.x, 1.0 - std::abs(p.x) - std::abs(p.y), p.y);
    if (n.y < 0.0) {
        n.x = (1.0 - std::abs(p.y)) * (p.x >= 0.0 ? 1.0 : -1.0);
        n.z = (1.0 - std::abs(p.x)) * (p.y >= 0.0 ? 1.0 : -1.0);
    }
    return glm::normalize(n);
}

RadianceCache buildRadianceCache(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, const Material& material,
                                 const glm::dvec3& toViewer, int size) {
    if (size < 2 || size > 1024) throw std::invalid_argument("radiance cache: size must be in 2..1024");
    RadianceCache cache;
    cache.size = size;
    cache.radiance.assign(size_t(size) * size_t(size), glm::vec3(0.0f));
    const double meanLuminance = luminance(environmentPower(map)) / (4.0 * std::numbers::pi);
    if (meanLuminance == 0.0) return cache;   // a black map reflects nothing
    tbb::parallel_for(0, size, [&](int j) {
        for (int i = 0; i < size; ++i) {
            const glm::dvec3 N = octahedralDecode({(i + 0.5) / size, (j + 0.5) / size});
            Reflection reflection{map, pyramid, material, N, toViewer, meanLuminance};
            cache.radiance[size_t(j) * size_t(size) + size_t(i)] = glm::vec3(reflection.integral());
        }
    });
    return cache;
}

glm::dvec3 lookupRadianceCache(const RadianceCache& cache, const glm::dvec3& N) {
    const glm::dvec2 uv = octahedralEncode(N) * double(cache.size) - 0.5;
    const glm::dvec2 base = glm::floor(uv), t = uv - base;
    const auto at = [&](int i, int j) {
        i = std::clamp(i, 0, cache.size - 1), j = std::clamp(j, 0, cache.size - 1);
        return glm::dvec3(cache.radiance[size_t(j) * size_t(cache.size) + size_t(i)]);
    };
    const int i0 = int(base.x), j0 = int(base.y);
    return (1.0 - t.y) * ((1.0 - t.x) * at(i0, j0) + t.x * at(i0 + 1, j0)) +
           t.y * ((1.0 - t.x) * at(i0, j0 + 1) + t.x * at(i0 + 1, j0 + 1));
}

}  // namespace shadowlab
