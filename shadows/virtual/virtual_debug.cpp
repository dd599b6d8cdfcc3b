#include "shadows/virtual/virtual_debug.h"

#include <algorithm>
#include <cmath>

#include "scenes/camera.h"

namespace shadowlab::vsm {
namespace {

std::vector<float> pageTableImage(const ClipmapSettings& clipmap, const PageTable& table,
                                  const std::vector<PageKey>& rendered) {
    const int n = clipmap.pagesPerSide();
    std::vector<float> image(size_t(n) * size_t(n) * size_t(clipmap.levelCount()), 0.0f);
    for (size_t l = 0; l < table.windows().size(); ++l) {
        const LevelWindow& w = table.windows()[l];
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const PageKey key{w.level, w.firstX + x, w.firstY + y};
                float state = 0.0f;
                if (table.physical(key) != kNoPhysicalPage)
                    state = !table.valid(key) ? 0.25f : table.requested(key) ? 0.75f : 0.5f;
                image[(l * size_t(n) + size_t(y)) * size_t(n) + size_t(x)] = state;
            }
        }
    }
    for (const PageKey& key : rendered) {
        const LevelWindow& w = table.windows()[size_t(key.level - clipmap.firstLevel)];
        image[(size_t(key.level - clipmap.firstLevel) * size_t(n) + size_t(key.y - w.firstY)) * size_t(n) +
              size_t(key.x - w.firstX)] = 1.0f;
    }
    return image;
}

std::vector<float> poolAtlas(const PagePool& pool, int& side) {
    const size_t pageSize = size_t(pool.pageTexels) * size_t(pool.pageTexels);
    const int pages = int(pool.depth.size() / pageSize);
    const int n = std::max(1, int(std::ceil(std::sqrt(double(pages)))));
    side = n * pool.pageTexels;
    std::vector<float> atlas(size_t(side) * size_t(side), 1.0f);
    for (int p = 0; p < pages; ++p)
        for (int y = 0; y < pool.pageTexels; ++y)
            for (int x = 0; x < pool.pageTexels; ++x)
                atlas[size_t((p / n) * pool.pageTexels + y) * size_t(side) + size_t((p % n) * pool.pageTexels + x)] =
                    pool.at(p, x, y);
    return atlas;
}

}  // namespace

void writeVirtualDebug(const DebugBuffers& debug, const GBuffer& g, const Camera& camera,
                       const ClipmapSettings& clipmap, const std::vector<PixelLevel>& levels, const PageTable& table,
                       const std::vector<PageKey>& rendered, const PagePool& pool,
                       const std::vector<float>& escapedRays) {
    if (!debug.enabled()) return;
    std::vector<float> level(g.pixelCount(), -1.0f), texelsPerPixel(g.pixelCount(), 0.0f);
    const glm::dvec3 eye(camera.eye), forward = glm::normalize(glm::dvec3(camera.target - camera.eye));
    const double perDepth = 2.0 / (clipFromViewD(camera)[1][1] * double(camera.height));
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (levels[k].level == kNoLevel) continue;
        level[k] = float(levels[k].level);
        const double footprint = perDepth * glm::dot(glm::dvec3(g.position[k]) - eye, forward);
        texelsPerPixel[k] = float(footprint / clipmap.texelM(clipmap.firstLevel + levels[k].level));
    }
    debug.write("level", g.width, g.height, level, -1.0f, float(clipmap.levelCount() - 1));
    debug.write("texels-per-pixel", g.width, g.height, texelsPerPixel, 0.0f, 4.0f);
    const int n = clipmap.pagesPerSide();
    debug.write("page-table", n, n * clipmap.levelCount(), pageTableImage(clipmap, table, rendered), 0.0f, 1.0f);
    int side = 0;
    const std::vector<float> atlas = poolAtlas(pool, side);
    debug.write("pool", side, side, atlas, 0.0f, 1.0f);
    if (!escapedRays.empty()) debug.write("smrt-escaped", g.width, g.height, escapedRays, 0.0f, 1.0f);
}

}  // namespace shadowlab::vsm
