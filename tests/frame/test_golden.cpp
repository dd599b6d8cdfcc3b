// Golden images by hash (style.md: "goldens are hashes of exact bytes", as llvmpipe's
// trace checksums). For every built-in scene the camera pass's visibility buffer, its
// depth, the G-buffer (both normals) and the unshadowed image are hashed, at every SIMD level with 1, 2
// and 8 threads, and must equal tests/golden/<scene>.hash, which also proves determinism
// across threads and instruction sets on real scenes.
//
// The exact reference's V is not hashed: it comes from Embree's own kernels, whose choice
// of instruction set is not ours. tests/shadows checks it against analytic answers.
//
// To record new goldens after an intended change of output, run this test with
// SHADOWLAB_UPDATE_GOLDEN=1 and commit the .hash files with the reason in the message.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "frame/registry.h"
#include "frame/render.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "shading/tonemap.h"

using namespace shadowlab;

namespace {

// FNV-1a, 64 bit, over raw bytes.
struct Fnv1a {
    uint64_t state = 0xcbf29ce484222325ull;
    template <class T>
    void add(const std::vector<T>& values) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
        for (size_t i = 0; i < values.size() * sizeof(T); ++i) state = (state ^ bytes[i]) * 0x100000001b3ull;
    }
};

std::string hex(uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

// One line per buffer: "<name> <hash>".
std::string frameHashes(const PreparedScene& prepared, raster::SimdLevel simd) {
    FrameSettings settings;
    settings.simd = simd;
    const Frame frame = renderFrame(prepared, findTechnique("none"), settings);
    const GBuffer& g = frame.gbuffer;
    auto line = [](const char* name, auto&&... buffers) {
        Fnv1a h;
        (h.add(buffers), ...);
        return std::string(name) + " " + hex(h.state) + "\n";
    };
    return line("triangle", g.triangle) + line("depth", g.depth) + line("position", g.position) +
           line("normal", g.normal) + line("shading-normal", g.shadingNormal) +
           line("image", toSrgb8Image(frame.radiance, {}));
}

std::string goldenPath(const std::string& scene) {
    return std::string(SHADOWLAB_SOURCE_DIR) + "/tests/golden/" + scene + ".hash";
}

// Every built-in scene at every level this CPU has, with `threads` threads, against its
// golden file. One test a thread count, so that the sanitizer runs can take one of them
// (scripts/sanitize.sh, scripts/tsan.sh) while the ordinary build checks all three.
void checkSceneGolden(int threads) {
    const bool update = std::getenv("SHADOWLAB_UPDATE_GOLDEN") != nullptr;
    if (update && threads != 1) return;
    for (const std::string& name : builtinSceneNames()) {
        const PreparedScene prepared(loadScene(name));
        std::string expected;
        if (update) {
            expected = frameHashes(prepared, raster::SimdLevel::Scalar);
            std::ofstream(goldenPath(name)) << expected;
        } else {
            std::ifstream in(goldenPath(name));
            REQUIRE_MESSAGE(in.good(), "no golden for " << name << ": run with SHADOWLAB_UPDATE_GOLDEN=1");
            std::stringstream text;
            text << in.rdbuf();
            expected = text.str();
        }
        for (raster::SimdLevel simd : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
            if (!raster::simdLevelSupported(simd)) {
                MESSAGE("skipped " << raster::simdLevelName(simd) << ": not supported by this CPU");
                continue;
            }
            INFO(name << ", " << raster::simdLevelName(simd) << ", " << threads << " threads");
            CHECK(withThreads(threads, [&] { return frameHashes(prepared, simd); }) == expected);
        }
    }
}

}  // namespace

TEST_CASE("built-in scenes render to their golden hashes at every SIMD level with 1 thread") { checkSceneGolden(1); }
TEST_CASE("built-in scenes render to their golden hashes at every SIMD level with 2 threads") { checkSceneGolden(2); }
TEST_CASE("built-in scenes render to their golden hashes at every SIMD level with 8 threads") { checkSceneGolden(8); }
