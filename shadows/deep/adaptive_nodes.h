// Adaptive volumetric shadow maps' per-texel storage (Salvi, Vidimce, Lauritzen and Lefohn
// 2010, section 3): at most `capacity` (depth, transmittance) nodes, nearest first, the
// curve linear between them, compressed on the fly. An occluder arrives as a segment, its
// entry and exit depths along the light's ray and the light it passes (section 3.1: a
// surface is a segment of no thickness, a step): its two nodes are inserted, the nodes
// inside it attenuated by the share of it in front of them and the nodes behind it by all
// of it. When the list holds more than `capacity` nodes, the interior node whose removal
// changes the area under the curve least is dropped (section 3.2: the first and the last
// node stay; the first such node on a tie), until it fits. The array must have room for
// capacity + 2 nodes.
#pragma once

#include "shadows/deep/transmittance_curve.h"

namespace shadowlab {

struct AdaptiveNodes {
    CurveVertex* nodes;
    int count, capacity;

    void insertSegment(float entry, float exit, float passed);

private:
    float behind(float z) const;
    void insertNode(int at, CurveVertex node);
    void removeCheapest();
};

}  // namespace shadowlab
