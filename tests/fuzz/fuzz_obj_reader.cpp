// libFuzzer target: the OBJ reader (scenes/obj_reader.cpp) on arbitrary text.
#include "fuzz_target.h"
#include "scenes/obj_reader.h"
#include "scenes/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<shadowlab::SceneError>(
        data, size, [](const std::string& text) { shadowlab::parseObj(text, "fuzz.obj"); });
}
