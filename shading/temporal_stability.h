// Temporal stability of a technique along a camera or light path (docs/conventions.md,
// "Flicker"): between consecutive frames, the change |V_t - V_(t-1)| of the technique's
// visibility on the pixels where the exact reference's visibility did not change. A
// moving camera sees other surface points, so some change is right; on pixels where the
// reference stays put, every change is flicker the technique adds (shadow-map texels
// swimming under the camera, a PCF kernel rotating, a cascade switching).
#pragma once

#include <cstdint>
#include <string>

#include "shading/image_io.h"

namespace shadowlab {

// The reference's V "did not change" if it moved by at most this much: one step of an
// 8-bit display, so that the soft reference's sub-display changes in a penumbra the camera
// slides over still count as unchanged, while the hard reference's are exactly 0 or 1.
inline constexpr float kStableReferenceTolerance = 1.0f / 256.0f;

struct FlickerFigures {
    uint64_t pixels = 0;         // hit in both frames of the reference
    uint64_t stablePixels = 0;   // of those, the reference's V changed by at most the tolerance
    // |V_t - V_(t-1)| of the test over the stable pixels (0 if there are none); NaN in a
    // test image makes both NaN.
    double mean = 0.0;
    double p99 = 0.0;            // the 99th percentile, by nearest rank: the ceil(0.99 n)-th smallest
    double stablePercent() const { return pixels == 0 ? 0.0 : 100.0 * double(stablePixels) / double(pixels); }
};

// Frames t - 1 and t of a reference (channels hit and `channel`) and of a test (`channel`),
// all of one size. Throws std::invalid_argument if the sizes differ or a channel is missing.
FlickerFigures flickerFigures(const ImageChannels& previousReference, const ImageChannels& reference,
                              const ImageChannels& previousTest, const ImageChannels& test,
                              const std::string& channel = "V", float tolerance = kStableReferenceTolerance);

}  // namespace shadowlab
