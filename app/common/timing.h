// Summary of repeated time measurements, as every benchmark here reports them
// (style.md, "benchmarks are repeatable protocols"): the median and the minimum.
#pragma once

#include <algorithm>
#include <vector>

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

}  // namespace shadowlab
