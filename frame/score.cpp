#include "frame/score.h"

#include <stdexcept>

#include "frame/registry.h"
#include "shading/flip.h"
#include "shading/luminance.h"
#include "shading/tonemap.h"

namespace shadowlab {
namespace {

void requireLights(const ImageChannels& test, const std::vector<std::string>& lights) {
    for (const std::string& name : lights) {
        if (!test.find(name))
            throw std::invalid_argument("the test image has no " + name + " channel: a frame is scored against a reference of the same lights");
    }
}

// Half of the sRGB code: marks in full colour stand out over any grey.
uint8_t dimmedGrey(const glm::vec3& radiance) {
    return uint8_t(toSrgb8(luminance(toneMap(radiance, {}))) / 2);
}

// One channel of `count` lights' V images stacked top to bottom, with their hit channel
// repeated: the image scoreImage() scores several lights on.
ImageChannels stackedLights(const ImageChannels& image, const std::vector<std::string>& channels) {
    ImageChannels stacked;
    stacked.width = image.width;
    stacked.height = image.height * int(channels.size());
    std::vector<float> hit, V;
    for (const std::string& name : channels) {
        const std::vector<float>& h = image.at(channel::hit);
        const std::vector<float>& v = image.at(name);
        hit.insert(hit.end(), h.begin(), h.end());
        V.insert(V.end(), v.begin(), v.end());
    }
    stacked.set(channel::hit, std::move(hit));
    stacked.set(channel::V, std::move(V));
    return stacked;
}

}  // namespace

std::string visibilityChannel(size_t light, size_t lightCount) {
    return lightCount == 1 ? std::string(channel::V) : "light" + std::to_string(light) + "." + channel::V;
}

std::vector<std::string> visibilityChannels(const ImageChannels& image) {
    if (image.find(channel::V)) return {channel::V};
    std::vector<std::string> names;
    while (image.find(visibilityChannel(names.size(), 2))) names.push_back(visibilityChannel(names.size(), 2));
    return names;
}

const char* scoredChannel(TechniqueOutput output) {
    return output == TechniqueOutput::Visibility ? channel::V : channel::Y;
}

ImageChannels scoredImage(const Frame& frame) {
    ImageChannels image;
    image.width = frame.gbuffer.width;
    image.height = frame.gbuffer.height;
    image.set(channel::hit, std::vector<float>(frame.gbuffer.hit.begin(), frame.gbuffer.hit.end()));
    if (frame.output == TechniqueOutput::Visibility) {
        for (const LightPass& pass : frame.passes)
            image.set(visibilityChannel(pass.light, frame.passes.size()), pass.shadow.visibility);
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
    if (output == TechniqueOutput::Visibility) {
        const std::vector<std::string> lights = visibilityChannels(reference);
        if (lights.size() > 1) {
            requireLights(test, lights);
            return compareImages(stackedLights(reference, lights), stackedLights(test, lights));
        }
    }
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

std::vector<ErrorFigures> scoreLights(const ImageChannels& reference, const ImageChannels& test) {
    const std::vector<std::string> lights = visibilityChannels(reference);
    if (lights.size() <= 1) return {scoreImage(reference, test, TechniqueOutput::Visibility)};
    requireLights(test, lights);
    std::vector<ErrorFigures> figures;
    for (const std::string& name : lights) {
        CompareOptions options;
        options.channel = name;
        figures.push_back(compareImages(reference, test, options));
    }
    return figures;
}

ErrorFigures scoreFrame(const ImageChannels& reference, const Frame& frame) {
    return scoreImage(reference, scoredImage(frame), frame.output);
}

std::vector<glm::vec3> displayedImage(const std::vector<glm::vec3>& radiance) {
    std::vector<glm::vec3> displayed(radiance.size());
    for (size_t k = 0; k < radiance.size(); ++k) displayed[k] = toneMap(radiance[k], {});
    return displayed;
}

double flipFigure(const std::vector<glm::vec3>& referenceShaded, const std::vector<glm::vec3>& testShaded, int width,
                  int height, const std::vector<float>& hit) {
    if (hit.size() != referenceShaded.size())
        throw std::invalid_argument("FLIP: the reference's hit channel and its shaded image differ in size");
    const FlipErrorMap map =
        flipErrorMap(displayedImage(referenceShaded), displayedImage(testShaded), width, height);
    std::vector<float> mask(hit.size());
    for (size_t k = 0; k < hit.size(); ++k) mask[k] = hit[k] == 1.0f ? 1.0f : 0.0f;
    return flipMean(map, mask);
}

ScoredReference scoredReference(const Frame& frame) { return {scoredImage(frame), frame.radiance}; }

ErrorFigures scoreFrame(const ScoredReference& reference, const ImageChannels& scored, const Frame& frame) {
    ErrorFigures figures = scoreImage(reference.scored, scored, frame.output);
    figures.flipMean = flipFigure(reference.shaded, frame.radiance, frame.gbuffer.width, frame.gbuffer.height,
                                  reference.scored.at(channel::hit));
    return figures;
}

std::vector<uint8_t> errorMapImage(const ImageChannels& reference, const ImageChannels& test,
                                   const std::vector<glm::vec3>& shaded, const std::string& scored) {
    const CompareOptions options;
    const std::vector<float>& hit = reference.at(channel::hit);
    const std::vector<std::string> channels =
        scored == channel::V && !reference.find(channel::V) ? visibilityChannels(reference) : std::vector{scored};
    std::vector<const std::vector<float>*> referenceV, testV;
    for (const std::string& name : channels) {
        referenceV.push_back(&reference.at(name));
        testV.push_back(&test.at(name));
        if (testV.back()->size() != hit.size())
            throw std::invalid_argument("error map: the reference, the test and the shaded image differ in size");
    }
    if (shaded.size() != hit.size())
        throw std::invalid_argument("error map: the reference, the test and the shaded image differ in size");
    std::vector<uint8_t> rgb(3 * shaded.size());
    for (size_t k = 0; k < shaded.size(); ++k) {
        bool falseShadow = false, falseLight = false;
        for (size_t c = 0; c < channels.size(); ++c) {
            const bool referenceLit = (*referenceV[c])[k] >= options.litThreshold;
            const bool testLit = (*testV[c])[k] >= options.litThreshold;
            falseShadow = falseShadow || (referenceLit && !testLit);
            falseLight = falseLight || (!referenceLit && testLit);
        }
        std::array<uint8_t, 3> colour;
        colour.fill(dimmedGrey(shaded[k]));
        if (hit[k] == 1.0f && falseShadow) colour = kFalseShadowColour;
        if (hit[k] == 1.0f && falseLight) colour = kFalseLightColour;
        std::copy(colour.begin(), colour.end(), rgb.begin() + 3 * k);
    }
    return rgb;
}

}  // namespace shadowlab
