// libFuzzer target: the compositing scene loader (differential/scene/compositing_file.cpp) on arbitrary
// text, read as if it were tests/fuzz/meshes/input.json, so the tiny meshes there
// ("file": "tetra.obj", "tetra.ply") are loaded too. It reads no photograph (that is
// compositing_inputs' work, through the EXR and image readers fuzzed on their own).
#include "differential/scene/compositing_file.h"
#include "fuzz_target.h"
#include "scenes/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<shadowlab::SceneError>(
        data, size, [](const std::string& text) { shadowlab::parseCompositingFile(text, SHADOWLAB_FUZZ_MESH_DIR "/input.json"); });
}
