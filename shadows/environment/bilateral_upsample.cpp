#include "shadows/environment/bilateral_upsample.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

constexpr int kTaps = 4;   // per side

// The first of the kTaps sampled columns (or rows) whose centres are nearest the output
// pixel's centre. Both cameras share the vertical field of view, so the views are centred
// on each other and a pixel spans H_s / H sampled pixels on both axes: output pixel x of
// `size` has its centre at sampledSize / 2 + (x + 0.5 - size / 2) * scale in sampled pixels.
int firstTap(int x, int size, double scale, int sampledSize) {
    const double centre = 0.5 * sampledSize + (x + 0.5 - 0.5 * size) * scale;
    const int nearestBelow = int(std::floor(centre - 0.5));
    return std::clamp(nearestBelow - (kTaps / 2 - 1), 0, std::max(0, sampledSize - kTaps));
}

struct Filtered {
    glm::vec3 value{0.0f};
    enum { Weighted, Nearest, Empty } how = Weighted;
};

Filtered filterPixel(const GBuffer& full, size_t p, const GBuffer& sampled, const std::vector<glm::vec3>& S, int i0,
                     int j0, double sigma) {
    const glm::dvec3 P(full.position[p]), N(full.shadingNormal[p]);
    glm::dvec3 sum(0.0);
    double weights = 0.0, nearestDistance2 = std::numeric_limits<double>::infinity();
    size_t nearest = 0;
    for (int j = j0; j < std::min(j0 + kTaps, sampled.height); ++j) {
        for (int i = i0; i < std::min(i0 + kTaps, sampled.width); ++i) {
            const size_t q = sampled.index(i, j);
            if (!sampled.hit[q]) continue;
            const glm::dvec3 d = glm::dvec3(sampled.position[q]) - P;
            const double distance2 = glm::dot(d, d);
            if (distance2 < nearestDistance2) nearestDistance2 = distance2, nearest = q;
            const double agreement = std::max(0.0, glm::dot(N, glm::dvec3(sampled.shadingNormal[q])));
            const double w = portable::exp(-distance2 / (2.0 * sigma * sigma)) * agreement;
            sum += w * glm::dvec3(S[q]);
            weights += w;
        }
    }
    if (weights > 0.0) return {glm::vec3(sum / weights), Filtered::Weighted};
    if (nearestDistance2 < std::numeric_limits<double>::infinity()) return {S[nearest], Filtered::Nearest};
    return {glm::vec3(0.0f), Filtered::Empty};
}

}  // namespace

std::vector<glm::vec3> upsampleShadowBuffer(const GBuffer& full, const Camera& camera, const GBuffer& sampled,
                                            const std::vector<glm::vec3>& S, UpsampleCounts* counts) {
    if (S.size() != sampled.pixelCount()) throw std::invalid_argument("upsampleShadowBuffer: S is not the sampled size");
    if (sampled.width == full.width && sampled.height == full.height) return S;
    const double scale = double(sampled.height) / full.height;
    // One full-size pixel's footprint per metre of distance, times the pixels one sample spans.
    const double footprint = 2.0 * portable::tan(double(camera.fovyDeg) * std::numbers::pi / 360.0) / full.height;
    const double span = double(full.height) / sampled.height;
    const glm::dvec3 eye(camera.eye);
    std::vector<glm::vec3> out(full.pixelCount(), glm::vec3(0.0f));
    std::atomic<uint64_t> nearest{0}, empty{0};
    tbb::parallel_for(tbb::blocked_range<int>(0, full.height), [&](const tbb::blocked_range<int>& rows) {
        uint64_t rowsNearest = 0, rowsEmpty = 0;
        for (int j = rows.begin(); j != rows.end(); ++j) {
            const int j0 = firstTap(j, full.height, scale, sampled.height);
            for (int i = 0; i < full.width; ++i) {
                const size_t p = full.index(i, j);
                if (!full.hit[p]) continue;
                const double sigma = span * footprint * glm::length(glm::dvec3(full.position[p]) - eye);
                const Filtered f = filterPixel(full, p, sampled, S, firstTap(i, full.width, scale, sampled.width), j0, sigma);
                out[p] = f.value;
                rowsNearest += f.how == Filtered::Nearest;
                rowsEmpty += f.how == Filtered::Empty;
            }
        }
        nearest += rowsNearest, empty += rowsEmpty;
    });
    if (counts) *counts = {nearest.load(), empty.load()};
    return out;
}

}  // namespace shadowlab
