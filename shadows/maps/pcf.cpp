#include "shadows/maps/pcf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "raster/portable_math.h"
#include "shading/pixel_sequence.h"

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
            const glm::dvec2 candidate(radius * portable::cos(angle), radius * portable::sin(angle));
            double distance = 4.0;
            for (const glm::dvec2& p : disk) distance = std::min(distance, glm::length(candidate - p));
            if (distance > bestDistance) bestDistance = distance, best = candidate;
        }
        disk.push_back(best);
    }
    return disk;
}

}  // namespace

PcfKernel makePcfKernel(const FilterSettings& settings, uint64_t frame) {
    PcfKernel kernel{settings, {}, frame};
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

double tapReachTexels(const FilterSettings& s) {
    switch (s.kind) {
        case FilterKind::Nearest: return 0.0;
        case FilterKind::Bilinear: return 0.5;
        case FilterKind::Grid: return 0.5 * (s.gridSize - 1);
        case FilterKind::Poisson: return s.poissonRadiusTexels * 1.0001;
    }
    return 0.0;
}

int poissonRotationIndex(uint64_t pixel) {
    static_assert(kPoissonRotations == 1 << 10);
    return int(splitMix64(pixel) >> 54);   // the hash's top 10 bits
}

double poissonRotationAngle(int index) { return 2.0 * std::numbers::pi * double(index) / double(kPoissonRotations); }

double poissonRotation(uint64_t pixel) { return poissonRotationAngle(poissonRotationIndex(pixel)); }

double frameGradientNoise(int i, int j, uint64_t frame) {
    const double shift = 5.588238 * double(frame % 64);
    return interleavedGradientNoise(i + 0.5 + shift, j + 0.5 + shift);
}

int poissonRotationIndex(RotationNoise noise, uint64_t frame, int i, int j, int width) {
    if (noise == RotationNoise::Hash) return poissonRotationIndex(uint64_t(j) * uint64_t(width) + uint64_t(i));
    const int index = int(frameGradientNoise(i, j, frame) * kPoissonRotations);
    return std::min(index, kPoissonRotations - 1);
}

glm::dvec2 poissonRotationCosSin(int index) {
    // Rounded to float as shadow_lookup.cpp's table holds them, so both turn a disk alike.
    const double angle = poissonRotationAngle(index);
    return {double(float(portable::cos(angle))), double(float(portable::sin(angle)))};
}

glm::dvec2 kernelRotation(const PcfKernel& kernel, size_t pixel, int width) {
    if (kernel.settings.kind != FilterKind::Poisson) return {1.0, 0.0};
    const int i = int(pixel % size_t(width)), j = int(pixel / size_t(width));
    return poissonRotationCosSin(poissonRotationIndex(kernel.settings.rotation, kernel.frame, i, j, width));
}

}  // namespace shadowlab
