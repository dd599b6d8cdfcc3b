// What every fuzz target checks: a loader given arbitrary bytes either returns or throws
// its documented error type. Anything else (a crash, a sanitizer report, a hang, memory
// beyond libFuzzer's -rss_limit_mb, or another exception escaping) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace shadowlab::fuzz {

template <typename DocumentedError, typename Parse>
int parseAcceptingDocumentedErrors(const uint8_t* data, size_t size, Parse parse) {
    try {
        parse(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const DocumentedError&) {
    }
    return 0;
}

}  // namespace shadowlab::fuzz
