// Reprojection: where a temporal technique finds its own result of the frame before
// (docs/temporal.md). Each pixel follows its motion vector (GBuffer::motion) into the
// previous image and takes the 2x2 texels around that point, weighted bilinearly, as TAA
// resolves and denoisers' temporal passes do (Schied et al. 2017, SVGF, section 4.1;
// Scherzer et al. 2007, section 3). A texel is kept only if it saw the same surface: its
// point lies on the plane of where this pixel's point was (the depth test) and its normal
// agrees (the normal test); the others get weight 0 and the kept ones share the weight.
// A pixel whose kept texels weigh less than kMinKeptWeight together is disoccluded, seen now
// but not then (a sliver of one texel alone is not its history): its history is rejected,
// and the technique starts it afresh.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "shading/gbuffer.h"
#include "shading/motion_vectors.h"

namespace shadowlab {

inline constexpr double kMinKeptWeight = 0.01;   // of the bilinear weights, as SVGF's resolve

struct ReprojectionSettings {
    // The depth test: a texel's point lies within this share of the previous eye's distance
    // from the plane (point and normal) of where this pixel's point was. 1% keeps a surface
    // seen at a grazing angle (its own plane: distance 0) and rejects one a step behind.
    double planeTolerance = 0.01;
    double minNormalCos = 0.9;   // the normal test: the two normals within 25.8 degrees
};

// Per pixel of the current frame, row-major (structure of arrays).
struct Reprojection {
    std::vector<glm::uvec4> texels;   // previous-image indices: top left, top right, bottom left, bottom right
    std::vector<glm::vec4> weights;   // theirs, summing to 1 over the kept texels; all 0: rejected
    std::vector<uint8_t> kept;        // 1 where some texel was kept (hit pixels only)
    size_t rejectedPixels = 0;        // hit pixels whose history was rejected
    size_t previousPixels = 0;        // the previous image's pixel count, which a history must have

    // The previous frame's values (indexed like PreviousView) resampled at `pixel`; a kept
    // pixel only.
    float resample(std::span<const float> previous, size_t pixel) const {
        const glm::uvec4& t = texels[pixel];
        const glm::vec4& w = weights[pixel];
        return w.x * previous[t.x] + w.y * previous[t.y] + w.z * previous[t.z] + w.w * previous[t.w];
    }
};

// Reprojects every pixel of `gbuffer` (which carries its motion) into `previous`. Throws
// std::invalid_argument if the G-buffer has no motion (a frame without a frame before) or
// the settings are outside planeTolerance > 0, minNormalCos in [-1, 1].
Reprojection reproject(const GBuffer& gbuffer, const PreviousView& previous, const ReprojectionSettings& settings);

// reproject() where the frame has a frame before and the history kept is of its size
// (historyPixels: a history written in another view cannot be read through this one's
// motion); none otherwise, and every pixel starts afresh.
std::optional<Reprojection> reprojectHistory(const GBuffer& gbuffer, const PreviousView* previous,
                                             size_t historyPixels, const ReprojectionSettings& settings);

// Throws std::logic_error (naming `who`) unless `history` has the previous image's pixel
// count: a history from another view (an older frame's, another size) read through this
// frame's motion would be read at the wrong places.
void requireHistoryOf(const Reprojection& reprojection, size_t historyPixels, const char* who);

}  // namespace shadowlab
