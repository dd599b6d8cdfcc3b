// The hierarchical min/max shadow map (Real-Time Rendering, 4th ed., section 7.6: "two
// mipmaps can be formed, one saving the largest z-depth found in each area ..., and one the
// smallest. Given a texel location, depth, and area to be sampled, the mipmaps can be used
// to rapidly determine fully lit and fully shadowed conditions"). Level l >= 1 holds, for
// every node of 2^l x 2^l texels, the least and the greatest window depth the map stores
// there (empty texels store 1). A map of any size halves by ceil(size / 2) per level until
// one node is left, so node n of level l covers texels [n 2^l, (n + 1) 2^l) on each axis.
//
// A query for a rectangle of texels takes the first level whose nodes are at least as wide
// as the rectangle, where it meets at most 2 x 2 nodes: their depth range holds the
// rectangle's. It is conservative (the nodes can reach beyond the rectangle), never wrong.
#pragma once

#include <vector>

#include "shadows/depth_map.h"
#include "shadows/maps/lookup_kernel.h"

namespace shadowlab {

struct DepthRange {
    float least = 1.0f;
    float greatest = 0.0f;
};

class MinMaxHierarchy {
public:
    explicit MinMaxHierarchy(const DepthMap& map);

    int levels() const { return int(sizes_.size()); }        // levels 1 .. levels()
    int sizeOf(int level) const { return sizes_[size_t(level - 1)]; }   // nodes per side
    DepthRange node(int level, int x, int y) const;
    // The depths of the texels [x0, x1] x [y0, y1] (inclusive, clamped to the map) lie in
    // the range returned.
    DepthRange over(int x0, int y0, int x1, int y1) const;
    // A level as an image (row-major), for the debug views.
    std::vector<float> leastImage(int level) const;
    std::vector<float> greatestImage(int level) const;
    // The view the vector kernels read (lookup_kernel.h); valid while this object lives.
    const LookupHierarchy& forKernel() const { return kernel_; }

private:
    int mapSize_ = 0;
    std::vector<int> sizes_, offsets_;   // per level from 1: nodes per side, first node's index
    std::vector<float> least_, greatest_;
    LookupHierarchy kernel_{};
};

// The first level l >= 1 at which a rectangle spanning `span` texels (x1 - x0 or y1 - y0,
// the larger) meets at most two nodes per axis: span < 2^l, capped at the top level.
int hierarchyLevelFor(int span, int levels);

}  // namespace shadowlab
