// `coloured-shadow-map` (Real-Time Rendering, 4th ed., section 7.8, first paragraph): over
// the opaque map, a second map of the translucent casters holding the depth of the nearest
// one and, as multiplicative blending would leave it, the product of the light every one of
// them passes, per channel. A receiver the opaque map leaves lit and that lies behind the
// nearest translucent surface gets that colour. Its known failures: a receiver between two
// translucent layers gets all of them (so a translucent caster cannot shadow itself
// correctly, as RTR says), and volumes are not seen.
#include <algorithm>

#include "shadows/deep/deep_techniques.h"
#include "shadows/deep/volumetric_frame.h"

namespace shadowlab {
namespace {

struct ColouredMap {
    std::vector<float> nearest;       // per texel, 1 where nothing translucent
    std::vector<glm::vec3> passed;    // per texel, the product of the translucent surfaces' passed light

    glm::vec3 at(size_t texel, float z) const { return z > nearest[texel] ? passed[texel] : glm::vec3(1.0f); }
    double bytesPerTexel() const { return sizeof(float) + sizeof(glm::vec3); }
    void addStats(VolumetricStats&) const {}
    // The colours as a picture (linear, 255 for 1) and their luminance as a buffer, and the
    // nearest translucent depth.
    void writeDebug(const DebugBuffers& debug, const VolumetricLayers& layers) const {
        std::vector<uint8_t> rgb(3 * passed.size());
        std::vector<float> luminances(passed.size());
        for (size_t t = 0; t < passed.size(); ++t) {
            for (int c = 0; c < 3; ++c) {
                rgb[3 * t + size_t(c)] = uint8_t(255.0f * std::clamp(passed[t][c], 0.0f, 1.0f) + 0.5f);
            }
            luminances[t] = luminance(passed[t]);
        }
        debug.writePicture("colour", layers.size(), layers.size(), rgb);
        debug.write("colour-luminance", layers.size(), layers.size(), luminances, 0.0f, 1.0f);
        debug.write("nearest-depth", layers.size(), layers.size(), nearest, layers.nearestDepth, 1.0f);
    }
};

ColouredMap buildColouredMap(const VolumetricLayers& layers) {
    const size_t texels = layers.start.size() - 1;
    ColouredMap map{std::vector<float>(texels, 1.0f), std::vector<glm::vec3>(texels, glm::vec3(1.0f))};
    for (size_t t = 0; t < texels; ++t) {
        for (uint32_t e = layers.start[t]; e < layers.start[t + 1]; ++e) {
            if (layers.triangle[e] == VolumetricLayers::kVolumePiece) continue;
            map.nearest[t] = std::min(map.nearest[t], layers.depthNear[e]);
            map.passed[t] *= layers.passed[e];
        }
    }
    return map;
}

ShadowOutputs runColouredShadowMap(const ShadowInputs& in) {
    return runVolumetricFrame(in, volumetricSettingsTable().read(in.params), "coloured-shadow-map", "colour_map",
                              buildColouredMap);
}

}  // namespace

Technique colouredShadowMapTechnique() {
    return {.name = "coloured-shadow-map",
            .description = "coloured shadow map (RTR 7.8): the nearest translucent depth and the product of the "
                           "translucent casters' colours over the opaque map",
            .params = volumetricSettingsTable().specs(),
            .run = runColouredShadowMap,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
