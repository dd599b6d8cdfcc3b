// libFuzzer target: reading an environment map (OpenEXR or Radiance HDR, told by its first
// bytes) as `shadowlab environment` and the natural-light techniques do
// (shading/environment/environment_file.h), from arbitrary bytes. The Radiance decoder is
// our own and instrumented; OpenEXR, as in fuzz_exr_reader, is not.
#include <stdexcept>

#include "fuzz_target.h"
#include "shading/environment/environment_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return shadowlab::fuzz::parseAcceptingDocumentedErrors<std::runtime_error>(
        data, size, [](const std::string& bytes) { shadowlab::parseEnvironmentMap(bytes, "fuzz"); });
}
