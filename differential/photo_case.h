// The demonstration on a real photograph: OpenCV's sample photograph of a printed
// checkerboard (assets/photos/), its calibration, and the board's plane as the local model,
// one patch per printed square with the square's reflectance (white or black: the parity
// of squares the photograph shows brighter is white). The office's real light is unknown
// (no light probe was taken), so the light is an environment map we choose and state, as
// distant patches on a dome (environment_dome.h); the camera response's exposure is
// fitted so the model's white squares have the photograph's intensity, which makes the
// 8-bit path (section 7.1) the natural one here: the shadow is taken off the photograph's
// own values. Shown, not scored.
#pragma once

#include "differential/scene/compositing_scene.h"
#include "differential/scene/photo_calibration.h"
#include "shading/environment/environment_map.h"
#include "shading/image_io.h"

namespace shadowlab {

struct PhotoCase {
    CompositingScene scene;
    glm::ivec2 crop{0};          // the window of the photograph the camera sees
    double offAxisPixels = 0.0;  // how far its centre misses the principal point
};

// The board's 10 x 7 printed squares of 25 mm (the calibration's target frame: squares from
// -25 mm, the front facing -z) become the model's floor (the front facing +y). The object
// (a 10-unit mesh, scaled by 0.005) crosses the board in 5 frames. Throws
// std::invalid_argument when the photograph's size is not the calibration's or its white
// squares are black.
PhotoCase compositingChessboard(const Image8& photo, const PhotoCalibration& calibration, const EnvironmentMap& light,
                                const Mesh& object);

}  // namespace shadowlab
