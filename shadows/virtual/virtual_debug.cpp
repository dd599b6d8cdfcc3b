#include "shadows/virtual/virtual_debug.h"

#include <algorithm>
#include <cmath>
#include <string>


namespace shadowlab::vsm {
namespace {

// A page's state in the page-table images (the header's key); "evicted" and "rendered this
// frame" the image functions set from the table's and the frame's lists.
constexpr float kEvictedState = 0.125f;
float pageState(const PageTable& table, const PageKey& key) {
    if (table.physical(key) == kNoPhysicalPage) return 0.0f;
    return !table.valid(key) ? 0.25f : table.requested(key) ? 0.75f : 0.5f;
}

std::vector<float> pageTableImage(const ClipmapSettings& clipmap, const PageTable& table,
                                  const std::vector<PageKey>& rendered) {
    const int n = clipmap.pagesPerSide();
    std::vector<float> image(size_t(n) * size_t(n) * size_t(clipmap.levelCount()), 0.0f);
    for (size_t l = 0; l < table.windows().size(); ++l) {
        const LevelWindow& w = table.windows()[l];
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x)
                image[(l * size_t(n) + size_t(y)) * size_t(n) + size_t(x)] = pageState(table, {w.level, w.firstX + x, w.firstY + y});
        }
    }
    const auto mark = [&](const std::vector<PageKey>& keys, float state) {
        for (const PageKey& key : keys) {
            const LevelWindow& w = table.windows()[size_t(key.level - clipmap.firstLevel)];
            if (!w.holds(key.x, key.y, n)) continue;   // an evicted page may lie outside
            image[(size_t(key.level - clipmap.firstLevel) * size_t(n) + size_t(key.y - w.firstY)) * size_t(n) +
                  size_t(key.x - w.firstX)] = state;
        }
    };
    mark(table.evictedThisFrame(), kEvictedState);
    mark(rendered, 1.0f);
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

// Face f's mips stacked from mip 0 down, each left-aligned in mip 0's width; the rows of
// mip m start at firstRow[m].
std::vector<float> facePageTableImage(const MipChain& chain, int face, const PageTable& table,
                                      const std::vector<PageKey>& rendered, int& rows) {
    const int n0 = chain.pagesPerSide(0);
    std::vector<int> firstRow{0};
    for (int mip = 0; mip < chain.mipCount; ++mip) firstRow.push_back(firstRow.back() + chain.pagesPerSide(mip));
    rows = firstRow.back();
    std::vector<float> image(size_t(n0) * size_t(rows), 0.0f);
    const auto at = [&](const PageKey& key) -> float& {
        return image[size_t(firstRow[size_t(chain.mipOfLevel(key.level))] + key.y) * size_t(n0) + size_t(key.x)];
    };
    for (int mip = 0; mip < chain.mipCount; ++mip) {
        const int level = chain.levelOf(face, mip);
        for (int32_t y = 0; y < chain.pagesPerSide(mip); ++y)
            for (int32_t x = 0; x < chain.pagesPerSide(mip); ++x) at({level, x, y}) = pageState(table, {level, x, y});
    }
    for (const PageKey& key : table.evictedThisFrame())
        if (chain.faceOfLevel(key.level) == face) at(key) = kEvictedState;
    for (const PageKey& key : rendered)
        if (chain.faceOfLevel(key.level) == face) at(key) = 1.0f;
    return image;
}

void writePool(const DebugBuffers& debug, const PagePool& pool) {
    int side = 0;
    const std::vector<float> atlas = poolAtlas(pool, side);
    debug.write("pool", side, side, atlas, 0.0f, 1.0f);
}

}  // namespace

void writeLocalVirtualDebug(const DebugBuffers& debug, const GBuffer& g, const Camera& camera, const MipChain& chain,
                            const std::vector<PixelLevel>& levels, const PageTable& table,
                            const std::vector<PageKey>& rendered, const PagePool& pool,
                            const std::vector<float>& escapedRays) {
    if (!debug.enabled()) return;
    std::vector<float> face(g.pixelCount(), -1.0f), mip(g.pixelCount(), -1.0f), texelsPerPixel(g.pixelCount(), 0.0f);
    const PixelFootprint footprint(camera);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (levels[k].level == kNoLevel) continue;
        const int f = chain.faceOfLevel(levels[k].level), m = chain.mipOfLevel(levels[k].level);
        const glm::dvec3 P(g.position[k]);
        face[k] = float(chain.faceCount() == 6 ? f : 0), mip[k] = float(m);
        // The mip's texel across the face's beam at the pixel's depth along its axis.
        const double along = -(chain.faces[size_t(f)] * glm::dvec4(P, 1.0)).z;
        const double texel = 2.0 * along * chain.tanHalf / double(chain.mipTexels(m));
        texelsPerPixel[k] = float(footprint.at(P) / texel);
    }
    debug.write("face", g.width, g.height, face, -1.0f, 5.0f);
    debug.write("mip", g.width, g.height, mip, -1.0f, float(chain.mipCount - 1));
    debug.write("texels-per-pixel", g.width, g.height, texelsPerPixel, 0.0f, 4.0f);
    for (int f = 0; f < chain.faceCount(); ++f) {
        int rows = 0;
        const std::vector<float> image = facePageTableImage(chain, f, table, rendered, rows);
        const std::string name = chain.faceCount() == 6 ? std::string("page-table-face-") + kCubeFaceNames[f] : "page-table";
        debug.write(name, chain.pagesPerSide(0), rows, image, 0.0f, 1.0f);
    }
    writePool(debug, pool);
    if (!escapedRays.empty()) debug.write("smrt-escaped", g.width, g.height, escapedRays, 0.0f, 1.0f);
}

void writeVirtualDebug(const DebugBuffers& debug, const GBuffer& g, const Camera& camera,
                       const ClipmapSettings& clipmap, const std::vector<PixelLevel>& levels, const PageTable& table,
                       const std::vector<PageKey>& rendered, const PagePool& pool,
                       const std::vector<float>& escapedRays) {
    if (!debug.enabled()) return;
    std::vector<float> level(g.pixelCount(), -1.0f), texelsPerPixel(g.pixelCount(), 0.0f);
    const PixelFootprint footprint(camera);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (levels[k].level == kNoLevel) continue;
        level[k] = float(levels[k].level);
        texelsPerPixel[k] = float(footprint.at(glm::dvec3(g.position[k])) / clipmap.texelM(clipmap.firstLevel + levels[k].level));
    }
    debug.write("level", g.width, g.height, level, -1.0f, float(clipmap.levelCount() - 1));
    debug.write("texels-per-pixel", g.width, g.height, texelsPerPixel, 0.0f, 4.0f);
    const int n = clipmap.pagesPerSide();
    debug.write("page-table", n, n * clipmap.levelCount(), pageTableImage(clipmap, table, rendered), 0.0f, 1.0f);
    writePool(debug, pool);
    if (!escapedRays.empty()) debug.write("smrt-escaped", g.width, g.height, escapedRays, 0.0f, 1.0f);
}

}  // namespace shadowlab::vsm
