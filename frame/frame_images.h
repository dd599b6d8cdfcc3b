// The pictures of a frame that a report shows (`sweep --images`, `render --error-map
// --json`): the tone-mapped image, the error map against the reference, V as grey, the
// reference's own image and V, and the technique's debug buffers. The JSON that lists them
// holds their paths relative to its own directory, so a folder of results can move whole.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "frame/render.h"
#include "shading/image_io.h"
#include "shading/tonemap.h"

namespace shadowlab {

struct FrameImages {
    std::string image;                       // tone-mapped sRGB PNG (writeFramePictures' tone)
    std::string errorMap;                    // errorMapImage() against the reference
    std::string visibility;                  // V, 0 black to 1 white (visibility techniques; meanVisibility())
    std::string referenceImage, referenceVisibility;   // the same of the reference
    std::vector<std::string> debugBuffers;   // the PNG and SVG pictures, by name
    bool empty() const;
};

// The V a picture shows: the light's, or with several lights their mean, in the order of
// the lights (each light's V is in the frame's EXR, conventions.md).
std::vector<float> meanVisibility(const Frame& frame);

// Writes FOLDER/NAME-image.png (tone mapped with `tone`), FOLDER/NAME-error-map.png if
// `reference` is given (the frame's scoredImage() against it) and, for a visibility frame,
// FOLDER/NAME-visibility.png; returns their paths relative to `base` (creates FOLDER if
// missing; an empty FOLDER is the working directory).
FrameImages writeFramePictures(const std::filesystem::path& base, const std::filesystem::path& folder,
                               const std::string& name, const Frame& frame, const ImageChannels* reference,
                               const ToneMapOptions& tone = {});

// The pictures of a technique's debug buffers: the PNG and SVG files directly in
// `directory` whose names start with "TECHNIQUE-" but not with the name of a technique that
// extends it ("reference-soft-" is not reference's), sorted, relative to `base` (none if the
// directory does not exist); then, for a frame of several lights, those of each light's
// folder (lightDebugFolder(): light0/, light1/, ... as far as they run without a gap).
std::vector<std::string> debugPictures(const std::filesystem::path& base, const std::filesystem::path& directory,
                                       const std::string& technique);

// The light a debug picture of debugPictures() belongs to: K for one in a folder
// lightDebugFolder(K), none for one of a frame of one light.
std::optional<size_t> debugPictureLight(const std::string& path);

// `path` relative to `base`, '/'-separated, without touching the file system.
std::string relativePath(const std::filesystem::path& path, const std::filesystem::path& base);

// `images` with `change` applied to each path that is set.
FrameImages withPaths(const FrameImages& images, const std::function<std::string(const std::string&)>& change);

// Every path of `images`, relative to `from`, made relative to `to` instead.
FrameImages rebased(const FrameImages& images, const std::filesystem::path& from, const std::filesystem::path& to);

// {"image", "error_map", "visibility", "reference_image", "reference_visibility",
//  "debug_buffers": [...]}, only the fields that are set.
std::string formatFrameImagesJson(const FrameImages& images);

}  // namespace shadowlab
