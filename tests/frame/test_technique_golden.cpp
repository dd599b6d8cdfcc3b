// Golden hashes of every technique's output: V and the stencil image of each case below,
// hashed byte for byte and compared with tests/golden/techniques.hash, at every SIMD level
// and with 1, 2 and 8 threads (docs/determinism.md: one set of bytes for all of them).
// A change of structure must leave them all alone; a change that means to alter bits (a
// new precision, a fixed bug) records new ones with SHADOWLAB_UPDATE_GOLDEN=1 (scalar, one
// thread) and says why in its commit.
//
// The Embree references are not hashed (their kernels are not ours, test_golden.cpp says
// why); every technique of our own is, on a small view so the whole table takes seconds.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "frame/render.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

namespace {

struct GoldenCase {
    std::string scene;   // a built-in name or a path below the source tree
    std::string technique;
    std::map<std::string, std::string> params;
};

const std::vector<GoldenCase>& goldenCases() {
    static const std::vector<GoldenCase> cases = {
        {"sphere-box", "none", {}},
        {"sphere-box", "shadow-map", {}},
        {"sphere-box", "shadow-map", {{"bias", "receiver-plane"}, {"filter", "bilinear"}}},
        {"sphere-box", "shadow-map", {{"bias", "normal-offset"}, {"filter", "grid"}, {"layer", "midpoint"}}},
        {"sphere-box", "shadow-map", {{"bias", "constant"}, {"filter", "poisson"}, {"layer", "second"}}},
        {"sphere-box", "shadow-map", {{"cube", "always"}}},
        {"sphere-box", "izb", {}},
        {"sphere-box", "shadow-volume", {}},
        {"sphere-box", "shadow-volume", {{"mode", "zpass"}}},
        {"sphere-box", "planar", {}},
        {"sphere-box", "pcss", {}},
        {"sphere-box", "pcss", {{"min-max-hierarchy", "on"}}},
        {"sphere-box", "chs", {}},
        {"sphere-box", "vsm", {}},
        {"sphere-box", "vsm", {{"filter", "sat"}, {"width", "pcss"}}},
        {"sphere-box", "esm", {{"blur", "gaussian"}}},
        {"sphere-box", "evsm", {}},
        {"sphere-box", "msm", {}},
        {"sphere-box", "multi-sample", {{"samples", "16"}}},
        {"sphere-box", "fins", {}},
        {"sphere-box", "fins", {{"layers", "1"}, {"falloff", "bernstein"}}},
        {"sphere-box", "smoothies", {}},
        {"sphere-box", "penumbra-maps", {}},
        {"sphere-box", "soft-shadow-volumes", {}},
        {"assets/scenes/soft/two-boxes.json", "soft-shadow-volumes", {{"hard-shadow", "binary"}}},
        {"assets/scenes/soft/square-over-plane.json", "soft-shadow-volumes", {}},
        {"sphere-box", "backprojection", {}},
        {"assets/scenes/soft/two-heights.json", "backprojection", {{"light-samples", "8"}}},
        {"bunny", "shadow-map", {}},
        {"bunny", "izb", {}},
        {"bunny", "shadow-volume", {}},
        {"bunny", "fins", {}},
        {"assets/scenes/hard/sun.json", "shadow-map", {{"warp", "lispsm"}}},
        {"assets/scenes/hard/sun.json", "csm", {}},
        {"assets/scenes/hard/sun.json", "csm", {{"split", "log"}, {"bounds", "camera"}, {"snap", "off"}}},
        {"assets/scenes/hard/point-light-inside.json", "shadow-map", {}},
        {"assets/scenes/hard/near-plane-cuts-volume.json", "shadow-volume", {}},
        {"assets/scenes/hard/spot.json", "planar", {}},
        {"assets/scenes/soft/torus-over-plane.json", "fins", {}},
        {"assets/scenes/hard/box-contact.json", "contact-shadows", {}},
        {"assets/scenes/soft/branch-over-crate.json", "izb-pcss", {}},
        {"assets/scenes/volumetric/stacked-sheets.json", "reference", {}},
        {"assets/scenes/volumetric/stacked-sheets.json", "opacity-shadow-maps", {}},
        {"assets/scenes/volumetric/stacked-sheets.json", "deep-shadow-maps", {}},
        {"assets/scenes/volumetric/stacked-sheets.json", "adaptive-volumetric-shadow-maps", {}},
        {"assets/scenes/volumetric/tinted-glass.json", "coloured-shadow-map", {}},
        {"assets/scenes/volumetric/smoke-over-plane.json", "deep-shadow-maps", {{"tolerance", "0.05"}}},
        {"assets/scenes/volumetric/foliage-cards.json", "shadow-map", {}},
    };
    return cases;
}

uint64_t fnv1a(const std::vector<float>& values, uint64_t state = 0xcbf29ce484222325ull) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (size_t i = 0; i < values.size() * sizeof(float); ++i) state = (state ^ bytes[i]) * 0x100000001b3ull;
    return state;
}

