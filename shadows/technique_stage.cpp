#include "shadows/technique_stage.h"

namespace shadowlab {

ShadowOutputs runTechniqueStage(const Technique& inner, const ShadowInputs& in,
                                const std::map<std::string, std::string>& given,
                                const std::filesystem::path& debugDir) {
    const TechniqueParams params(inner.name, inner.params, given);
    const ShadowInputs stage{.prepared = in.prepared,
                             .gbuffer = in.gbuffer,
                             .light = in.light,
                             .simd = in.simd,
                             .params = params,
                             .debugDir = debugDir,
                             .progress = in.progress,
                             .gbufferCamera = in.gbufferCamera,
                             .casterScene = in.casterScene,
                             .receiverLiftM = in.receiverLiftM};
    return inner.run(stage);
}

}  // namespace shadowlab
