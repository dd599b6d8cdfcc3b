#include "shadows/temporal/temporal_accumulation.h"

#include <stdexcept>
#include <utility>

#include "shadows/debug_buffers.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

// What the technique keeps between frames (technique_history.h): the last frame's result.
struct AccumulationHistory {
    AccumulatedFrame last, next;
};

void writeBuffers(const ShadowInputs& in, const std::string& technique, const AccumulatedFrame& result,
                  const AccumulationBuffers& buffers, const std::vector<float>& current, float cap) {
    const DebugBuffers debug(in.debugDir, technique);
    const int w = result.width, h = result.height;
    debug.write("temporal-current", w, h, current, 0.0f, 1.0f);
    debug.write("temporal-reprojected", w, h, buffers.reprojected, 0.0f, 1.0f);
    debug.write("temporal-clamped", w, h, buffers.clamped, 0.0f, 1.0f);
    debug.write("temporal-frames", w, h, result.frames, 0.0f, cap);
}

}  // namespace

const SettingsTable<TemporalSettings>& temporalSettingsTable() {
    using S = TemporalSettings;
    static const auto table =
        SettingsTable<S>()
            .flag("temporal", member(&S::on), "accumulate V over the frames of a sequence (reprojected)")
            .integer("temporal-frames", member(&S::accumulation, &AccumulationSettings::maxFrames), 1, 65535,
                     "temporal: frames a pixel's history holds at most (blend weight 1 / n)")
            .choice("temporal-clamp", member(&S::accumulation, &AccumulationSettings::clamp),
                    {{"off", HistoryClamp::Off},
                     {"minmax", HistoryClamp::MinMax, "3x3 neighbourhood's range"},
                     {"variance", HistoryClamp::Variance, "3x3 mean +- gamma sigma"}},
                    "temporal: the history clamped to this frame's neighbourhood")
            .real("temporal-gamma", member(&S::accumulation, &AccumulationSettings::varianceGamma), 0.01, 16.0,
                  "temporal-clamp=variance: the box's half-width in standard deviations");
    return table;
}

Technique withTemporalAccumulation(Technique technique) {
    for (const ParamSpec& spec : temporalSettingsTable().specs()) technique.params.push_back(spec);
    technique.run = [inner = std::move(technique.run), name = technique.name](const ShadowInputs& in) {
        const TemporalSettings s = temporalSettingsTable().read(in.params);
        ShadowOutputs out = inner(in);
        if (!s.on) return out;
        if (!out.colouredVisibility.empty())
            throw std::invalid_argument(name + ": temporal accumulation of tinted casters' coloured V is not built; "
                                               "give temporal=off");
        StageTimer timer;
        AccumulationHistory& history = in.kept().state<AccumulationHistory>();
        const std::optional<Reprojection> reprojection =
            reprojectHistory(in.gbuffer, in.previous, history.last.value.size(), s.reprojection);
        AccumulationBuffers buffers;
        accumulate(out.visibility, in.gbuffer, reprojection ? &*reprojection : nullptr, history.last, s.accumulation,
                   history.next, in.debugDir.empty() ? nullptr : &buffers);
        if (!in.debugDir.empty())
            writeBuffers(in, name, history.next, buffers, out.visibility, float(s.accumulation.maxFrames));
        out.visibility = history.next.value;
        std::swap(history.last, history.next);
        timer.lap("temporal");
        double frames = 0.0;
        size_t hits = 0;
        for (size_t k = 0; k < in.gbuffer.pixelCount(); ++k) {
            if (in.gbuffer.hit[k]) frames += history.last.frames[k], ++hits;
        }
        out.stats.push_back({"history_rejected_pixels", reprojection ? double(reprojection->rejectedPixels) : 0.0});
        out.stats.push_back({"history_frames_mean_count", hits ? frames / double(hits) : 0.0});
        timer.appendTo(out.stats);
        return out;
    };
    return technique;
}

}  // namespace shadowlab
