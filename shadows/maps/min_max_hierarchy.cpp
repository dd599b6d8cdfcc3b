#include "shadows/maps/min_max_hierarchy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

constexpr int kFirst = MinMaxHierarchy::kFirstLevel;
constexpr int kFirstWidth = 1 << kFirst;          // texels per side of a first-level node
constexpr double kInf = std::numeric_limits<double>::infinity();

float roundedDown(double v) {
    const float f = float(v);
    return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundedUp(double v) {
    const float f = float(v);
    return double(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// A node of empty texels only: +inf residuals both ways (any depth passes). A node holding
// a NaN proves nothing: -inf below, +inf above.
NodePlane emptyNode() { return {0.0f, 0.0f, 0.0f, float(kInf), float(kInf)}; }
NodePlane unknownNode() { return {0.0f, 0.0f, 0.0f, float(-kInf), float(kInf)}; }
bool allEmpty(const NodePlane& p) { return p.residualLow == float(kInf); }

// The plane of a first-level node from its solid texels z[y][x] (centres at x + 0.5 - 2
// from the node's centre): on each axis the mean slope between the first and last solid
// texel of every row (column) that has two, through the solid texels' centroid; empty
// texels and those beyond the map's border left out. The residuals bound every solid texel
// against the float plane; an empty texel makes the high residual +inf.
NodePlane firstLevelPlane(const float (&z)[kFirstWidth][kFirstWidth], int width, int height) {
    double sum = 0.0, sumX = 0.0, sumY = 0.0;
    int solid = 0;
    bool anyEmpty = false;
    const auto offset = [](int c) { return c + 0.5 - 0.5 * kFirstWidth; };
    const auto solidAt = [&](int x, int y) { return z[y][x] < 1.0f; };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (std::isnan(z[y][x])) return unknownNode();
            if (!solidAt(x, y)) anyEmpty = true;
            else sum += z[y][x], sumX += offset(x), sumY += offset(y), ++solid;
        }
    }
    if (solid == 0) return emptyNode();
    // The mean slope along one axis over the lines across it that hold two solid texels.
    const auto meanSlope = [&](bool alongX) {
        double slope = 0.0;
        int lines = 0;
        for (int line = 0; line < (alongX ? height : width); ++line) {
            int first = -1, last = -1;
            for (int c = 0; c < (alongX ? width : height); ++c) {
                if (!(alongX ? solidAt(c, line) : solidAt(line, c))) continue;
                if (first < 0) first = c;
                last = c;
            }
            if (last <= first) continue;
            const double zFirst = alongX ? z[line][first] : z[first][line];
            const double zLast = alongX ? z[line][last] : z[last][line];
            slope += (zLast - zFirst) / double(last - first), ++lines;
        }
        return lines ? slope / lines : 0.0;
    };
    NodePlane out{0.0f, float(meanSlope(true)), float(meanSlope(false)), 0.0f, 0.0f};
    out.depth = float(sum / solid - double(out.slopeX) * (sumX / solid) - double(out.slopeY) * (sumY / solid));
    double low = kInf, high = -kInf;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (!solidAt(x, y)) continue;
            const double fit = double(out.depth) + double(out.slopeX) * offset(x) + double(out.slopeY) * offset(y);
            const double e = double(z[y][x]) - fit;
            low = std::min(low, e), high = std::max(high, e);
        }
    }
    out.residualLow = roundedDown(low);
    out.residualHigh = anyEmpty ? float(kInf) : roundedUp(high);
    return out;
}

