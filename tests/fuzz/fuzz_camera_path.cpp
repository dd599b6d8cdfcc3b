// libFuzzer target: a fly-through's keyframes as CSV (scenes/camera_path.cpp) on arbitrary
// text, for a scene whose first light is a point light and for one whose is the sun; a path
// that reads is then sampled and placed at a few frames, which may refuse a frame whose view
// is undefined (std::invalid_argument) but nothing else.
#include <stdexcept>

#include "fuzz_target.h"
#include "scenes/camera_path.h"
#include "scenes/scene_error.h"

namespace {

void readAndPlace(const std::string& text, shadowlab::LightType type) {
    std::vector<shadowlab::Light> lights(1);
    lights[0].type = type;
    const shadowlab::CameraPath path = shadowlab::parseCameraPathCsv(text, "fuzz.csv", lights);
    for (int frames : {2, 5}) {
        for (int f = 0; f < frames; ++f) {
            shadowlab::Camera camera;
            std::vector<shadowlab::Light> placed = lights;
            try {
                shadowlab::placeOnPath(shadowlab::samplePath(path, f, frames), f, camera, placed);
            } catch (const std::invalid_argument&) {
            }
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    for (shadowlab::LightType type : {shadowlab::LightType::Point, shadowlab::LightType::Directional}) {
        shadowlab::fuzz::parseAcceptingDocumentedErrors<shadowlab::SceneError>(
            data, size, [type](const std::string& text) { readAndPlace(text, type); });
    }
    return 0;
}
