#include "frame/score.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "shading/tonemap.h"

namespace shadowlab {
namespace {

// Rec. 709 luminance of a display-referred linear colour.
float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Half of the sRGB code: marks in full colour stand out over any grey.
uint8_t dimmedGrey(const glm::vec3& radiance) {
    return uint8_t(toSrgb8(luminance(toneMap(radiance, {}))) / 2);
}

}  // namespace

ImageChannels visibilityImage(const Frame& frame) {
    ImageChannels image;
    image.width = frame.gbuffer.width;
    image.height = frame.gbuffer.height;
    image.set(channel::hit, std::vector<float>(frame.gbuffer.hit.begin(), frame.gbuffer.hit.end()));
    image.set(channel::V, frame.shadow.visibility);
    return image;
}

ImageChannels renderReferenceVisibility(const PreparedScene& prepared, raster::SimdLevel simd,
                                        const std::string& referenceName, Progress* progress) {
    FrameSettings settings;
    settings.simd = simd;
    settings.progress = progress;
    return visibilityImage(renderFrame(prepared, findTechnique(referenceName), settings));
}

ErrorFigures scoreFrame(const ImageChannels& reference, const Frame& frame) {
    return compareImages(reference, visibilityImage(frame));
}

std::vector<uint8_t> errorMapImage(const ImageChannels& reference, const ImageChannels& test,
                                   const std::vector<glm::vec3>& shaded) {
    const CompareOptions options;
    const std::vector<float>& hit = reference.at(channel::hit);
    const std::vector<float>& referenceV = reference.at(options.channel);
    const std::vector<float>& testV = test.at(options.channel);
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

std::string formatScoreJson(const std::string& sceneName, const std::string& technique, const std::string& reference,
                            const std::map<std::string, std::string>& settings, const Frame& frame,
                            const ErrorFigures& figures) {
    nlohmann::ordered_json stats = nlohmann::ordered_json::object();
    for (const TechniqueStat& s : frame.shadow.stats) stats[s.name] = s.value;
    nlohmann::ordered_json j;
    j["scene"] = sceneName;
    j["technique"] = technique;
    j["reference"] = reference;
    j["settings"] = settings;
    j["technique_ms"] = frame.techniqueMs;
    j["stats"] = stats;
    j["errors"] = nlohmann::ordered_json::parse(formatJson(figures));
    return j.dump(2) + "\n";
}

}  // namespace shadowlab