// A node's plane from its present children (index 2 row + column; `step` texels between
// neighbouring children's centres, childHalfWidth from a child's centre to its outermost
// texel centre): the mean of the solid children's slopes, and the mean of their centre
// depths moved to the node's centre along them. The residuals bound every texel: a child's
// own residual plus how far its plane departs from the node's over the child.
NodePlane combine(const NodePlane (&kids)[4], const bool (&present)[4], double step, double childHalfWidth) {
    double slopeX = 0.0, slopeY = 0.0;
    int solid = 0;
    bool anyEmpty = false;
    for (int k = 0; k < 4; ++k) {
        if (!present[k]) continue;
        anyEmpty = anyEmpty || !std::isfinite(kids[k].residualHigh);
        if (allEmpty(kids[k])) continue;
        slopeX += kids[k].slopeX, slopeY += kids[k].slopeY, ++solid;
    }
    if (solid == 0) return emptyNode();
    NodePlane out{0.0f, float(slopeX / solid), float(slopeY / solid), 0.0f, 0.0f};
    const auto offset = [&](int k, float slope, int axisBit) {   // along the plane, from the node's centre
        return slope * ((double((k >> axisBit) & 1) - 0.5) * step);
    };
    const auto solidKid = [&](int k) { return present[k] && !allEmpty(kids[k]); };
    double depth = 0.0;
    for (int k = 0; k < 4; ++k) {
        if (solidKid(k)) depth += kids[k].depth - offset(k, out.slopeX, 0) - offset(k, out.slopeY, 1);
    }
    out.depth = float(depth / solid);
    double low = kInf, high = -kInf;
    for (int k = 0; k < 4; ++k) {
        if (!solidKid(k)) continue;
        const NodePlane& c = kids[k];
        const double fit = double(out.depth) + offset(k, out.slopeX, 0) + offset(k, out.slopeY, 1);
        const double centre = double(c.depth) - fit;
        const double spread =
            (std::abs(double(c.slopeX) - out.slopeX) + std::abs(double(c.slopeY) - out.slopeY)) * childHalfWidth;
        low = std::min(low, centre - spread + c.residualLow);
        high = std::max(high, centre + spread + c.residualHigh);
    }
    out.residualLow = roundedDown(low);
    out.residualHigh = anyEmpty ? float(kInf) : roundedUp(high);
    return out;
}

}  // namespace

int hierarchyLevelFor(int span, int levels) {
    int level = MinMaxHierarchy::kFirstLevel;
    while (level < levels && span >= (1 << level)) ++level;
    return level;
}

int readingLevelFor(int span, int nodes, int levels) {
    if (span < nodes) return 0;
    int level = MinMaxHierarchy::kFirstLevel;
    while (level < levels && (span >> level) + 2 > nodes) ++level;   // (span >> l) + 2 nodes at most
    return level;
}

double planeLeastOver(const MapReceiver& r, int level, int x, int y) {
    const double width = double(1 << level), halfWidth = 0.5 * (width - 1.0);
    return r.depthAt({(x + 0.5) * width, (y + 0.5) * width}) -
           (std::abs(r.depthSlope.x) + std::abs(r.depthSlope.y)) * halfWidth;
}

MinMaxHierarchy::MinMaxHierarchy(const DepthMap& map) : mapSize_(map.size) {
    if (map.size < 2) throw std::invalid_argument("min/max hierarchy: a map of at least 2 x 2 texels");
    size_t total = 0;
    for (int size = (map.size + kFirstWidth - 1) / kFirstWidth;; size = (size + 1) / 2) {
        sizes_.push_back(size), offsets_.push_back(int(total));
        total += size_t(size) * size_t(size);
        if (size == 1) break;
    }
    if (levels() > kMaxHierarchyLevels) throw std::invalid_argument("min/max hierarchy: map too large");
    for (auto* v : {&least_, &greatest_, &planeDepth_, &slopeX_, &slopeY_, &residualLow_, &residualHigh_}) {
        v->resize(total);
    }
    buildFirstLevel(map);
    for (int level = kFirstLevel + 1; level <= levels(); ++level) buildLevel(level);
    kernel_ = {least_.data(),   greatest_.data(),    planeDepth_.data(), slopeX_.data(), slopeY_.data(),
               residualLow_.data(), residualHigh_.data(), kFirstLevel,  levels(),       {},  {}};
    for (int l = kFirstLevel; l <= levels(); ++l) {
        kernel_.size[l - kFirstLevel] = sizeOf(l), kernel_.offset[l - kFirstLevel] = offsets_[size_t(l - kFirstLevel)];
    }
}

// Each node's 4 x 4 texels, read once for its range and its plane.
void MinMaxHierarchy::buildFirstLevel(const DepthMap& map) {
    const int size = sizeOf(kFirstLevel);
    tbb::parallel_for(0, size, [&](int ny) {
        for (int nx = 0; nx < size; ++nx) {
            float z[kFirstWidth][kFirstWidth];
            const int width = std::min(kFirstWidth, map.size - nx * kFirstWidth);
            const int height = std::min(kFirstWidth, map.size - ny * kFirstWidth);
            float least = 1.0f, greatest = 0.0f;
            // A node's rows are runs of 4 texels inside one 8 x 8 block of the block-linear map.
            static_assert(raster::kBlockSize % kFirstWidth == 0);
            for (int y = 0; y < height; ++y) {
                const size_t first = raster::blockLinearIndex(nx * kFirstWidth, ny * kFirstWidth + y, map.tilesX);
                const float* row = &map.depth[first];
                for (int x = 0; x < width; ++x) {
                    z[y][x] = row[x];
                    // A NaN texel (no map of ours holds one) widens the range to everything.
                    least = std::isnan(z[y][x]) ? 0.0f : std::min(least, z[y][x]);
                    greatest = std::isnan(z[y][x]) ? 1.0f : std::max(greatest, z[y][x]);
                }
            }
            store(indexOf(kFirstLevel, nx, ny), {least, greatest}, firstLevelPlane(z, width, height));
        }
    });
}

