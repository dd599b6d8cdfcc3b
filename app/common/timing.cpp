#include "app/common/timing.h"

#include <stdexcept>

namespace shadowlab {

TimedFrames timeFrames(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings,
                       int warmupRuns, int runs, const ProgressStage& frames) {
    if (runs < 1) throw std::invalid_argument("the number of measured runs must be >= 1");
    for (int k = 0; k < warmupRuns; ++k) {
        renderFrame(prepared, technique, settings);
        frames.advance();
    }
    std::vector<double> ms;
    Frame frame;
    for (int k = 0; k < runs; ++k) {
        frame = renderFrame(prepared, technique, settings);
        ms.push_back(frame.techniqueMs);
        frames.advance();
    }
    return {summarizeTimes(std::move(ms)), std::move(frame)};
}

}  // namespace shadowlab
