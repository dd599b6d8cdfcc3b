// Camera paths for fly-throughs (docs/flythrough.md): keyframes of the camera's eye and
// target, and optionally of the first light and of instances' transforms, read from a
// scene file's "flythrough" (or, without instances, a CSV file), and sampled at evenly
// spaced times.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "scenes/json_fields.h"
#include "scenes/scene.h"

namespace shadowlab {

// A path's frames are sampled at times evenly spaced from the first keyframe's time to the
// last's (frame 0 at the first keyframe, frame frames - 1 at the last; one frame: the
// first), each interpolated linearly between the two keyframes around it. Interpolation in
// straight lines keeps a move exactly as small as its keyframes say, which the sub-texel
// tests rely on; a curve is as many keyframes as it needs.
// An instance's pose is interpolated per field: translate and scale in straight lines, and
// each of rotate's three angles on its own (as a DCC tool's Euler curves): a turn about one
// axis turns at an even rate, exact at the keyframes; a turn about several is as many
// keyframes as it needs.
struct PathSample {
    double time = 0.0;
    glm::vec3 eye{0.0f}, target{0.0f};
    std::optional<glm::vec3> light;   // interpolated (placeOnPath normalises a direction)
    std::vector<InstancePlacement> placements;   // one per CameraPath::instances, in its order
};
PathSample samplePath(const CameraPath& path, int frame, int frames);

// The camera and lights of a sample: the eye and target moved, the first light moved to the
// sample's position (keeping its orientation) or turned to its direction, normalised. Throws
// std::invalid_argument naming the frame if the view frame is undefined there (the eye on
// the target between two keyframes).
void placeOnPath(const PathSample& sample, int frame, Camera& camera, std::vector<Light>& lights);

// A scene file's "flythrough": {"frames": N (optional), "keyframes": [{"time", "eye",
// "target", "light_position" or "light_direction" (optional, every keyframe or none),
// "instances" (optional, the same instances in every keyframe or none): [{"instance": its
// name or index, "translate", "rotate", "scale"}]}]}. `parts`: the placements' parts of the
// instances a keyframe may move, those of the file's "instances" entries (SceneNames).
// Throws SceneError naming the field.
CameraPath readCameraPath(const JsonField& field, const Scene& scene, std::span<const PathInstance> parts);

// A CSV file, one keyframe per line after a header naming the columns: time, eye_x, eye_y,
// eye_z, target_x, target_y, target_z, then optionally light_position_x, _y, _z or
// light_direction_x, _y, _z. Blank lines and lines starting with '#' are skipped. Throws
// SceneError naming the file and line.
CameraPath parseCameraPathCsv(const std::string& text, const std::string& file, const std::vector<Light>& lights);

}  // namespace shadowlab