void MinMaxHierarchy::buildLevel(int level) {
    const int size = sizeOf(level), below = sizeOf(level - 1);
    const double step = double(1 << (level - 1)), childHalfWidth = 0.5 * (step - 1.0);
    tbb::parallel_for(0, size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            NodePlane kids[4];
            bool present[4];
            float least = 1.0f, greatest = 0.0f;
            for (int k = 0; k < 4; ++k) {
                const int cx = 2 * x + k % 2, cy = 2 * y + k / 2;
                present[k] = cx < below && cy < below;
                if (!present[k]) continue;
                kids[k] = plane(level - 1, cx, cy);
                const DepthRange r = node(level - 1, cx, cy);
                least = std::min(least, r.least), greatest = std::max(greatest, r.greatest);
            }
            store(indexOf(level, x, y), {least, greatest}, combine(kids, present, step, childHalfWidth));
        }
    });
}

void MinMaxHierarchy::store(size_t n, const DepthRange& range, const NodePlane& p) {
    least_[n] = range.least, greatest_[n] = range.greatest;
    planeDepth_[n] = p.depth, slopeX_[n] = p.slopeX, slopeY_[n] = p.slopeY;
    residualLow_[n] = p.residualLow, residualHigh_[n] = p.residualHigh;
}

NodePlane MinMaxHierarchy::plane(int level, int x, int y) const {
    const size_t n = indexOf(level, x, y);
    return {planeDepth_[n], slopeX_[n], slopeY_[n], residualLow_[n], residualHigh_[n]};
}

DepthRange MinMaxHierarchy::node(int level, int x, int y) const {
    const size_t n = indexOf(level, x, y);
    return {least_[n], greatest_[n]};
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

bool MinMaxHierarchy::nodeProvedLit(const MapReceiver& r, int level, int x, int y) const {
    const NodePlane p = plane(level, x, y);
    const double width = double(1 << level), halfWidth = 0.5 * (width - 1.0);
    const glm::dvec2 centre((x + 0.5) * width, (y + 0.5) * width), d = centre - r.texel;
    const double g = double(p.depth) - r.depthAt(centre);
    const double spread = (std::abs(p.slopeX - r.depthSlope.x) + std::abs(p.slopeY - r.depthSlope.y)) * halfWidth;
    // litBy compares in double (u = 2^-53): a margin of 2^-40 times the terms' magnitudes
    // covers its roundings and these many times over.
    const double terms = 1.0 + std::abs(r.depth) + std::abs(double(p.depth)) +
                         (std::abs(r.depthSlope.x) + std::abs(p.slopeX)) * (std::abs(d.x) + halfWidth) +
                         (std::abs(r.depthSlope.y) + std::abs(p.slopeY)) * (std::abs(d.y) + halfWidth);
    return g - spread + double(p.residualLow) + r.tolerance >= 0x1p-40 * terms;
}

bool MinMaxHierarchy::nodeShadowed(const MapReceiver& r, int level, int x, int y) const {
    const float greatest = node(level, x, y).greatest;
    return greatest < 1.0f && double(greatest) + r.tolerance < planeLeastOver(r, level, x, y);
}

bool MinMaxHierarchy::provedLit(const MapReceiver& r, int x0, int y0, int x1, int y1) const {
    if (x0 < 0 || y0 < 0 || x1 >= mapSize_ || y1 >= mapSize_ || x1 < x0 || y1 < y0) return false;
    const int level = hierarchyLevelFor(std::max(x1 - x0, y1 - y0), levels());
    for (int y : {y0 >> level, y1 >> level}) {
        for (int x : {x0 >> level, x1 >> level}) {
            if (!nodeProvedLit(r, level, x, y)) return false;
        }
    }
    return true;
}

std::vector<float> MinMaxHierarchy::levelImage(const std::vector<float>& values, int level) const {
    const auto first = values.begin() + ptrdiff_t(indexOf(level, 0, 0));
    return {first, first + ptrdiff_t(sizeOf(level)) * sizeOf(level)};
}

}  // namespace shadowlab
