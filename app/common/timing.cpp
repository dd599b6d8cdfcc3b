#include "app/common/timing.h"

#include <stdexcept>
#include <string_view>

namespace shadowlab {

void takeStageMedians(std::vector<TechniqueStat>& last, const std::vector<std::vector<TechniqueStat>>& runs) {
    for (TechniqueStat& stat : last) {
        if (!std::string_view(stat.name).ends_with("_ms")) continue;
        std::vector<double> ms;
        for (const std::vector<TechniqueStat>& run : runs) {
            for (const TechniqueStat& s : run)
                if (s.name == stat.name) ms.push_back(s.value);
        }
        stat.value = summarizeTimes(std::move(ms)).medianMs;
    }
}

TimedFrames timeFrames(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings,
                       int warmupRuns, int runs, const ProgressStage& frames) {
    if (runs < 1) throw std::invalid_argument("the number of measured runs must be >= 1");
    // A still view's warm-up frames follow one another; a path's frame starts every run from
    // the history it was entered with (timing.h).
    const bool onPath = settings.history != nullptr;
    const FrameHistory entering = onPath ? *settings.history : FrameHistory{};
    FrameHistory run;
    FrameSettings frameSettings = settings;
    frameSettings.history = &run;
    for (int k = 0; k < warmupRuns; ++k) {
        if (onPath) run = entering;
        renderFrame(prepared, technique, frameSettings);
        frames.advance();
    }
    const FrameHistory measuredFrom = onPath ? entering : run;
    std::vector<double> ms;
    std::vector<std::vector<TechniqueStat>> stats;
    Frame frame;
    for (int k = 0; k < runs; ++k) {
        run = measuredFrom;
        frame = renderFrame(prepared, technique, frameSettings);
        ms.push_back(frame.techniqueMs);
        stats.push_back(frame.shadow.stats);
        frames.advance();
    }
    if (onPath) *settings.history = std::move(run);
    takeStageMedians(frame.shadow.stats, stats);
    return {summarizeTimes(std::move(ms)), std::move(frame)};
}

}  // namespace shadowlab
