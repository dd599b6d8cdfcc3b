// Summary of repeated time measurements, as every benchmark here reports them
// (style.md, "benchmarks are repeatable protocols"): the median and the minimum; and the
// protocol by which sweep, scaling and flythrough time a technique's frames.
#pragma once

#include <algorithm>
#include <vector>

#include "frame/render.h"
#include "shadows/progress.h"

namespace shadowlab {

struct Timing {
    double medianMs = 0.0, minMs = 0.0;
};

// ms must not be empty; an even count takes the mean of the two middle values.
inline Timing summarizeTimes(std::vector<double> ms) {
    std::sort(ms.begin(), ms.end());
    const size_t n = ms.size();
    return {n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]), ms.front()};
}

// A stage's time (the "<stage>_ms" stats of shadows/stage_timer.h) moves from frame to frame
// as the frame's does: each of `last`'s becomes its median over `runs` (every measured frame's
// stats, `last`'s included), as Timing summarizes the whole; the other stats are the same in
// every frame and stay as they are.
void takeStageMedians(std::vector<TechniqueStat>& last, const std::vector<std::vector<TechniqueStat>>& runs);

// Warm-up frames, then `runs` measured frames; the median and minimum of
// Frame::techniqueMs, and the last frame, its stage times ("<stage>_ms" stats) replaced by
// their medians over the measured frames. Every frame, warm-up ones included, is counted in
// `frames`.
//
// What the frames keep (FrameHistory) follows the view. A still view (settings.history
// null: sweep, scaling) is a steady state: its warm-up frames follow one another, as an
// engine's frames of an unchanging view would, and each measured frame starts from where
// they left it; with no warm-up frame, from nothing (a first frame). A frame of a path
// (settings.history given: flythrough) starts every run, warm-up or measured, from the
// history the frames before it left, which it then replaces with its last run's. Every
// measured frame so does the same work from the same state.
struct TimedFrames {
    Timing timing;
    Frame last;
};
TimedFrames timeFrames(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings,
                       int warmupRuns, int runs, const ProgressStage& frames);

}  // namespace shadowlab
