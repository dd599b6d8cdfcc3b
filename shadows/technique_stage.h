// One technique run as a stage of another by its parameters' text: izb-pcss runs `izb` for
// its hard part. The inner technique reads the same scene, G-buffer, light, casters and SIMD
// level, with parameters of its own, so it is the very technique a user can run alone (the
// same bytes, the same errors), not a copy of it. A family with typed settings offers its
// run with them instead (runShadowMap, runShadowVolume), which contact-shadows and the
// environment techniques call.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "shadows/technique.h"

namespace shadowlab {

// Runs `inner` on `in` with `given` for its parameters (checked as on the command line)
// and its intermediate buffers written to `debugDir` (empty: none).
ShadowOutputs runTechniqueStage(const Technique& inner, const ShadowInputs& in,
                                const std::map<std::string, std::string>& given, const std::filesystem::path& debugDir);

}  // namespace shadowlab
