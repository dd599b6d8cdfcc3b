#include "shading/environment/structured_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "shading/environment/environment_pyramid.h"

namespace shadowlab {
namespace {

constexpr int kMaxStrata = 8;

// The pyramid level the strata are built on: the finest no wider than 256 cells (so a lamp
// of a few texels still stands out of its cell), or finer while it has fewer than 8 cells a
// sample.
int cellLevel(const EnvironmentPyramid& pyramid, int count) {
    int l = 0;
    while (l + 1 < int(pyramid.levels.size()) && pyramid.levels[size_t(l)].width > 256) ++l;
    const auto cells = [&](int level) { return size_t(pyramid.levels[size_t(level)].width) * size_t(pyramid.levels[size_t(level)].height); };
    while (l > 0 && cells(l) < 8 * size_t(count)) --l;
    return l;
}

struct Cells {
    const PyramidLevel& level;
    std::vector<double> luminance;          // of the cell's mean radiance
    glm::dvec3 direction(size_t c) const { return {level.x[c], level.y[c], level.z[c]}; }
    size_t size() const { return luminance.size(); }
};

// Stratum of every cell: floor(Y / sigma), at most kMaxStrata - 1.
std::vector<int> strataOf(const Cells& cells) {
    double mean = 0.0, sphere = 0.0;
    for (size_t c = 0; c < cells.size(); ++c) mean += cells.luminance[c] * cells.level.solidAngle[c], sphere += cells.level.solidAngle[c];
    mean /= sphere;
    double variance = 0.0;
    for (size_t c = 0; c < cells.size(); ++c) {
        const double d = cells.luminance[c] - mean;
        variance += d * d * cells.level.solidAngle[c];
    }
    const double sigma = std::sqrt(variance / sphere);
    std::vector<int> stratum(cells.size(), 0);
    if (sigma > 0.0) {
        for (size_t c = 0; c < cells.size(); ++c) stratum[c] = int(std::min(double(kMaxStrata - 1), std::floor(cells.luminance[c] / sigma)));
    }
    return stratum;
}

// Samples per stratum, in proportion to Y_j dOmega_j^(1/4), summing to `count`.
std::vector<int> samplesPerStratum(const Cells& cells, const std::vector<int>& stratum, int count) {
    std::vector<double> energy(kMaxStrata, 0.0), area(kMaxStrata, 0.0), importance(kMaxStrata, 0.0);
    for (size_t c = 0; c < cells.size(); ++c) {
        energy[stratum[c]] += cells.luminance[c] * cells.level.solidAngle[c];
        area[stratum[c]] += cells.level.solidAngle[c];
    }
    std::vector<int> cellsIn(kMaxStrata, 0);
    for (int s : stratum) ++cellsIn[s];
    for (int j = 0; j < kMaxStrata; ++j) importance[j] = area[j] > 0.0 ? energy[j] / area[j] * std::sqrt(std::sqrt(area[j])) : 0.0;
    // A black map has no importance anywhere: spread the samples by area instead.
    const double total = std::accumulate(importance.begin(), importance.end(), 0.0);
    if (!(total > 0.0)) importance = area;
    const double sum = std::accumulate(importance.begin(), importance.end(), 0.0);
    std::vector<int> samples(kMaxStrata, 0);
    std::vector<std::pair<double, int>> remainders;
    int given = 0;
    for (int j = 0; j < kMaxStrata; ++j) {
        const double share = count * importance[j] / sum;
        samples[j] = std::min(cellsIn[j], int(std::floor(share)));
        given += samples[j];
        if (samples[j] < cellsIn[j]) remainders.push_back({-(share - samples[j]), j});   // largest first, ties to lower j
    }
    std::sort(remainders.begin(), remainders.end());
    // Hand out what rounding left, largest remainder first, as long as a stratum has cells left.
    for (size_t k = 0; given < count; k = (k + 1) % remainders.size()) {
        const int j = remainders[k].second;
        if (samples[j] < cellsIn[j]) ++samples[j], ++given;
    }
    return samples;
}

// Farthest-point placement (Hochbaum and Shmoys 1985), brightest stratum first.
std::vector<size_t> placeSamples(const Cells& cells, const std::vector<int>& stratum, const std::vector<int>& samples) {
    std::vector<double> nearestCos(cells.size(), -2.0);   // cosine to the nearest placed sample
    std::vector<bool> taken(cells.size(), false);
    std::vector<size_t> placed;
    const auto place = [&](size_t c) {
        placed.push_back(c);
        taken[c] = true;
        const glm::dvec3 d = cells.direction(c);
        for (size_t k = 0; k < cells.size(); ++k) nearestCos[k] = std::max(nearestCos[k], glm::dot(d, cells.direction(k)));
    };
    for (int j = kMaxStrata - 1; j >= 0; --j) {
        for (int n = 0; n < samples[j]; ++n) {
            // The first sample of all is the brightest cell; every later one the stratum's
            // cell farthest from all placed so far.
            size_t best = cells.size();
            double bestKey = std::numeric_limits<double>::infinity();
            for (size_t c = 0; c < cells.size(); ++c) {
                if (stratum[c] != j || taken[c]) continue;
                const double key = placed.empty() ? -cells.luminance[c] : nearestCos[c];
                if (key < bestKey) bestKey = key, best = c;
            }
            if (best == cells.size()) throw std::logic_error("structured sampling: a stratum ran out of cells");
            place(best);
        }
    }
    return placed;
}

}  // namespace

std::vector<EnvironmentLight> structuredLights(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, int count,
                                               std::vector<uint32_t>* regionOfTexel) {
    const size_t texels = map.radiance.size();
    if (count < 1 || size_t(count) > texels) {
        throw std::invalid_argument("structured importance sampling: " + std::to_string(count) + " lights from a map of " +
                                    std::to_string(texels) + " texels; 1 to the texel count are possible");
    }
    const int level = cellLevel(pyramid, count);
    Cells cells{pyramid.levels[size_t(level)], {}};
    for (const glm::dvec3& L : cells.level.radiance) cells.luminance.push_back(luminance(L));
    const std::vector<int> stratum = strataOf(cells);
    const std::vector<size_t> samples = placeSamples(cells, stratum, samplesPerStratum(cells, stratum, count));

    // Voronoi regions: each cell to its nearest sample (ties to the earlier sample).
    std::vector<EnvironmentLight> lights(samples.size());
    std::vector<uint32_t> regionOfCell(cells.size(), 0);
    for (size_t c = 0; c < cells.size(); ++c) {
        double best = -2.0;
        for (size_t s = 0; s < samples.size(); ++s) {
            const double cosine = glm::dot(cells.direction(c), cells.direction(samples[s]));
            if (cosine > best) best = cosine, regionOfCell[c] = uint32_t(s);
        }
        EnvironmentLight& light = lights[regionOfCell[c]];
        light.power += cells.level.radiance[c] * cells.level.solidAngle[c];
        light.solidAngle += cells.level.solidAngle[c];
    }
    for (size_t s = 0; s < samples.size(); ++s) {
        lights[s].direction = glm::normalize(cells.direction(samples[s]));
    }
    if (regionOfTexel) {
        // Each level halves the indices (a lone last texel where a count is odd), so map
        // texel (i, j) lies in cell (i >> level, j >> level).
        regionOfTexel->assign(texels, 0);
        for (int j = 0; j < map.height; ++j) {
            for (int i = 0; i < map.width; ++i)
                (*regionOfTexel)[size_t(j) * size_t(map.width) + size_t(i)] = regionOfCell[cells.level.index(i >> level, j >> level)];
        }
    }
    return lights;
}

}  // namespace shadowlab
