// libFuzzer target: the PLY reader (scenes/ply_reader.cpp), ASCII and binary, on arbitrary bytes.
#include "fuzz_target.h"
#include "scenes/ply_reader.h"
#include "scenes/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<shadowlab::SceneError>(
        data, size, [](const std::string& bytes) { shadowlab::parsePly(bytes, "fuzz.ply"); });
}
