#include "shading/environment/median_cut.h"

#include <algorithm>
#include <cstddef>
#include <queue>
#include <stdexcept>
#include <utility>
#include <string>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab {
namespace {

struct Region {
    glm::ivec2 first, last;   // texels [first, last)
    double energy = 0.0;
};

// Energy (luminance times solid angle) per texel, row-major.
struct EnergyGrid {
    int width, height;
    std::vector<double> energy;

    explicit EnergyGrid(const EnvironmentMap& map) : width(map.width), height(map.height), energy(map.radiance.size()) {
        for (int j = 0; j < height; ++j) {
            const double solidAngle = map.texelSolidAngle(j);
            for (int i = 0; i < width; ++i) energy[size_t(j) * size_t(width) + size_t(i)] = luminance(glm::dvec3(map.at(i, j))) * solidAngle;
        }
    }
    double at(int i, int j) const { return energy[size_t(j) * size_t(width) + size_t(i)]; }
    double sum(const glm::ivec2& first, const glm::ivec2& last) const {
        double total = 0.0;
        for (int j = first.y; j < last.y; ++j)
            for (int i = first.x; i < last.x; ++i) total += at(i, j);
        return total;
    }
};

// Whether to cut across x (columns): the longer side on the sphere, if it has two texels.
bool cutsColumns(const Region& r, const EnergyGrid& g) {
    const glm::ivec2 size = r.last - r.first;
    if (size.x < 2 || size.y < 2) return size.x >= 2;
    const double middleTheta = kPi * 0.5 * (r.first.y + r.last.y) / g.height;
    const double width = size.x * (2.0 * kPi / g.width) * portable::sin(middleTheta), height = size.y * kPi / g.height;
    return width >= height;
}

// The two halves of a region: cut at the texel edge nearest to half the energy (at least one
// texel each side), or in the middle for a region of no energy.
std::pair<Region, Region> cut(const Region& r, const EnergyGrid& g) {
    const bool columns = cutsColumns(r, g);
    const int axis = columns ? 0 : 1, from = r.first[axis], to = r.last[axis];
    int edge = from + (to - from) / 2;
    if (r.energy > 0.0) {
        // The slice that crosses half goes to the side that leaves the halves closer.
        double before = 0.0;
        for (edge = from + 1; edge < to; ++edge) {
            glm::ivec2 sliceFirst = r.first, sliceLast = r.last;
            sliceFirst[axis] = edge - 1, sliceLast[axis] = edge;
            const double after = before + g.sum(sliceFirst, sliceLast);
            if (after >= 0.5 * r.energy) {
                if (0.5 * r.energy - before < after - 0.5 * r.energy && edge - 1 > from) --edge;
                break;
            }
            before = after;
        }
        edge = std::min(edge, to - 1);
    }
    Region a = r, b = r;
    a.last[axis] = edge, b.first[axis] = edge;
    a.energy = g.sum(a.first, a.last), b.energy = g.sum(b.first, b.last);
    return {a, b};
}

bool splittable(const Region& r) { return r.last.x - r.first.x >= 2 || r.last.y - r.first.y >= 2; }

EnvironmentLight lightOf(const Region& r, const EnvironmentMap& map, const EnergyGrid& g) {
    EnvironmentLight light;
    light.first = r.first, light.last = r.last;
    glm::dvec3 centroid(0.0);
    for (int j = r.first.y; j < r.last.y; ++j) {
        const double solidAngle = map.texelSolidAngle(j);
        light.solidAngle += solidAngle * double(r.last.x - r.first.x);
        for (int i = r.first.x; i < r.last.x; ++i) {
            light.power += glm::dvec3(map.at(i, j)) * solidAngle;
            centroid += g.at(i, j) * map.direction((i + 0.5) / map.width, (j + 0.5) / map.height);
        }
    }
    // Energy spread evenly around the sphere cancels to rounding noise: no direction there.
    const double length = glm::length(centroid);
    const glm::ivec2 middle = (r.first + r.last) / 2;
    light.direction = length > 1e-9 * r.energy && length > 0.0
                          ? centroid / length
                          : map.direction((middle.x + 0.5) / map.width, (middle.y + 0.5) / map.height);
    return light;
}

}  // namespace

std::vector<EnvironmentLight> medianCutLights(const EnvironmentMap& map, int count) {
    const size_t texels = map.radiance.size();
    if (count < 1 || size_t(count) > texels) {
        throw std::invalid_argument("median cut: " + std::to_string(count) + " lights from a map of " +
                                    std::to_string(texels) + " texels; 1 to the texel count are possible");
    }
    const EnergyGrid grid(map);
    std::vector<Region> regions = {{{0, 0}, {map.width, map.height}, grid.sum({0, 0}, {map.width, map.height})}};
    // Splittable regions by energy, ties to the earlier region: (energy, -index) in a max-heap.
    std::priority_queue<std::pair<double, ptrdiff_t>> next;
    const auto offer = [&](size_t k) {
        if (splittable(regions[k])) next.push({regions[k].energy, -ptrdiff_t(k)});
    };
    offer(0);
    while (int(regions.size()) < count) {
        const size_t brightest = size_t(-next.top().second);
        next.pop();
        const auto [a, b] = cut(regions[brightest], grid);
        regions[brightest] = a;
        regions.push_back(b);
        offer(brightest), offer(regions.size() - 1);
    }
    std::vector<EnvironmentLight> lights;
    for (const Region& r : regions) lights.push_back(lightOf(r, map, grid));
    return lights;
}

std::vector<uint32_t> medianCutRegions(const EnvironmentMap& map, const std::vector<EnvironmentLight>& lights) {
    std::vector<uint32_t> region(map.radiance.size(), 0);
    for (size_t l = 0; l < lights.size(); ++l) {
        for (int j = lights[l].first.y; j < lights[l].last.y; ++j) {
            for (int i = lights[l].first.x; i < lights[l].last.x; ++i) region[size_t(j) * size_t(map.width) + size_t(i)] = uint32_t(l);
        }
    }
    return region;
}

}  // namespace shadowlab
