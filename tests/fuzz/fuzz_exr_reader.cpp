// libFuzzer target: reading an EXR file as `compare` does (shading/image_io.cpp) from
// arbitrary bytes. Debian's OpenEXR is not instrumented, so coverage guides the fuzzer
// through our checks only; AddressSanitizer still sees the library's heap.
#include <stdexcept>

#include "fuzz_target.h"
#include "shading/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<std::runtime_error>(
        data, size, [](const std::string& bytes) { shadowlab::parseExr(bytes, "fuzz.exr"); });
}
