#include "shadows/maps/pcf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadowlab {
namespace {

// SplitMix64 (Steele et al. 2014): a bijective integer hash, the same on every platform.
uint64_t splitMix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

double unitInterval(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

int texelOf(double coordinate) { return int(std::floor(coordinate)); }

double nearest(const DepthMap& map, const MapReceiver& r, const glm::dvec2& at) {
    return r.litBy(map, texelOf(at.x), texelOf(at.y)) ? 1.0 : 0.0;
}

// The four texel centres around the receiver and its bilinear weights (section 7.5).
double bilinear(const DepthMap& map, const MapReceiver& r) {
    const glm::dvec2 base = r.texel - 0.5;
    const int x0 = texelOf(base.x), y0 = texelOf(base.y);
    const double fx = base.x - x0, fy = base.y - y0;
    const double top = (1.0 - fx) * r.litBy(map, x0, y0) + fx * r.litBy(map, x0 + 1, y0);
    const double bottom = (1.0 - fx) * r.litBy(map, x0, y0 + 1) + fx * r.litBy(map, x0 + 1, y0 + 1);
    return (1.0 - fy) * top + fy * bottom;
}

double grid(const DepthMap& map, const MapReceiver& r, int n) {
    const double first = -0.5 * (n - 1);
    int lit = 0;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) lit += r.litBy(map, texelOf(r.texel.x + first + a), texelOf(r.texel.y + first + b));
    }
    return double(lit) / double(n * n);
}

// Mitchell's best-candidate algorithm: each new tap is the candidate farthest from the
// taps so far, of `kCandidatesPerTap` times as many candidates as taps, drawn uniformly on
// the unit disk from a fixed hash sequence. It approximates a Poisson-disk distribution.
std::vector<glm::dvec2> bestCandidateDisk(int taps) {
    constexpr int kCandidatesPerTap = 16;
    std::vector<glm::dvec2> disk;
    uint64_t counter = 0;
    for (int t = 0; t < taps; ++t) {
        glm::dvec2 best(0.0);
        double bestDistance = -1.0;
        for (int c = 0; c < kCandidatesPerTap * (t + 1); ++c) {
            const double radius = std::sqrt(unitInterval(splitMix64(counter++)));
            const double angle = 2.0 * std::numbers::pi * unitInterval(splitMix64(counter++));
            const glm::dvec2 candidate(radius * std::cos(angle), radius * std::sin(angle));
            double distance = 4.0;
            for (const glm::dvec2& p : disk) distance = std::min(distance, glm::length(candidate - p));
            if (distance > bestDistance) bestDistance = distance, best = candidate;
        }
        disk.push_back(best);
    }
    return disk;
}

}  // namespace

PcfKernel makePcfKernel(const FilterSettings& settings) {
    PcfKernel kernel{settings, {}};
    if (settings.kind == FilterKind::Poisson) kernel.disk = bestCandidateDisk(settings.poissonTaps);
    return kernel;
}

double kernelRadiusTexels(const FilterSettings& s) {
    switch (s.kind) {
        case FilterKind::Nearest: return 0.5;
        case FilterKind::Bilinear: return 1.0;
        case FilterKind::Grid: return 0.5 * s.gridSize;
        case FilterKind::Poisson: return s.poissonRadiusTexels + 0.5;
    }
    return 0.0;
}

double poissonRotation(uint64_t pixel) { return 2.0 * std::numbers::pi * unitInterval(splitMix64(pixel)); }

double poissonVisibility(const DepthMap& map, const MapReceiver& r, const std::vector<glm::dvec2>& disk, uint64_t pixel,
                         const glm::dvec2& radiusTexels) {
    const double angle = poissonRotation(pixel);
    const glm::dvec2 rotation(std::cos(angle), std::sin(angle));
    double lit = 0.0;
    for (const glm::dvec2& d : disk) lit += nearest(map, r, r.texel + rotatedTap(d, rotation, radiusTexels));
    return lit / double(disk.size());
}

double filteredVisibility(const DepthMap& map, const MapReceiver& r, const PcfKernel& k, uint64_t pixel) {
    switch (k.settings.kind) {
        case FilterKind::Nearest: return nearest(map, r, r.texel);
        case FilterKind::Bilinear: return bilinear(map, r);
        case FilterKind::Grid: return grid(map, r, k.settings.gridSize);
        case FilterKind::Poisson: return poissonVisibility(map, r, k.disk, pixel, glm::dvec2(k.settings.poissonRadiusTexels));
    }
    return 0.0;
}

}  // namespace shadowlab
