// Environment maps from files: OpenEXR (channels R, G, B; half or float, any compression
// OpenEXR 3 reads, lossy DWAB included) or Radiance HDR (RGBE, read by stb_image), in
// latitude-longitude layout (environment_map.h).
//
// Negative values, the ringing of a resampled or lossily compressed map around a sun, are
// clamped to 0 (radiance is never negative, and a negative lobe would subtract light in every
// integral of the map). Errors are std::runtime_error naming the file: a file it cannot read,
// a format it does not know, an 8-bit image (which holds display values, not radiance), a NaN
// or infinite texel (with its position), a map smaller than 2 x 1 or larger than the images
// shadowlab reads (scene_limits.h).
#pragma once

#include <filesystem>

#include "shading/environment/environment_map.h"

namespace shadowlab {

EnvironmentMap readEnvironmentMap(const std::filesystem::path& path, double rotationRadians = 0.0);

}  // namespace shadowlab
