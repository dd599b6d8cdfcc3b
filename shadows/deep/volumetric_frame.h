// What every volumetric shadow map shares: the light's views (one frustum, or a point
// light's cube faces) and their opaque maps (a shadow map's resolution, bias and filter,
// shadows/maps/shadow_map_settings.h), the normal offset of the transmittance lookup, and
// the frame they all run per view: the light's layers, the opaque lookup, the technique's
// per-texel storage and its lookup (runVolumetricFrame).
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "shading/luminance.h"
#include "shadows/caster_transmission.h"
#include "shadows/debug_buffers.h"
#include "shadows/deep/curve_plot.h"
#include "shadows/deep/light_layers.h"
#include "shadows/deep/transmittance_lookup.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/stage_timer.h"
#include "shadows/technique.h"

namespace shadowlab {

struct VolumetricSettings {
    // Each texel holds a list or a curve, not one depth: a smaller map by default.
    ShadowMapSettings map{.resolution = 512};
    TransmittanceLookup lookup;
    bool cullCubeFaces = true;   // `cube-faces`, as shadow-map's
};

// The shadow map's parameters, `transmittance-offset` and `cube-faces`.
const SettingsTable<VolumetricSettings>& volumetricSettingsTable();

// The views a frame draws (fitLightViews, light_view.h): the one frustum fitted to the
// receivers, or, for a point light they surround, the cube faces that hold one (every face
// with `cube-faces=all`), as shadow-map draws them.
LightViews volumetricViews(const ShadowInputs& in, const Light& light, const VolumetricSettings& settings);

// The map selector (shadow_lookup.h) of view v alone: 0 where it serves the receiver at P,
// else -1. The one frustum serves every receiver; a receiver uses the first face whose
// pyramid holds it, as in shadow-map, and only that face answers it.
struct ServedBy {
    const LightViews& views;
    size_t v;
    int operator()(const glm::dvec3& P) const;
};

// The figures of a frame drawn through several views, each added once per view: a total
// sums them, a mean averages them (every view has as many texels), a most keeps the
// largest; reported in the order first added. With one view each is that view's value.
class VolumetricStats {
public:
    void total(const std::string& name, double value) { add(name, value, Combine::Total); }
    void mean(const std::string& name, double value) { add(name, value, Combine::Mean); }
    void most(const std::string& name, double value) { add(name, value, Combine::Most); }
    void appendTo(std::vector<TechniqueStat>& stats) const;

private:
    enum class Combine { Total, Mean, Most };
    struct Entry {
        TechniqueStat stat;
        Combine combine;
        int views;
    };
    void add(const std::string& name, double value, Combine combine);
    std::vector<Entry> entries_;
};

// The stages before a technique's own, through view v: the light's layers (stage `layers`)
// and the opaque lookup of the receivers the view serves (stage `opaque_lookup`), for a
// hard light (an area light's centre stands in).
struct VolumetricFrame {
    VolumetricLayers layers;
    std::vector<float> opaqueV;   // 0 where the view does not serve the pixel
    std::vector<int8_t> served;   // 0 where it does, -1 elsewhere
};
VolumetricFrame beginVolumetricFrame(const ShadowInputs& in, const Light& light, const LightViews& views, size_t v,
                                     const CasterTransmission& transmission, const VolumetricSettings& settings,
                                     StageTimer& timer);

// The stats every volumetric technique reports per view: fragments, volume pieces, events
// per texel, and the technique's bytes per texel.
void addVolumetricStats(const VolumetricFrame& frame, double bytesPerTexel, VolumetricStats& stats);

// Debug buffers every technique writes per view: the opaque map and the number of events
// per texel.
void writeVolumetricDebug(const DebugBuffers& debug, const VolumetricFrame& frame);

// The values of view v's lookup at the pixels it serves, into the frame's (all of them for
// the first view, whose values elsewhere are 0).
template <class Value>
void keepServed(std::vector<Value>&& passed, const std::vector<int8_t>& served, std::vector<Value>& frame) {
    if (frame.empty()) return void(frame = std::move(passed));
    for (size_t k = 0; k < served.size(); ++k) {
        if (served[k] == 0) frame[k] = passed[k];
    }
}

// One frame of a volumetric technique with its settings as read, per view
// (volumetricViews): the shared stages (beginVolumetricFrame), what the technique keeps per
// texel, `build(layers)` (timed as `stage`), the lookup of its `at(texel, depth)` at every
// receiver the view serves (a transmittance, or one per channel, which the frame shades with
// and whose luminance is V), and the figures and buffers every technique reports with the
// storage's own (`bytesPerTexel()`, `addStats(stats)`, `writeDebug(debug, layers)`), and
// maps_count, the views drawn.
template <class Build>
ShadowOutputs runVolumetricFrame(const ShadowInputs& in, const VolumetricSettings& settings, const std::string& technique,
                                 const char* stage, const Build& build) {
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const CasterTransmission transmission(in.casters().scene(), in.casterWorld());
    const Light light = pointLightFor(in.light);
    const LightViews views = volumetricViews(in, light, settings);
    timer.lap("light_view");
    using Value = decltype(build(std::declval<const VolumetricLayers&>()).at(size_t(0), 0.0f));
    std::vector<Value> passed;
    VolumetricStats stats;
    for (size_t v = 0; v < views.size(); ++v) {
        const VolumetricFrame frame = beginVolumetricFrame(in, light, views, v, transmission, settings, timer);
        const auto storage = build(frame.layers);
        timer.lap(stage);
        const auto curve = [&](size_t texel, float z) { return storage.at(texel, z); };
        keepServed(lookUpTransmittance(in.gbuffer, frame.layers.opaque, frame.opaqueV, settings.lookup, curve),
                   frame.served, passed);
        timer.lap("lookup");
        addVolumetricStats(frame, storage.bytesPerTexel(), stats);
        storage.addStats(stats);
        const DebugBuffers debug(in.debugDir, technique, views.suffix(v));
        if (debug.enabled()) {
            writeVolumetricDebug(debug, frame);
            storage.writeDebug(debug, frame.layers);
        }
        plotCurves(in.debugDir, technique, views.suffix(v), frame.layers, curve);
    }
    ShadowOutputs out;
    if constexpr (std::is_same_v<Value, glm::vec3>) {
        out.visibility.resize(passed.size());
        for (size_t k = 0; k < passed.size(); ++k) out.visibility[k] = luminance(passed[k]);
        out.colouredVisibility = std::move(passed);
    } else {
        out.visibility = std::move(passed);
    }
    stats.appendTo(out.stats);
    out.stats.push_back({"maps_count", double(views.size())});
    timer.appendTo(out.stats);
    return out;
}

}  // namespace shadowlab
