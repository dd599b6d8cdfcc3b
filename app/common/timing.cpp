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
    for (int k = 0; k < warmupRuns; ++k) {
        renderFrame(prepared, technique, settings);
        frames.advance();
    }
    std::vector<double> ms;
    std::vector<std::vector<TechniqueStat>> stats;
    Frame frame;
    for (int k = 0; k < runs; ++k) {
        frame = renderFrame(prepared, technique, settings);
        ms.push_back(frame.techniqueMs);
        stats.push_back(frame.shadow.stats);
        frames.advance();
    }
    takeStageMedians(frame.shadow.stats, stats);
    return {summarizeTimes(std::move(ms)), std::move(frame)};
}

}  // namespace shadowlab
