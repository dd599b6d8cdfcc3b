// The hierarchical min/max shadow map (Real-Time Rendering, 4th ed., section 7.6: "two
// mipmaps can be formed, one saving the largest z-depth found in each area ..., and one the
// smallest. Given a texel location, depth, and area to be sampled, the mipmaps can be used
// to rapidly determine fully lit and fully shadowed conditions"). Level l holds, for every
// node of 2^l x 2^l texels, the least and the greatest window depth the map stores there
// (empty texels store 1). A map of any size halves by ceil(size / 2) per level until one
// node is left, so node n of level l covers texels [n 2^l, (n + 1) 2^l) on each axis. The
// chain starts at level 2 (4 x 4 texels): levels 0 and 1 would cost more to build and
// store than the taps they could save.
//
// A query for a rectangle of texels takes the first level whose nodes are at least as wide
// as the rectangle, where it meets at most 2 x 2 nodes: their depth range holds the
// rectangle's. It is conservative (the nodes can reach beyond the rectangle), never wrong.
//
// A receiver that lies in the map itself (a floor under its occluders) defeats the plain
// range: its own depths across a node span the plane's slope, so the node's least depth is
// nearer than the receiver's farthest point and nothing is proved (under 3% of PCSS's taps
// on the built-in scenes). So each node also keeps its depths as a plane plus a residual:
// a plane fit d(x, y) = depth + slopeX (x - xc) + slopeY (y - yc) about the node's centre
// (xc, yc) in texel units, and the least and greatest of stored - d over its non-empty
// texels (greatest = +inf if any is empty; both +inf if all are). Compared with the
// receiver's own plane, a floor's node then differs by its residual alone (a few depth
// steps, inside the compare's tolerance), so it is proved lit. The plane of a first-level node
// comes from its solid texels (mean slopes across its rows and columns, through their
// centroid), that of a higher node is the mean of its children's;
// the residual bounds are computed in double against the float plane the kernel reads,
// then rounded outwards.
#pragma once

#include <vector>

#include "shadows/depth_map.h"
#include "shadows/maps/lookup_kernel.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

struct DepthRange {
    float least = 1.0f;
    float greatest = 0.0f;
};

// A node's depths as a plane about its centre plus a residual range (see above).
struct NodePlane {
    float depth = 0.0f, slopeX = 0.0f, slopeY = 0.0f;
    float residualLow = 0.0f, residualHigh = 0.0f;
};

class MinMaxHierarchy {
public:
    explicit MinMaxHierarchy(const DepthMap& map);

    static constexpr int kFirstLevel = 2;
    int levels() const { return kFirstLevel - 1 + int(sizes_.size()); }   // levels kFirstLevel .. levels()
    int sizeOf(int level) const { return sizes_[size_t(level - kFirstLevel)]; }   // nodes per side
    DepthRange node(int level, int x, int y) const;
    NodePlane plane(int level, int x, int y) const;
    // The depths of the texels [x0, x1] x [y0, y1] (inclusive, clamped to the map) lie in
    // the range returned.
    DepthRange over(int x0, int y0, int x1, int y1) const;
    // Whether r.litBy answers lit at every texel of [x0, x1] x [y0, y1] (inside the map), by
    // the 2 x 2 nodes' planes and residuals: the double twin of the lookup kernel's proof
    // (lookup_kernel.inl, proveTaps). False proves nothing.
    bool provedLit(const MapReceiver& r, int x0, int y0, int x1, int y1) const;
    // The same for every texel of node (level, x, y) that lies in the map.
    bool nodeProvedLit(const MapReceiver& r, int level, int x, int y) const;
    // Whether r.litBy answers shadowed at every texel of node (level, x, y): none is empty,
    // and its greatest depth plus the compare's tolerance is nearer than the receiver's plane
    // anywhere over the node.
    bool nodeShadowed(const MapReceiver& r, int level, int x, int y) const;
    // A level as an image (row-major), for the debug views.
    std::vector<float> leastImage(int level) const { return levelImage(least_, level); }
    std::vector<float> greatestImage(int level) const { return levelImage(greatest_, level); }
    // The view the vector kernels read (lookup_kernel.h); valid while this object lives.
    const LookupHierarchy& forKernel() const { return kernel_; }

private:
    void buildFirstLevel(const DepthMap& map);
    void buildLevel(int level);
    void store(size_t n, const DepthRange& range, const NodePlane& p);
    std::vector<float> levelImage(const std::vector<float>& values, int level) const;
    size_t indexOf(int level, int x, int y) const {
        return size_t(offsets_[size_t(level - kFirstLevel)]) + size_t(y) * size_t(sizeOf(level)) + size_t(x);
    }

    int mapSize_ = 0;
    std::vector<int> sizes_, offsets_;   // per level from kFirstLevel: nodes per side, first node's index
    std::vector<float> least_, greatest_;
    std::vector<float> planeDepth_, slopeX_, slopeY_, residualLow_, residualHigh_;
    LookupHierarchy kernel_{};
};

// The level at which to read a region spanning `span` texels with at most `nodes` nodes per
// side: 0 (the texels) where they suffice, else the first of the hierarchy's that does.
int readingLevelFor(int span, int nodes, int levels);

// The receiver's plane depth at its least over node (level, x, y) of 2^level texels a side
// (level 0: a texel): a texel nearer than this, plus the compare's tolerance, is shadowed
// wherever it lies in the node.
double planeLeastOver(const MapReceiver& r, int level, int x, int y);

// The first level l >= MinMaxHierarchy::kFirstLevel at which a rectangle spanning `span`
// texels (x1 - x0 or y1 - y0, the larger) meets at most two nodes per axis: span < 2^l,
// capped at the top level.
int hierarchyLevelFor(int span, int levels);

}  // namespace shadowlab
