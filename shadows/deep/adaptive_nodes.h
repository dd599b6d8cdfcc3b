// Adaptive volumetric shadow maps' per-texel storage (Salvi, Vidimce, Lauritzen and Lefohn
// 2010, section 3.2): at most `capacity` (depth, transmittance) nodes, nearest first, the
// transmittance just behind each, compressed on the fly. A fragment of depth d that passes
// t becomes a node whose value is the one in front of it times t, and every node behind it
// is multiplied by t; when the list holds one node too many, the interior node whose
// removal changes the area under the piecewise-linear curve least is dropped (the first
// such on a tie). The array must have room for capacity + 1 nodes.
#pragma once

#include "shadows/deep/transmittance_curve.h"

namespace shadowlab {

struct AdaptiveNodes {
    CurveVertex* nodes;
    int count, capacity;

    void insert(float depth, float passed);

private:
    void removeCheapest();
};

}  // namespace shadowlab
