// Gibson et al. 2003, Figure 3's experiment: how far the 8-bit path's result lies from the
// truth as more of a vertex's sources are occluded. At every receiver vertex with light,
// the intensity transfers S_ij are made with the sources split into two sets (section 7.1,
// intensity_transfer.h); then, for P occluded sources chosen at random, the estimate
// T(L_i) - sum S_ij is compared with the truth T(L_i - sum L_ij), both unrounded 8-bit
// intensities. The estimate is exact for P = 0 and when the occluded sources are one set.
#pragma once

#include <cstdint>
#include <vector>

#include "differential/scene/compositing_scene.h"
#include "differential/transfers.h"

namespace shadowlab {

struct IntensityErrorPoint {
    int occluded;          // P, of the table's sources
    double rmsLevels;      // RMS over vertices, trials and channels, in 8-bit levels
    double largestLevels;  // the largest of them
};

// `firstSetShare` of the sources (spread evenly through the order, brightest first) form the
// first set: 0.5 is the paper's even/odd split. One point per P from 0 to every source, each
// from `trials` random subsets per vertex (a PCG stream per vertex, so any thread count
// gives the same figures). Throws std::invalid_argument for a share outside (0, 1) or
// trials < 1.
std::vector<IntensityErrorPoint> intensityTransferError(const TransferTable& table, const CameraResponse& T,
                                                        double firstSetShare, int trials, uint64_t seed = 7);

}  // namespace shadowlab
