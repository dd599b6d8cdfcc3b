// A photograph's pinhole calibration as OpenCV gives it (the format of
// assets/photos/chessboard_left05_camera.txt: "key value..." lines, '#' comments): the image
// size, the intrinsics K and the pose of a planar target, X_camera = R X_target + t, in the
// OpenCV camera frame (x right, y down, z forward; pixel centres at whole coordinates).
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct PhotoCalibration {
    int width = 0, height = 0;
    double fx = 0, fy = 0, cx = 0, cy = 0;
    glm::dmat3 R{1.0};    // target -> camera rotation
    glm::dvec3 t{0.0};    // target -> camera translation, metres
};

// Throws std::runtime_error naming the file for a missing file, a missing or malformed
// image_size, K, R or tvec line, a K with skew or non-positive focal lengths, or an R that
// is not a rotation (to 1e-4).
PhotoCalibration readPhotoCalibration(const std::string& path);

// Whether m is a rotation: orthonormal to 1e-4 in each entry of m^T m, determinant +1.
bool isRotation(const glm::dmat3& m);
// Whether m is a rigid transform: a rotation, a translation and a last row of 0 0 0 1.
bool isRigid(const glm::dmat4& m);

// Our camera for the calibration, in the world frame `worldFromTarget` places the target in
// (a rigid transform): the same centre, axes and focal lengths, on the largest window of
// whole pixels centred on the principal point (our cameras are symmetric; conventions.md).
// `crop` gets the window's first column and row in the photograph, and `offAxisPixels` how
// far (in pixels) the principal point misses the window's centre (under 0.71 by
// construction: half a pixel on each axis).
// Throws std::invalid_argument when fx and fy differ by more than 1% (square pixels only)
// or worldFromTarget is not rigid.
Camera cameraOf(const PhotoCalibration& calibration, const glm::dmat4& worldFromTarget, glm::ivec2& crop,
                double& offAxisPixels);

}  // namespace shadowlab
