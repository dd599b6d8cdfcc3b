// libFuzzer target: the scene loader (scenes/scene_file.cpp and its parts) on arbitrary text.
// The text is read as if it were tests/fuzz/meshes/input.json, so the tiny meshes there
// ("file": "tetra.obj", "tetra.ply") are loaded too.
#include "fuzz_target.h"
#include "scenes/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<shadowlab::SceneError>(
        data, size, [](const std::string& text) { shadowlab::parseScene(text, SHADOWLAB_FUZZ_MESH_DIR "/input.json"); });
}
