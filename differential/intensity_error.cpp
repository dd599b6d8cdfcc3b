#include "differential/intensity_error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "differential/intensity_transfer.h"
#include "shading/light_sampling.h"

namespace shadowlab {
namespace {

// Source s is in the first set when the running count of share * (s + 1) steps up: the
// first set's members spread evenly through the order (every other one at one half).
std::vector<uint8_t> twoSets(size_t count, double firstSetShare) {
    std::vector<uint8_t> set(count);
    for (size_t s = 0; s < count; ++s) {
        set[s] = std::floor(firstSetShare * double(s + 1)) > std::floor(firstSetShare * double(s)) ? 0 : 1;
    }
    return set;
}

struct ErrorSums {
    double squares = 0.0, largest = 0.0;
    size_t count = 0;
};

}  // namespace

std::vector<IntensityErrorPoint> intensityTransferError(const TransferTable& table, const CameraResponse& T,
                                                        double firstSetShare, int trials, uint64_t seed) {
    if (!(firstSetShare > 0.0 && firstSetShare < 1.0))
        throw std::invalid_argument("intensity error: the first set's share must be in (0, 1)");
    if (trials < 1) throw std::invalid_argument("intensity error: trials must be 1 or more");
    const size_t S = table.sources.size(), rows = table.vertices.size();
    const std::vector<uint8_t> set = twoSets(S, firstSetShare);
    // Per vertex, per P: the sums of its trials, added in vertex order afterwards.
    std::vector<ErrorSums> sums(rows * (S + 1));
    tbb::parallel_for(size_t(0), rows, [&](size_t r) {
        if (table.total[r] == glm::dvec3(0.0)) return;
        std::vector<glm::dvec3> L(S), intensity(S);
        for (size_t s = 0; s < S; ++s) L[s] = glm::dvec3(table.L[r * S + s]);
        intensityTransfers(table.total[r], std::span<const glm::dvec3>(L), std::span<const uint8_t>(set), T,
                           std::span(intensity));
        Pcg32 rng(seed, r);
        std::vector<uint32_t> order(S);
        for (size_t P = 0; P <= S; ++P) {
            ErrorSums& e = sums[r * (S + 1) + P];
            for (int t = 0; t < trials; ++t) {
                std::iota(order.begin(), order.end(), 0u);
                glm::dvec3 lost(0.0), taken(0.0);
                for (size_t k = 0; k < P; ++k) {   // the first P of a random permutation
                    std::swap(order[k], order[k + rng.next() % uint32_t(S - k)]);
                    lost += L[order[k]], taken += intensity[order[k]];
                }
                const glm::dvec3 error = (T(table.total[r]) - taken) - T(table.total[r] - lost);
                for (int c = 0; c < 3; ++c) {
                    e.squares += error[c] * error[c], e.largest = std::max(e.largest, std::abs(error[c]));
                    ++e.count;
                }
            }
        }
    });
    std::vector<IntensityErrorPoint> points;
    for (size_t P = 0; P <= S; ++P) {
        ErrorSums total;
        for (size_t r = 0; r < rows; ++r) {
            const ErrorSums& e = sums[r * (S + 1) + P];
            total.squares += e.squares, total.largest = std::max(total.largest, e.largest), total.count += e.count;
        }
        points.push_back({int(P), total.count ? std::sqrt(total.squares / double(total.count)) : 0.0, total.largest});
    }
    return points;
}

}  // namespace shadowlab
