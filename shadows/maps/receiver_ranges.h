// The range of values over the receivers a map serves (the G-buffer's hit pixels), for the
// fits that bound them: LiSPSM's light-space and warped extents, csm's sample bounds.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "shading/gbuffer.h"

namespace shadowlab {

struct Range {
    double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
    void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }   // a NaN leaves it as it is
    void add(const Range& r) { lo = std::min(lo, r.lo), hi = std::max(hi, r.hi); }
    void widen(double fraction) {
        const double m = (hi - lo) * fraction;
        lo -= m, hi += m;
    }
};

// The ranges of the N coordinates of values(P) (a glm::vec<N, double>) over the hit pixels,
// in parallel: a minimum or maximum is exact in any order, so the thread count does not
// change them.
template <glm::length_t N, class Values>
std::array<Range, N> receiverRanges(const GBuffer& g, Values values) {
    using Ranges = std::array<Range, N>;
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, g.pixelCount(), 16384), Ranges{},
        [&](const tbb::blocked_range<size_t>& r, Ranges ranges) {
            for (size_t k = r.begin(); k != r.end(); ++k) {
                if (!g.hit[k]) continue;
                const glm::vec<N, double> v = values(glm::dvec3(g.position[k]));
                for (glm::length_t c = 0; c < N; ++c) ranges[c].add(v[c]);
            }
            return ranges;
        },
        [](Ranges a, const Ranges& b) {
            for (glm::length_t c = 0; c < N; ++c) a[c].add(b[c]);
            return a;
        });
}

}  // namespace shadowlab
