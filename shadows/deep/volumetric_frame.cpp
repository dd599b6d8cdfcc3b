#include "shadows/deep/volumetric_frame.h"

#include <algorithm>

#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_debug.h"

namespace shadowlab {

const SettingsTable<VolumetricSettings>& volumetricSettingsTable() {
    static const auto table =
        SettingsTable<VolumetricSettings>()
            .include(member(&VolumetricSettings::map), shadowMapSettingsTable())
            .real("transmittance-offset", member(&VolumetricSettings::lookup, &TransmittanceLookup::offsetTexels), 0.0,
                  100.0, "texels the receiver moves along its normal before the transmittance lookup")
            .choice("cube-faces", member(&VolumetricSettings::cullCubeFaces),
                    {{"visible", true, "only the faces whose pyramid holds a visible receiver"},
                     {"all", false, "all six (to measure the culling; the same V)"}},
                    "point lights their receivers surround");
    return table;
}

LightViews volumetricViews(const ShadowInputs& in, const Light& light, const VolumetricSettings& settings) {
    LightFitOptions fit;
    fit.resolution = settings.map.resolution;
    fit.simd = in.simd;
    fit.cullCubeFaces = settings.cullCubeFaces;
    return fitLightViews(light, in.gbuffer, in.casterWorld(), fit);
}

int ServedBy::operator()(const glm::dvec3& P) const {
    if (views.faces.empty()) return 0;
    size_t first = 0;
    while (first < views.size() && !insideCubeFace(views.views[first], P)) ++first;
    return first == v ? 0 : -1;
}

void VolumetricStats::add(const std::string& name, double value, Combine combine) {
    for (Entry& e : entries_) {
        if (e.stat.name != name) continue;
        e.stat.value = combine == Combine::Most ? std::max(e.stat.value, value) : e.stat.value + value;
        ++e.views;
        return;
    }
    entries_.push_back({{name, value}, combine, 1});
}

void VolumetricStats::appendTo(std::vector<TechniqueStat>& stats) const {
    for (const Entry& e : entries_) {
        stats.push_back({e.stat.name, e.combine == Combine::Mean ? e.stat.value / e.views : e.stat.value});
    }
}

VolumetricFrame beginVolumetricFrame(const ShadowInputs& in, const Light& light, const LightViews& views, size_t v,
                                     const CasterTransmission& transmission, const VolumetricSettings& settings,
                                     StageTimer& timer) {
    VolumetricFrame frame;
    frame.layers = renderVolumetricLayers(in, views.views[v], transmission,
                                          {settings.map.resolution, polygonOffsetFor(settings.map.bias)});
    timer.lap("layers");
    // The opaque map read in place, the one map of the lookup.
    ShadowLookup opaque = lookUpShadows(in.gbuffer, in.camera(), light, std::span(&frame.layers.opaque, 1),
                                        ServedBy{views, v}, settings.map.bias, makePcfKernel(settings.map.filter, in.frameIndex),
                                        in.simd);
    frame.opaqueV = std::move(opaque.visibility);
    frame.served = std::move(opaque.mapIndex);
    timer.lap("opaque_lookup");
    return frame;
}

void addVolumetricStats(const VolumetricFrame& frame, double bytesPerTexel, VolumetricStats& stats) {
    const VolumetricLayers& layers = frame.layers;
    const double texels = double(layers.size()) * double(layers.size());
    uint32_t most = 0;
    for (size_t t = 0; t + 1 < layers.start.size(); ++t) most = std::max(most, layers.eventCount(t));
    stats.most("resolution_texels", double(layers.size()));
    stats.total("translucent_fragments", double(layers.translucentFragments));
    stats.total("volume_pieces_count", double(layers.volumePieces));
    stats.mean("events_per_texel_mean_count", double(layers.start.back()) / texels);
    stats.most("events_per_texel_max_count", double(most));
    stats.mean("storage_per_texel_bytes", bytesPerTexel);
}

void writeVolumetricDebug(const DebugBuffers& debug, const VolumetricFrame& frame) {
    writeDepthMap(debug, "opaque-depth", frame.layers.opaque);
    const int size = frame.layers.size();
    std::vector<float> counts(size_t(size) * size_t(size));
    float most = 1.0f;
    for (size_t t = 0; t < counts.size(); ++t) most = std::max(most, counts[t] = float(frame.layers.eventCount(t)));
    debug.write("events-per-texel", size, size, counts, 0.0f, most);
}

}  // namespace shadowlab
