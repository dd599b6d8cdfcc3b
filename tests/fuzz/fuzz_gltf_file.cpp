// libFuzzer target: the glTF reader (scenes/gltf_scene.h) on arbitrary bytes, as .gltf
// text or .glb (told by the first bytes), then the scene a render would make of it (the
// default camera framing its bounds). External URIs are looked up in the fuzzers' mesh
// folder, whose files are small.
#include "fuzz_target.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<shadowlab::SceneError>(data, size, [](const std::string& bytes) {
        const std::string path = std::string(SHADOWLAB_FUZZ_MESH_DIR) + "/fuzz.gltf";
        shadowlab::gltfScene(shadowlab::parseGltfModel(bytes, path), path);
    });
}
