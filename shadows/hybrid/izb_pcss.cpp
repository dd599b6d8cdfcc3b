// The `izb-pcss` technique: the stages of izb_pcss.h in order, its figures and its debug
// buffers.
#include <stdexcept>
#include <string>

#include "shadows/debug_buffers.h"
#include "shadows/filtered/pcss.h"
#include "shadows/hybrid/izb_pcss.h"
#include "shadows/izb/izb.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

const char* const kIzbPcssName = "izb-pcss";

struct IzbPcssSettings {
    PcssSettings pcss;
    IzbSettings izb;
    BlendDistances blend;
};

// The irregular z-buffer's resolution is its own parameter, `izb-resolution`: `resolution`
// is the PCSS map's.
const SettingsTable<IzbPcssSettings>& izbPcssSettingsTable() {
    using S = IzbPcssSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::pcss), pcssSettingsTable())
            .integerOrAuto("izb-resolution", member(&S::izb, &IzbSettings::resolution), kMinMapResolution,
                           kMaxMapResolution,
                           "irregular z-buffer grid texels per side; auto: about 2 receivers per list")
            .real("hard-below", member(&S::blend, &BlendDistances::hardBelowM), 0.0, 1000.0,
                  "m from receiver to occluder up to which the exact hard shadow is kept")
            .real("soft-above", member(&S::blend, &BlendDistances::softAboveM), 0.0, 1000.0,
                  "m from receiver to occluder from which PCSS is kept; blended between");
    return table;
}

IzbPcssSettings readSettings(const TechniqueParams& params) {
    const IzbPcssSettings s = izbPcssSettingsTable().read(params);
    if (!(s.blend.hardBelowM < s.blend.softAboveM)) {
        throw std::invalid_argument(std::string(kIzbPcssName) + ": hard-below must be less than soft-above");
    }
    return s;
}

// The `izb` technique itself, its buffers not written.
ShadowOutputs hardShadows(const ShadowInputs& in, const IzbSettings& settings) {
    ShadowInputs stage = in;
    stage.debugDir.clear();
    return runIrregularZBuffer(stage, settings);
}

void writeDebug(const ShadowInputs& in, const SoftShadowMap& soft, const std::vector<float>& weight,
                const std::vector<float>& hard, const std::vector<float>& blockerDistance,
                const std::vector<float>& softV) {
    const DebugBuffers debug(in.debugDir, kIzbPcssName);
    if (!debug.enabled()) return;
    const GBuffer& g = in.gbuffer;
    debug.write("blend-weight", g.width, g.height, weight, 0.0f, 1.0f);
    debug.write("izb", g.width, g.height, hard, 0.0f, 1.0f);
    debug.write("pcss", g.width, g.height, softV, 0.0f, 1.0f);
    debug.write("blocker-distance", g.width, g.height, blockerDistance, float(soft.zNear()), float(soft.zFar()));
}

// Pixels by the part that decides them, in pixel order (one thread): the same for any
// thread count.
void addStats(ShadowOutputs& out, const GBuffer& g, const std::vector<float>& weight) {
    size_t hard = 0, blended = 0, soft = 0;
    for (size_t k = 0; k < weight.size(); ++k) {
        if (!g.hit[k]) continue;
        hard += weight[k] == 0.0f, soft += weight[k] == 1.0f, blended += weight[k] > 0.0f && weight[k] < 1.0f;
    }
    out.stats.push_back({"hard_pixels", double(hard)});
    out.stats.push_back({"blended_pixels", double(blended)});
    out.stats.push_back({"soft_pixels", double(soft)});
}

ShadowOutputs runIzbPcss(const ShadowInputs& in) {
    const IzbPcssSettings settings = readSettings(in.params);
    const PcssSettings& pcss = settings.pcss;
    requireAreaLight(in.light, kIzbPcssName);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    // 1. PCSS: the soft V and the blocker distances.
    const SoftShadowMap& soft = renderPcssMap(in, pcss.resolution);
    timer.lap("pcss_map");
    const PcssBuffers softPart = pcssPerPixel(in, soft, pcss, pcssHierarchy(soft, pcss));
    timer.lap("pcss");
    // 2. The irregular z-buffer: the exact hard V.
    const ShadowOutputs hardPart = hardShadows(in, settings.izb);
    timer.lap("izb");
    // 3 and 4. The weight from the occluder distance, and the blend (exactly one part at w = 0 or 1).
    const std::vector<float> weight = blendWeights(in.gbuffer, soft, softPart.blockerDistance, settings.blend);
    ShadowOutputs out;
    out.visibility.resize(weight.size());
    for (size_t k = 0; k < weight.size(); ++k) {
        out.visibility[k] = (1.0f - weight[k]) * hardPart.visibility[k] + weight[k] * softPart.visibility[k];
    }
    timer.lap("blend");
    out.stats.push_back({"resolution_texels", double(pcss.resolution)});
    addStats(out, in.gbuffer, weight);
    timer.appendTo(out.stats);
    writeDebug(in, soft, weight, hardPart.visibility, softPart.blockerDistance, softPart.visibility);
    return out;
}

}  // namespace

Technique izbPcssTechnique() {
    return {.name = kIzbPcssName,
            .description = "hybrid of The Division (RTR 7.9, Story and Wyman 2016): irregular z-buffer shadows "
                           "near their occluders, PCSS far from them, blended by the occluder distance",
            .params = izbPcssSettingsTable().specs(),
            .run = runIzbPcss,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
