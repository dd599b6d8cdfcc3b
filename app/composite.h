// `shadowlab composite CASE`: differential rendering of a synthetic object's shadows into a
// photograph (Gibson et al. 2003; docs/differential-rendering.md). Preprocesses the case
// once, then for each frame of the object's path and each number of passes composites the
// frame (timed: the median of the runs after a warm-up), renders the exact differential
// reference, and writes the images, the intermediate buffers, the figures (JSON) and their
// plots: time against RMS per frame (time-rms.svg), the deepest shadow along the path,
// ours at each n and the reference's (shadow-depth.svg), and each frame from above with the
// shafts it touched and its clusters (plan-*.svg).
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

struct CompositeArgs {
    std::string scene = "room";                 // room, room-lift, outdoor, chessboard
    std::vector<int> passes{10, 20, 50, 0};      // 0: one per occluded source ("all")
    std::vector<int> frames;                     // of the path; empty: every frame
    int width = 640, height = 400, resolution = 256, shadowTriangles = 300;
    int runs = 1, warmupRuns = 0, threads = 0;
    double sourceShare = 0.7, significance = 0.02;
    std::vector<int> referenceStrata{8, 2};   // per side of an emitting and of a reflecting patch
    bool ldr = false, reference = true, masks = false;
    bool ldrError = false;               // Figure 3's experiment on the case's transfers (ldr-error.csv, .svg)
    bool referenceConvergence = false;   // also the reference at twice the strata per side, and the RMS between
    std::string outDir = "out/composite";
};

void runCompositeCommand(const CompositeArgs& args);

}  // namespace shadowlab
