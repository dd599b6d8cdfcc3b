#include "shadows/backprojection/light_bitmask.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace shadowlab {

LightBitmask& LightBitmask::operator|=(const LightBitmask& o) {
    for (size_t j = 0; j < rows.size(); ++j) rows[j] |= o.rows[j];
    return *this;
}

LightGrid::LightGrid(int n, bool disk) : n_(n) {
    if (n < 1 || n > kMaxLightSamplesPerAxis) {
        throw std::invalid_argument("light bitmask: 1 to " + std::to_string(kMaxLightSamplesPerAxis) +
                                    " samples per axis, not " + std::to_string(n));
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const float a = centre(i), b = centre(j);
            if (disk && a * a + b * b > 1.0f) continue;
            onLight_.rows[size_t(j)] |= 1u << i;
            ++count_;
        }
    }
}

// The cells [ceil(first), floor(last)] whose centres -1 + (2 i + 1) / n lie in [lo, hi],
// clamped to the grid in float before any conversion (a patch corner near the receiver's
// own height projects arbitrarily far out); empty where lo > hi or either is NaN.
std::pair<int, int> LightGrid::cells(float lo, float hi) const {
    const float first = std::ceil((lo + 1.0f) * 0.5f * float(n_) - 0.5f);
    const float last = std::floor((hi + 1.0f) * 0.5f * float(n_) - 0.5f);
    if (!(first <= last) || !(first <= float(n_ - 1)) || !(last >= 0.0f)) return {1, 0};
    return {int(std::max(first, 0.0f)), int(std::min(last, float(n_ - 1)))};
}

uint32_t LightGrid::span(float lo, float hi) const {
    const auto [i0, i1] = cells(lo, hi);
    if (i0 > i1) return 0u;
    const uint32_t upTo = i1 == 31 ? ~0u : (2u << i1) - 1u;
    return upTo & ~((1u << i0) - 1u);
}

void LightGrid::cover(LightBitmask& mask, const glm::vec2* v, int count) const {
    float bLow = v[0].y, bHigh = v[0].y;
    for (int k = 1; k < count; ++k) bLow = std::min(bLow, v[k].y), bHigh = std::max(bHigh, v[k].y);
    const auto [j0, j1] = cells(bLow, bHigh);
    for (int j = j0; j <= j1; ++j) {
        // The polygon's extent along the row b = centre(j): where the row crosses its edges.
        const float b = centre(j);
        float lo = 2.0f, hi = -2.0f;
        for (int k = 0; k < count; ++k) {
            const glm::vec2 p = v[k], q = v[(k + 1) % count];
            if ((p.y - b) * (q.y - b) > 0.0f) continue;   // the edge does not reach the row
            if (p.y == q.y) {                              // along the row: both ends
                lo = std::min({lo, p.x, q.x}), hi = std::max({hi, p.x, q.x});
                continue;
            }
            const float a = p.x + (q.x - p.x) * ((b - p.y) / (q.y - p.y));
            lo = std::min(lo, a), hi = std::max(hi, a);
        }
        if (lo <= hi) mask.rows[size_t(j)] |= span(lo, hi);
    }
}

void LightGrid::coverHalfPlane(LightBitmask& mask, double alpha, double beta, double gamma) const {
    if (gamma > std::abs(alpha) + std::abs(beta)) return;   // the whole square above the plane: nothing hidden
    for (int j = 0; j < n_; ++j) {
        const double c = beta * centre(j) + gamma;             // alpha a + c <= 0
        if (alpha == 0.0) {
            if (c <= 0.0) mask.rows[size_t(j)] |= onLight_.rows[size_t(j)];
            continue;
        }
        const float edge = float(-c / alpha);   // hidden: a <= edge (alpha > 0) or a >= edge (alpha < 0)
        mask.rows[size_t(j)] |= alpha > 0.0 ? span(-2.0f, edge) : span(edge, 2.0f);
    }
}

bool LightGrid::full(const LightBitmask& mask) const {
    for (int j = 0; j < n_; ++j) {
        if ((mask.rows[size_t(j)] & onLight_.rows[size_t(j)]) != onLight_.rows[size_t(j)]) return false;
    }
    return true;
}

int LightGrid::hidden(const LightBitmask& mask) const {
    int count = 0;
    for (int j = 0; j < n_; ++j) count += std::popcount(mask.rows[size_t(j)] & onLight_.rows[size_t(j)]);
    return count;
}

}  // namespace shadowlab
