#include "shadows/virtual/page_marking.h"

#include <algorithm>
#include <cstdint>

#include "scenes/camera.h"

namespace shadowlab::vsm {
namespace {

// What every pixel's choice needs from the camera and the clipmap.
struct LevelChoice {
    PixelFootprint footprint;
    const ClipmapSettings& clipmap;
    const std::vector<LevelWindow>& windows;
    const MarkingSettings& settings;
    std::vector<double> texelsPerM;   // per level: 1 / texelM, a power of two, so exact

    // The finest level whose texel is no larger than the pixel's (biased) footprint:
    // texel(l) = 2^(l+1) / resolution <= footprint, so l = floor(log2(footprint * resolution
    // / 2)), the binary exponent, exact.
    int matchingLevel(const glm::dvec3& P) const {
        const double scaled = footprint.at(P) * double(clipmap.resolution) / 2.0;
        // A pixel wider than the coarsest texel reads the coarsest level (more detail than
        // it needs); one finer than the finest, or at no depth, the finest.
        const int level = scaled > 0.0 ? binaryExponent(scaled) - 1 + settings.lodBias : clipmap.firstLevel;
        return std::clamp(level, clipmap.firstLevel, clipmap.lastLevel);
    }

    // The level from `level` up whose window holds the whole box the lookup reads.
    PixelLevel choose(const glm::dvec3& P, const LightFrame& frame) const {
        const glm::dvec3 local = frame.local(P);
        const int n = clipmap.pagesPerSide();
        for (int level = matchingLevel(P); level <= clipmap.lastLevel; ++level) {
            const double perM = texelsPerM[size_t(level - clipmap.firstLevel)];
            const glm::dvec2 texel(local.x * perM, -local.y * perM);   // texelOf's bits
            const PageBox box = pagesRead(texel, settings.reachTexels, clipmap.pageTexels);
            const LevelWindow& w = windows[size_t(level - clipmap.firstLevel)];
            if (w.holds(box.x0, box.y0, n) && w.holds(box.x1, box.y1, n))
                return {int8_t(level - clipmap.firstLevel), texel};
        }
        return {};
    }
};

// The pages a pixel's rays read (RayReach): at every level from its own to the one its
// highest sample reads whose window holds the box, and, where the last of those does not,
// at the coarser one the rays then read (heldRayLevel).
void markRays(BoxRequests& requests, const std::vector<LevelWindow>& windows, const ClipmapSettings& clipmap,
              const MarkingSettings& settings, int level, const glm::dvec3& local) {
    const double reach = rayBoxReach(settings);
    const int top = rayLevel(clipmap, level, -local.z - settings.rays.zNear, settings.rays);
    const auto mark = [&](int l) {
        if (windowHoldsBox(clipmap, windows[size_t(l - clipmap.firstLevel)], local, reach))
            requests.request(l, pagesRead(texelOf(clipmap, l, local), reach, clipmap.pageTexels));
    };
    for (int l = level; l <= top; ++l) mark(l);
    const int held = heldRayLevel(clipmap, windows, top, local, reach);
    if (held != top) mark(held);
}

}  // namespace

int rayLevel(const ClipmapSettings& clipmap, int level, double heightM, const RayReach& rays) {
    const double drift = rays.tanHalfAngle * heightM;
    while (level < clipmap.lastLevel && drift > rays.reachTexels * clipmap.texelM(level)) ++level;
    return level;
}

bool windowHoldsBox(const ClipmapSettings& clipmap, const LevelWindow& window, const glm::dvec3& local, double reach) {
    const PageBox box = pagesRead(texelOf(clipmap, window.level, local), reach, clipmap.pageTexels);
    const int n = clipmap.pagesPerSide();
    return window.holds(box.x0, box.y0, n) && window.holds(box.x1, box.y1, n);
}

int heldRayLevel(const ClipmapSettings& clipmap, const std::vector<LevelWindow>& windows, int level,
                 const glm::dvec3& local, double reach) {
    while (level < clipmap.lastLevel && !windowHoldsBox(clipmap, windows[size_t(level - clipmap.firstLevel)], local, reach))
        ++level;
    return level;
}

PixelFootprint::PixelFootprint(const Camera& camera)
    : eye_(camera.eye), forward_(glm::normalize(glm::dvec3(camera.target - camera.eye))),
      perDepth_(2.0 / (clipFromViewD(camera)[1][1] * double(camera.height))) {}

PageBox pagesRead(const glm::dvec2& texel, double reachTexels, int pageTexels) {
    const auto page = [&](double c) { return pageOf(c, pageTexels); };
    return {page(texel.x - reachTexels), page(texel.y - reachTexels), page(texel.x + reachTexels),
            page(texel.y + reachTexels)};
}

void markPages(const GBuffer& g, const Camera& camera, const Light& sun, const LightFrame& frame,
               const ClipmapSettings& clipmap, const MarkingSettings& settings, PageTable& table,
               std::vector<PixelLevel>& levels) {
    LevelChoice choice{PixelFootprint(camera), clipmap, table.windows(), settings, {}};
    for (int l = clipmap.firstLevel; l <= clipmap.lastLevel; ++l) choice.texelsPerM.push_back(1.0 / clipmap.texelM(l));
    markEachPixel(g, sun, table, levels, [&](size_t k, BoxRequests& requests) {
        const PixelLevel chosen = choice.choose(glm::dvec3(g.position[k]), frame);
        if (chosen.level == kNoLevel) return chosen;
        const int level = clipmap.firstLevel + chosen.level;
        requests.request(level, pagesRead(chosen.texel, settings.reachTexels, clipmap.pageTexels));
        if (settings.rays.tanHalfAngle > 0.0)
            markRays(requests, table.windows(), clipmap, settings, level, frame.local(glm::dvec3(g.position[k])));
        return chosen;
    });
}

}  // namespace shadowlab::vsm
