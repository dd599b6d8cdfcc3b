#include "frame/score.h"

#include <stdexcept>

#include "frame/registry.h"
#include "shading/luminance.h"
#include "shading/tonemap.h"

namespace shadowlab {
namespace {

// Half of the sRGB code: marks in full colour stand out over any grey.
uint8_t dimmedGrey(const glm::vec3& radiance) {
    return uint8_t(toSrgb8(luminance(toneMap(radiance, {}))) / 2);
}

}  // namespace

const char* scoredChannel(TechniqueOutput output) {
    return output == TechniqueOutput::Visibility ? channel::V : channel::Y;
}

ImageChannels scoredImage(const Frame& frame) {
    ImageChannels image;
    image.width = frame.gbuffer.width;
    image.height = frame.gbuffer.height;
    image.set(channel::hit, std::vector<float>(frame.gbuffer.hit.begin(), frame.gbuffer.hit.end()));
    if (frame.output == TechniqueOutput::Visibility) {
        image.set(channel::V, frame.shadow.visibility);
    } else {
        std::vector<float> Y(frame.radiance.size()), display(frame.radiance.size());
        for (size_t k = 0; k < Y.size(); ++k) {
            Y[k] = luminance(frame.radiance[k]);
            display[k] = luminance(toneMap(frame.radiance[k], {}));
        }
        image.set(channel::Y, std::move(Y));
        image.set(kDisplayLuminance, std::move(display));
    }
    return image;
}

Frame renderReferenceFrame(const PreparedScene& prepared, raster::SimdLevel simd, const std::string& referenceName,
                           Progress* progress) {
    FrameSettings settings;
    settings.simd = simd;
    settings.progress = progress;
    return renderFrame(prepared, findTechnique(referenceName), settings);
}

ImageChannels renderReferenceImage(const PreparedScene& prepared, raster::SimdLevel simd, const std::string& referenceName,
                                   Progress* progress) {
    return scoredImage(renderReferenceFrame(prepared, simd, referenceName, progress));
}

ErrorFigures scoreImage(const ImageChannels& reference, const ImageChannels& test, TechniqueOutput output) {
    CompareOptions options;
    // Assigned from a std::string: GCC 12 warns falsely (-Wrestrict) on assigning the char*.
    options.channel = std::string(scoredChannel(output));
    if (!reference.find(options.channel)) {
        std::string why = "the reference has no ";
        why.append(options.channel).append(" channel: a technique is scored against a reference of the same output");
        throw std::invalid_argument(why);
    }
    ErrorFigures figures = compareImages(reference, test, options);
    if (output == TechniqueOutput::Radiance && reference.find(kDisplayLuminance)) {
        CompareOptions display;
        display.channel = kDisplayLuminance;
        figures.rmsDisplay = compareImages(reference, test, display).rms;
    }
    return figures;
}

ErrorFigures scoreFrame(const ImageChannels& reference, const Frame& frame) {
    return scoreImage(reference, scoredImage(frame), frame.output);
}

std::vector<uint8_t> errorMapImage(const ImageChannels& reference, const ImageChannels& test,
                                   const std::vector<glm::vec3>& shaded, const std::string& scored) {
    const CompareOptions options;
    const std::vector<float>& hit = reference.at(channel::hit);
    const std::vector<float>& referenceV = reference.at(scored);
    const std::vector<float>& testV = test.at(scored);
    if (testV.size() != hit.size() || shaded.size() != hit.size())
        throw std::invalid_argument("error map: the reference, the test and the shaded image differ in size");
    std::vector<uint8_t> rgb(3 * shaded.size());
    for (size_t k = 0; k < shaded.size(); ++k) {
        std::array<uint8_t, 3> colour;
        colour.fill(dimmedGrey(shaded[k]));
        const bool referenceLit = referenceV[k] >= options.litThreshold, testLit = testV[k] >= options.litThreshold;
        if (hit[k] == 1.0f && referenceLit && !testLit) colour = kFalseShadowColour;
        if (hit[k] == 1.0f && !referenceLit && testLit) colour = kFalseLightColour;
        std::copy(colour.begin(), colour.end(), rgb.begin() + 3 * k);
    }
    return rgb;
}

}  // namespace shadowlab