std::string describe(const GoldenCase& c) {
    std::string text = c.scene + " " + c.technique;
    for (const auto& [name, value] : c.params) text += " " + name + "=" + value;
    return text;
}

// "<case> <hash of V> <hash of the stencil image>" for one case, on a 320 x 200 view.
std::string caseLine(const GoldenCase& c, raster::SimdLevel simd, int threads) {
    const bool builtin = c.scene.find('/') == std::string::npos;
    Scene scene = loadScene(builtin ? c.scene : std::string(SHADOWLAB_SOURCE_DIR) + "/" + c.scene);
    scene.camera.width = 320, scene.camera.height = 200;
    const PreparedScene prepared(scene);
    FrameSettings settings;
    settings.simd = simd;
    settings.params = c.params;
    const Frame frame = withThreads(threads, [&] { return renderFrame(prepared, findTechnique(c.technique), settings); });
    char hashes[40];
    std::snprintf(hashes, sizeof hashes, " %016llx %016llx", static_cast<unsigned long long>(fnv1a(frame.shadow.visibility)),
                  static_cast<unsigned long long>(fnv1a(frame.shadow.stencil)));
    return describe(c) + hashes;
}

std::string goldenPath() { return std::string(SHADOWLAB_SOURCE_DIR) + "/tests/golden/techniques.hash"; }

// Every case at every level this CPU has, with `threads` threads, against the golden file.
// .ci/run requires the machine's levels (test_determinism.cpp), so none is skipped there.
void checkGolden(int threads) {
    if (std::getenv("SHADOWLAB_UPDATE_GOLDEN")) {
        if (threads != 1) return;
        std::ofstream out(goldenPath());
        for (const GoldenCase& c : goldenCases()) out << caseLine(c, raster::SimdLevel::Scalar, 1) << "\n";
        return;
    }
    std::map<std::string, std::string> expected;
    std::ifstream in(goldenPath());
    REQUIRE_MESSAGE(in.good(), "no golden at " << goldenPath() << ": run with SHADOWLAB_UPDATE_GOLDEN=1");
    std::string line;
    while (std::getline(in, line)) expected[line.substr(0, line.size() - 34)] = line;
    for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (!raster::simdLevelSupported(level)) {
            MESSAGE("this CPU has no " << raster::simdLevelName(level) << ": not checked");
            continue;
        }
        for (const GoldenCase& c : goldenCases()) {
            INFO(describe(c) << " at " << raster::simdLevelName(level) << " with " << threads << " thread(s)");
            const auto it = expected.find(describe(c));
            REQUIRE_MESSAGE(it != expected.end(), "no golden line for this case");
            CHECK(caseLine(c, level, threads) == it->second);
        }
    }
}

}  // namespace

TEST_CASE("every technique gives its golden V and stencil bytes at every SIMD level with 1 thread") { checkGolden(1); }
TEST_CASE("every technique gives its golden V and stencil bytes at every SIMD level with 2 threads") { checkGolden(2); }
TEST_CASE("every technique gives its golden V and stencil bytes at every SIMD level with 8 threads") { checkGolden(8); }
