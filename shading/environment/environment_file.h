// Environment maps from files, the format told by the first bytes: OpenEXR (channels R, G,
// B; half or float, any compression OpenEXR 3 reads, lossy DWAB included; image_io.h) or
// Radiance HDR (RGBE, radiance_hdr.h), in latitude-longitude layout (environment_map.h).
// The whole image is the sphere: an EXR's data window is what is read, and the aspect ratio
// is not checked (any W x H maps onto the sphere; lat-long maps are 2:1).
//
// Negative values, the ringing of a resampled or lossily compressed map around a sun, are
// clamped to 0 (radiance is never negative, and a negative lobe would subtract light in every
// integral of the map). Errors are std::runtime_error naming the file: a file it cannot read,
// neither format (an 8-bit image holds display values, not radiance), a truncated or corrupt
// file, a missing R, G or B channel, a NaN or infinite texel (with its position), a map
// smaller than 2 x 1 or larger than raster::kMaxViewport (8192) on a side.
#pragma once

#include <filesystem>
#include <string>

#include "shading/environment/environment_map.h"

namespace shadowlab {

EnvironmentMap readEnvironmentMap(const std::filesystem::path& path, double rotationRadians = 0.0);
// The same from a file's bytes already in memory; `name` names them in errors.
EnvironmentMap parseEnvironmentMap(const std::string& bytes, const std::string& name, double rotationRadians = 0.0);

}  // namespace shadowlab
