// A progress line for work that takes a while (`sweep`, `scaling`, `bench`, the exact
// references): "what done/total (percent), elapsed, ~estimate left", redrawn in place with
// '\r' on one line of a stream and ended with a newline when the work is done.
//
// The command that wants progress creates a Progress on stderr and hands a pointer down
// (through FrameSettings and ShadowInputs to a technique); a null pointer reports nothing.
// The work declares a ProgressStage and counts its units in it, from any thread. Nothing
// is drawn for a stage that ends within kDelay of its start, and the line is redrawn at
// most once per kInterval, so that counting a unit costs an atomic add and, when no other
// thread is drawing, a clock reading. Reporting reads only the counts: it never changes
// what the work computes.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <ostream>
#include <string>

namespace shadowlab {

class Progress {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr std::chrono::milliseconds kDelay{2000}, kInterval{100};

    // Draws on `out`, timing with `now` (a test passes its own clock).
    explicit Progress(std::ostream& out, std::function<Clock::time_point()> now = Clock::now);

private:
    friend class ProgressStage;
    void begin(std::string what, uint64_t total);
    void advance(uint64_t units);
    void end();
    void draw(Clock::time_point now);   // mutex_ held; writes only a changed line

    std::ostream& out_;
    const std::function<Clock::time_point()> now_;
    std::atomic<uint64_t> done_{0};
    std::mutex mutex_;                  // one thread draws at a time; guards the members below
    std::string what_;
    uint64_t total_ = 0;
    Clock::time_point start_, lastDraw_;
    std::string line_;                  // the current stage's line as drawn; empty: not drawn yet
};

// One stage of work reported on a Progress: `total` units, counted with advance(). Stages of
// one Progress follow one another; they do not nest. A null Progress reports nothing.
class ProgressStage {
public:
    ProgressStage(Progress* progress, std::string what, uint64_t total);
    ~ProgressStage();   // ends the line, if it was drawn, with the final count
    ProgressStage(const ProgressStage&) = delete;
    ProgressStage& operator=(const ProgressStage&) = delete;

    void advance(uint64_t units = 1) const;   // thread-safe

private:
    Progress* progress_;
};

}  // namespace shadowlab
