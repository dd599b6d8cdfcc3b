#include "frame/score_json.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "frame/overrides_json.h"

namespace shadowlab {

std::string formatScoreJson(const std::string& sceneName, const std::string& technique, const std::string& reference,
                            const std::map<std::string, std::string>& settings, const Frame& frame,
                            const ErrorFigures& figures, const FrameImages& images, const SceneOverrides& overrides,
                            const std::vector<ErrorFigures>& lightFigures) {
    nlohmann::ordered_json stats = nlohmann::ordered_json::object();
    for (const TechniqueStat& s : frame.shadow.stats) stats[s.name] = s.value;
    nlohmann::ordered_json j;
    j["scene"] = sceneName;
    j["overrides"] = overridesJson(overrides);
    j["technique"] = technique;
    j["reference"] = reference;
    j["settings"] = settings;
    j["technique_ms"] = frame.techniqueMs;
    j["stats"] = stats;
    nlohmann::ordered_json preparation = nlohmann::ordered_json::object();
    for (const TechniqueStat& s : frame.preparation) preparation[s.name] = s.value;
    j["preparation"] = preparation;
    j["errors"] = nlohmann::ordered_json::parse(formatJson(figures));
    if (frame.passes.size() > 1) {
        if (lightFigures.size() != frame.passes.size())
            throw std::invalid_argument("score JSON: " + std::to_string(frame.passes.size()) + " lights but " +
                                        std::to_string(lightFigures.size()) + " lights' figures");
        nlohmann::ordered_json lights = nlohmann::ordered_json::array();
        for (size_t k = 0; k < frame.passes.size(); ++k) {
            const LightPass& pass = frame.passes[k];
            lights.push_back({{"light", pass.light},
                              {"technique_ms", pass.techniqueMs},
                              {"errors", nlohmann::ordered_json::parse(formatJson(lightFigures[k]))}});
        }
        j["lights"] = lights;
    }
    if (!images.empty()) j["images"] = nlohmann::ordered_json::parse(formatFrameImagesJson(images));
    return j.dump(2) + "\n";
}

}  // namespace shadowlab
