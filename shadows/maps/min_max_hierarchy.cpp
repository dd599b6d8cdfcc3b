#include "shadows/maps/min_max_hierarchy.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// Level 1 from the map's texels, each node the range of its (up to) 2 x 2 texels.
void reduceFromMap(const DepthMap& map, int size, float* least, float* greatest) {
    tbb::parallel_for(0, size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const int x1 = std::min(2 * x + 1, map.size - 1), y1 = std::min(2 * y + 1, map.size - 1);
            const float a = map.at(2 * x, 2 * y), b = map.at(x1, 2 * y), c = map.at(2 * x, y1), d = map.at(x1, y1);
            least[size_t(y) * size_t(size) + size_t(x)] = std::min(std::min(a, b), std::min(c, d));
            greatest[size_t(y) * size_t(size) + size_t(x)] = std::max(std::max(a, b), std::max(c, d));
        }
    });
}

// Level l + 1 from level l (`below`, belowSize nodes per side).
void reduceLevel(const float* below, int belowSize, float* out, int size, bool greatest) {
    tbb::parallel_for(0, size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const int x1 = std::min(2 * x + 1, belowSize - 1), y1 = std::min(2 * y + 1, belowSize - 1);
            const auto at = [&](int i, int j) { return below[size_t(j) * size_t(belowSize) + size_t(i)]; };
            const float a = at(2 * x, 2 * y), b = at(x1, 2 * y), c = at(2 * x, y1), d = at(x1, y1);
            out[size_t(y) * size_t(size) + size_t(x)] = greatest ? std::max(std::max(a, b), std::max(c, d))
                                                                 : std::min(std::min(a, b), std::min(c, d));
        }
    });
}

}  // namespace

int hierarchyLevelFor(int span, int levels) {
    int level = 1;
    while (level < levels && span >= (1 << level)) ++level;
    return level;
}

MinMaxHierarchy::MinMaxHierarchy(const DepthMap& map) : mapSize_(map.size) {
    if (map.size < 2) throw std::invalid_argument("min/max hierarchy: a map of at least 2 x 2 texels");
    size_t total = 0;
    for (int size = map.size; size > 1;) {
        size = (size + 1) / 2;
        sizes_.push_back(size), offsets_.push_back(int(total));
        total += size_t(size) * size_t(size);
    }
    if (levels() > kMaxHierarchyLevels) throw std::invalid_argument("min/max hierarchy: map too large");
    least_.resize(total), greatest_.resize(total);
    reduceFromMap(map, sizes_[0], least_.data(), greatest_.data());
    for (int l = 1; l < levels(); ++l) {
        const size_t from = size_t(offsets_[size_t(l - 1)]), to = size_t(offsets_[size_t(l)]);
        reduceLevel(least_.data() + from, sizes_[size_t(l - 1)], least_.data() + to, sizes_[size_t(l)], false);
        reduceLevel(greatest_.data() + from, sizes_[size_t(l - 1)], greatest_.data() + to, sizes_[size_t(l)], true);
    }
    kernel_.least = least_.data(), kernel_.greatest = greatest_.data(), kernel_.levels = levels();
    for (int l = 0; l < levels(); ++l) kernel_.size[l] = sizes_[size_t(l)], kernel_.offset[l] = offsets_[size_t(l)];
}

DepthRange MinMaxHierarchy::node(int level, int x, int y) const {
    const size_t k = size_t(offsets_[size_t(level - 1)]) + size_t(y) * size_t(sizeOf(level)) + size_t(x);
    return {least_[k], greatest_[k]};
}

DepthRange MinMaxHierarchy::over(int x0, int y0, int x1, int y1) const {
    const auto clamp = [&](int c) { return std::clamp(c, 0, mapSize_ - 1); };
    x0 = clamp(x0), y0 = clamp(y0), x1 = clamp(x1), y1 = clamp(y1);
    const int level = hierarchyLevelFor(std::max(x1 - x0, y1 - y0), levels());
    DepthRange r;
    for (int y : {y0 >> level, y1 >> level}) {
        for (int x : {x0 >> level, x1 >> level}) {
            const DepthRange n = node(level, x, y);
            r.least = std::min(r.least, n.least), r.greatest = std::max(r.greatest, n.greatest);
        }
    }
    return r;
}

std::vector<float> MinMaxHierarchy::leastImage(int level) const {
    const auto first = least_.begin() + offsets_[size_t(level - 1)];
    return {first, first + ptrdiff_t(sizeOf(level)) * sizeOf(level)};
}

std::vector<float> MinMaxHierarchy::greatestImage(int level) const {
    const auto first = greatest_.begin() + offsets_[size_t(level - 1)];
    return {first, first + ptrdiff_t(sizeOf(level)) * sizeOf(level)};
}

}  // namespace shadowlab
