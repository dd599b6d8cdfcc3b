// The `contact-shadows` technique: the stages of contact_shadows.h in order, its figures and
// its debug buffers.
//
// Why the minimum: both passes estimate the visibility of the same point light, and each
// errs mostly towards light. The map's bias moves every receiver towards the light, so a
// caster within the bias of its receiver casts nothing there: light leaks at contacts,
// peter panning (RTR 7.4, Figures 7.13 and 7.14). The march finds only casters that are on
// screen, in front and no thicker than the depth thickness (RTR 7.10), so it misses the rest.
// A pixel is shadowed if either found an occluder: the march "restores" what the bias lost,
// which is the use Sousa et al. made of it. Its one error towards shadow, a sample behind a
// surface thinner than the thickness, stays within the march's short length.
#include "shadows/screen/contact_shadows.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"
#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/plot_pixel.h"
#include "shadows/screen/march_plot.h"
#include "shadows/screen/screen_march.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

const char* const kContactShadowsName = "contact-shadows";
const char* const kMapDebugFolder = "contact-shadows-shadow-map";

struct ContactShadowSettings {
    ShadowMapTechniqueSettings map;
    MarchSettings march;
    bool withMap = true;   // off: the march alone
    PlotPixelSettings plot;
};

const SettingsTable<ContactShadowSettings>& contactShadowSettingsTable() {
    using S = ContactShadowSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::map), shadowMapTechniqueSettingsTable())
            .real("march-length", member(&S::march, &MarchSettings::lengthM), 1e-4, 100.0,
                  "m marched from each pixel towards the light")
            .integer("march-steps", member(&S::march, &MarchSettings::steps), 1, 1024, "samples along the march")
            .real("depth-thickness", member(&S::march, &MarchSettings::thicknessM), 0.0, 100.0,
                  "m behind the depth buffer's surface a sample still counts as inside it")
            .flag("shadow-map", member(&S::withMap), "off: the march alone (no caster off screen or hidden casts)")
            .include(member(&S::plot), plotPixelSettingsTable("march is plotted"));
    return table;
}

// 1. The shadow map: the shadow-map technique's own checks, V, figures and stage times, and
// its buffers in a folder of their own.
ShadowOutputs shadowMapStage(const ShadowInputs& in, const ShadowMapTechniqueSettings& settings) {
    ShadowInputs mapInputs = in;
    mapInputs.debugDir = in.debugDir.empty() ? in.debugDir : in.debugDir / kMapDebugFolder;
    return runShadowMap(mapInputs, settings);
}

// The pixel whose march the debug view plots: the parameters', or the image's centre.
glm::ivec2 plottedPixel(const ShadowInputs& in, const PlotPixelSettings& plot) {
    const auto [i, j] = plotPixel(plot, in.gbuffer.width, in.gbuffer.height, kContactShadowsName);
    return {i, j};
}

void writeDebug(const ShadowInputs& in, const ContactShadowSettings& settings, const ScreenMarch& march,
                const ScreenMarch::Mask& mask) {
    const DebugBuffers debug(in.debugDir, kContactShadowsName);
    if (!debug.enabled()) return;
    const GBuffer& g = in.gbuffer;
    debug.write("march-mask", g.width, g.height, mask.visibility, 0.0f, 1.0f);
    const glm::ivec2 p = plottedPixel(in, settings.plot);
    const std::vector<MarchSample> samples =
        g.hit[g.index(p.x, p.y)] ? marchSamples(march, g, p.x, p.y) : std::vector<MarchSample>{};
    writeMarchPlot(in.debugDir, g, mask.visibility, p.x, p.y, samples, settings.march.thicknessM);
}

// 3. Shadowed where either pass found an occluder, V = min(V_map, V_march), with the march's
// figures (restored: where the map saw light), rows in parallel. The figures are counts, the
// same in any order, so the same for any thread count.
struct MarchCounts {
    size_t occluded = 0, restored = 0, leftScreen = 0;
};

MarchCounts combine(const GBuffer& g, const ScreenMarch::Mask& mask, std::vector<float>& visibility) {
    const auto rows = [&](const tbb::blocked_range<int>& range, MarchCounts counts) {
        for (size_t k = g.index(0, range.begin()); k < g.index(0, range.end()); ++k) {
            const bool occluded = mask.end[k] == uint8_t(MarchEnd::Occluded);
            counts.occluded += occluded, counts.restored += occluded && visibility[k] > 0.0f;
            counts.leftScreen += mask.end[k] == uint8_t(MarchEnd::LeftScreen);
            visibility[k] = std::min(visibility[k], mask.visibility[k]);
        }
        return counts;
    };
    const auto sum = [](const MarchCounts& a, const MarchCounts& b) {
        return MarchCounts{a.occluded + b.occluded, a.restored + b.restored, a.leftScreen + b.leftScreen};
    };
    return tbb::parallel_reduce(tbb::blocked_range<int>(0, g.height), MarchCounts{}, rows, sum);
}

void addStats(ShadowOutputs& out, const MarchCounts& counts) {
    out.stats.push_back({"march_occluded_pixels", double(counts.occluded)});
    out.stats.push_back({"restored_pixels", double(counts.restored)});
    out.stats.push_back({"march_left_screen_pixels", double(counts.leftScreen)});
}

// Without the map: V = 1 wherever the light reaches the surface, for the march to shadow.
ShadowOutputs reachedOutputs(const GBuffer& g, const Light& light) {
    ShadowOutputs out = unlitOutputs(g);
    const LightReach reaches(light);
    for (size_t k = 0; k < g.pixelCount(); ++k) out.visibility[k] = g.hit[k] && reaches(g.position[k], g.normal[k]);
    return out;
}

ShadowOutputs runContactShadows(const ShadowInputs& in) {
    const ContactShadowSettings settings = contactShadowSettingsTable().read(in.params);
    plottedPixel(in, settings.plot);   // settings checked before any work
    const Light light = pointLightFor(in.light);
    ShadowOutputs out = settings.withMap ? shadowMapStage(in, settings.map) : reachedOutputs(in.gbuffer, light);
    if (!anyReachable(in.gbuffer, in.light)) return out;   // V = 0 already
    StageTimer timer;
    // 2. The march.
    const ScreenMarch march(in.gbuffer, in.camera(), light, settings.march);
    const ScreenMarch::Mask mask = march.mask(in.simd);
    timer.lap("march");
    // 3. V = min(V_map, V_march), and the march's figures.
    const MarchCounts counts = combine(in.gbuffer, mask, out.visibility);
    timer.lap("combine");
    addStats(out, counts);
    timer.appendTo(out.stats);
    writeDebug(in, settings, march, mask);
    return out;
}

}  // namespace

Technique contactShadowsTechnique() {
    return {.name = kContactShadowsName,
            .description = "contact shadows (RTR 7.10, Sousa et al. 2011): a shadow map, and a march over the "
                           "camera's depth buffer that restores the shadows its bias loses at contacts",
            .params = contactShadowSettingsTable().specs(),
            .run = runContactShadows,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
