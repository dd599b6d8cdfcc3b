// The wall time of a technique's stages, so a user sees where a frame goes: each lap ends
// the stage that began at the previous lap (or when the timer was made) and is reported as
// the stat "<stage>_ms", after the technique's other figures, in the order the stages first
// ran; a stage that runs again (once per cube face, say) adds to its time.
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
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        const std::string name = stage + "_ms";
        for (TechniqueStat& lap : laps_) {
            if (lap.name == name) return void(lap.value += ms);
        }
        laps_.push_back({name, ms});
    }

    void appendTo(std::vector<TechniqueStat>& stats) const { stats.insert(stats.end(), laps_.begin(), laps_.end()); }

private:
    std::vector<TechniqueStat> laps_;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace shadowlab
