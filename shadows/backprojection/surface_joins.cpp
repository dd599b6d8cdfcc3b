// Gap closing's joins (surface_joins.h). What edgeRatio (8 by default) allows for, twice
// over: 1 for the surface itself; 1.5 for the slope-scaled polygon offset the map is drawn
// with (1.5 texels of each triangle's steepest slope, so it changes from facet to facet;
// along a line that runs across a steep slope the change exceeds the steps along the line,
// which is why the steps across it count too); and faces only a texel or two wide (a box's
// side seen grazing), whose steps beside lie on the next face (about 4 on two-heights'
// rail). Two-heights' plate and its rail moved partly under the plate's edge stay apart up
// to 100.
//
// What the depths cannot tell apart: a steep silhouette in front of a surface that goes on
// behind it (joined: right) from one in front of a surface that ends there (joined too: a
// skirt, too dark); a flat edge in front of a farther surface stays apart either way (one
// depth layer: what it hides is lost).
//
// Rows run in parallel and each writes its own nodes' bits: the same bytes for any thread
// count.
#include "shadows/backprojection/surface_joins.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// Float steps (2^-23 of the larger window depth: one or two ulps) that rounding can add to a
// step between neighbours beyond the steps beside it: each stored depth is within half an
// ulp of its surface's, so a plane's steps differ by up to two, and the polygon offset's
// constant part (4 ulps: BiasSettings' default, which renderPcssMap draws with) by a few
// more where the depths cross a power of two.
constexpr double kDepthRoundingSteps = 8.0;

// The depths of one level (a node's: its least), read once into rows with a border of one
// node before and two after, the border nodes' copied (so no step lies beyond the map).
class LevelDepths {
public:
    LevelDepths(const DepthMap& map, const MinMaxHierarchy& hierarchy, int level)
        : size(level == 0 ? map.size : hierarchy.sizeOf(level)), depths_(size_t(size + 3) * size_t(size + 3)) {
        for (int y = -1; y <= size + 1; ++y) {
            for (int x = -1; x <= size + 1; ++x) {
                const int cx = std::clamp(x, 0, size - 1), cy = std::clamp(y, 0, size - 1);
                depths_[index(x, y)] = level == 0 ? map.at(cx, cy) : hierarchy.node(level, cx, cy).least;
            }
        }
    }

    double operator()(int x, int y) const { return depths_[index(x, y)]; }

    const int size;

private:
    size_t index(int x, int y) const { return size_t(y + 1) * size_t(size + 3) + size_t(x + 1); }

    std::vector<float> depths_;
};

// Whether node (x, y) and its neighbour (x + dx, y + dy) lie on one surface: the step
// between them is at most edgeRatio times the largest step beside it, give or take rounding.
bool oneSurface(const LevelDepths& at, int x, int y, int dx, int dy, double edgeRatio) {
    const double a = at(x, y), b = at(x + dx, y + dy);
    const double step = std::abs(b - a), rounding = kDepthRoundingSteps * std::ldexp(std::max(a, b), -23);
    const double along = std::max(std::abs(a - at(x - dx, y - dy)), std::abs(at(x + 2 * dx, y + 2 * dy) - b));
    if (step <= edgeRatio * along + rounding) return true;
    const auto across = [&](int u, int v, double here) {   // the smaller one-sided step across the line
        return std::min(std::abs(here - at(u - dy, v - dx)), std::abs(at(u + dy, v + dx) - here));
    };
    return step <= edgeRatio * std::max(across(x, y, a), across(x + dx, y + dy, b)) + rounding;
}

std::vector<uint8_t> levelJoins(const LevelDepths& at, double edgeRatio) {
    std::vector<uint8_t> joins(size_t(at.size) * size_t(at.size), 0);
    tbb::parallel_for(0, at.size, [&](int y) {
        for (int x = 0; x < at.size; ++x) {
            uint8_t& bits = joins[size_t(y) * size_t(at.size) + size_t(x)];
            if (x + 1 < at.size && oneSurface(at, x, y, 1, 0, edgeRatio)) bits |= 1u;
            if (y + 1 < at.size && oneSurface(at, x, y, 0, 1, edgeRatio)) bits |= 2u;
        }
    });
    return joins;
}

// Index into sizes_ and joins_ of a level: 0, or the hierarchy's from kFirstLevel.
size_t slotOf(int level) { return level == 0 ? 0 : size_t(level - MinMaxHierarchy::kFirstLevel + 1); }

}  // namespace

SurfaceJoins::SurfaceJoins(const DepthMap& map, const MinMaxHierarchy& hierarchy, double edgeRatio) {
    for (int level = 0; level <= hierarchy.levels(); level = level == 0 ? MinMaxHierarchy::kFirstLevel : level + 1) {
        const LevelDepths depths(map, hierarchy, level);
        sizes_.push_back(depths.size);
        joins_.push_back(levelJoins(depths, edgeRatio));
    }
}

bool SurfaceJoins::bit(int level, int x, int y, uint8_t which) const {
    const size_t slot = slotOf(level);
    const int size = sizes_[slot];
    if (x < 0 || y < 0 || x >= size || y >= size) return false;
    return (joins_[slot][size_t(y) * size_t(size) + size_t(x)] & which) != 0;
}

}  // namespace shadowlab
