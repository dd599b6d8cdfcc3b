// The wall time of a technique's stages, so a user sees where a frame goes: each lap ends
// the stage that began at the previous lap (or when the timer was made) and is reported as
// the stat "<stage>_ms", after the technique's other figures, in the order the stages ran.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "shadows/technique.h"

namespace shadowlab {

class StageTimer {
public:
    void lap(const std::string& stage) {
        const auto now = std::chrono::steady_clock::now();
        laps_.push_back({stage + "_ms", std::chrono::duration<double, std::milli>(now - last_).count()});
        last_ = now;
    }

    void appendTo(std::vector<TechniqueStat>& stats) const { stats.insert(stats.end(), laps_.begin(), laps_.end()); }

private:
    std::vector<TechniqueStat> laps_;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace shadowlab
