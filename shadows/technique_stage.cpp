#include "shadows/technique_stage.h"

namespace shadowlab {

std::map<std::string, std::string> sharedParamValues(const Technique& inner, const TechniqueParams& outer) {
    std::map<std::string, std::string> shared;
    for (const ParamSpec& spec : inner.params) {
        const auto it = outer.values().find(spec.name);
        if (it != outer.values().end()) shared[spec.name] = it->second;
    }
    return shared;
}

ShadowOutputs runTechniqueStage(const Technique& inner, const ShadowInputs& in,
                                const std::map<std::string, std::string>& given,
                                const std::filesystem::path& debugDir) {
    const TechniqueParams params(inner.name, inner.params, given);
    const ShadowInputs stage{in.prepared,   in.gbuffer,       in.light,         in.simd,        params,
                             debugDir,      in.progress,      in.gbufferCamera, in.casterScene, in.receiverLiftM};
    return inner.run(stage);
}

}  // namespace shadowlab
