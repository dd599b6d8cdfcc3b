#include "shadows/virtual/page_lookup.h"

namespace shadowlab::vsm {

float PageTexels::at(int level, int x, int y) const {
    Cursor cursor;
    return at(level, x, y, cursor);
}

float PageTexels::at(int level, int x, int y, Cursor& cursor) const {
    const PageKey key = pageOf(level, x, y);
    if (key != cursor.key) {
        const int32_t physical = table_.physical(key);
        cursor.key = key;
        cursor.texels = physical == kNoPhysicalPage || !table_.valid(key)
                            ? nullptr
                            : &pool_.depth[size_t(physical) * size_t(pageTexels_) * size_t(pageTexels_)];
    }
    if (!cursor.texels) return kMissingTexel;
    return cursor.texels[size_t(y - key.y * pageTexels_) * size_t(pageTexels_) +
                         size_t(x - key.x * pageTexels_)];
}

std::vector<DepthMap> levelMaps(const LightFrame& frame, const ClipmapSettings& clipmap, const DepthRange& range) {
    std::vector<DepthMap> maps(size_t(clipmap.levelCount()));
    for (int l = 0; l < clipmap.levelCount(); ++l) {
        maps[size_t(l)].texelFromWorld = levelTexelFromWorld(frame, clipmap, range, clipmap.firstLevel + l);
        maps[size_t(l)].worldFromTexel = glm::inverse(maps[size_t(l)].texelFromWorld);
    }
    return maps;
}

double lookupReachTexels(const BiasSettings& bias, const FilterSettings& filter) {
    return (bias.mode == BiasMode::NormalOffset ? bias.normalOffsetTexels : 0.0) + tapReachTexels(filter);
}

LookupResult lookUpPages(const GBuffer& g, const Light& sun, const LightFrame& frame, const ClipmapSettings& clipmap,
                         const DepthRange& range, const BiasSettings& bias, const PcfKernel& filter,
                         const std::vector<PixelLevel>& levels, const PageTable& table, const PagePool& pool) {
    const std::vector<DepthMap> maps = levelMaps(frame, clipmap, range);
    const PageTexels texels(clipmap.pageTexels, table, pool);
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(sun.direction));
    return lookUpEachPixel(g, sun, levels, [&](size_t k, const PixelLevel& p, bool& missing) {
        const MapReceiver r = mapReceiver(maps[size_t(p.level)], glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]),
                                          towardsLight, bias);
        const int level = clipmap.firstLevel + p.level;
        PageTexels::Cursor cursor;
        const auto litAt = [&](int x, int y) {
            const float stored = texels.at(level, x, y, cursor);
            missing |= stored == PageTexels::kMissingTexel;
            return stored == PageTexels::kMissingTexel || r.litByStored(stored, x, y);
        };
        const glm::dvec2 rotation = kernelRotation(filter, k, g.width);
        return float(pcfLitFraction(filter, r.texel, rotation, litAt));
    });
}

}  // namespace shadowlab::vsm
