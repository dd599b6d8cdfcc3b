#include "shadows/maps/shadow_map_debug.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "shading/image_io.h"

namespace shadowlab {

void writeDepthMap(const DebugBuffers& debug, const std::string& name, const DepthMap& map) {
    if (!debug.enabled()) return;
    const std::vector<float> image = map.image();
    const float nearest = *std::min_element(image.begin(), image.end());
    debug.write(name, map.size, map.size, image, nearest, 1.0f);
}

void writeMinMaxHierarchy(const DebugBuffers& debug, const MinMaxHierarchy& hierarchy) {
    if (!debug.enabled()) return;
    const std::vector<float> top = hierarchy.leastImage(hierarchy.levels());
    const float nearest = *std::min_element(top.begin(), top.end());
    for (int level = MinMaxHierarchy::kFirstLevel; level <= std::min(6, hierarchy.levels()); level += 2) {
        const int size = hierarchy.sizeOf(level);
        debug.write("hierarchy-min-" + std::to_string(level), size, size, hierarchy.leastImage(level), nearest, 1.0f);
        debug.write("hierarchy-max-" + std::to_string(level), size, size, hierarchy.greatestImage(level), nearest, 1.0f);
    }
}

void writeTexelDensity(const DebugBuffers& debug, const GBuffer& g, const ShadowLookup& lookup) {
    debug.write("texel-density", g.width, g.height, lookup.texelDensity, 0.0f, 2.0f);
}

void writeMapColouring(const std::filesystem::path& directory, const std::string& technique, const std::string& name,
                       const GBuffer& g, const ShadowLookup& lookup) {
    if (directory.empty()) return;
    // Purple, green, yellow, red as in Figure 7.20, then blue, cyan, orange, white.
    static const uint8_t kColours[8][3] = {{150, 60, 200}, {60, 180, 60},  {230, 210, 40}, {210, 50, 40},
                                           {50, 90, 220},  {40, 200, 210}, {240, 140, 30}, {230, 230, 230}};
    std::vector<uint8_t> rgb(g.pixelCount() * 3, 128);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        const int m = lookup.mapIndex[k];
        if (!g.hit[k] || m < 0) continue;
        const float shade = 0.45f + 0.55f * lookup.visibility[k];
        for (int c = 0; c < 3; ++c) rgb[3 * k + c] = uint8_t(std::lround(kColours[m % 8][c] * shade));
    }
    writePng(directory / (technique + "-" + name + ".png"), g.width, g.height, rgb);
}

}  // namespace shadowlab
