// Debug buffers (`render --debug-buffers DIR`, shadows/debug_buffers.h). Every technique
// writes its intermediate buffers as DIR/<technique>-<name>.exr (channel Y) and .png,
// readable, finite, of the camera's size or a light-space size, and showing them does not
// change V. The views show what the technique computed:
// shadow-volume's stencil and fill, soft-shadow-volumes' hard shadow, wedges and coverage
// correction, izb's list lengths, shadow-map's texel density and
// csm's cascade colouring, each checked against the technique's own outputs and stats.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <stb/stb_image.h>

#include "frame/registry.h"
#include "shading/image_io.h"
#include "shadows/maps/cascades.h"
#include "shadows/maps/shadow_lookup.h"
#include "tests/same_bits.h"
#include "tests/scratch_directory.h"
#include "tests/shadows/maps/shadow_map_test_util.h"
#include "tests/shadows/shadow_test_support.h"
#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;
using test::sameBytes;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 160, kHeight = 100;

using ScratchDir = test::ScratchDirectory;

// A scene at kWidth x kHeight, flattened once; its frames with or without debug buffers.
struct SmallScene {
    PreparedScene prepared;
    explicit SmallScene(Scene s) : prepared(std::move(s)) {}

    Frame run(const std::string& technique, const fs::path& debugDir,
              const std::map<std::string, std::string>& params = {}) const {
        FrameSettings settings;
        settings.params = params;
        settings.debugDir = debugDir;
        return renderFrame(prepared, findTechnique(technique), settings);
    }
};

// A sun's techniques (test::runsOnASun) run on sphere-box under a sun; every other technique
// on sphere-box with its disk light (hard-shadow techniques use its centre).
SmallScene sceneFor(const std::string& technique) {
    return SmallScene(test::runsOnASun(findTechnique(technique)) ? test::sunSphereBox(kWidth, kHeight)
                                                                 : test::smallScene("sphere-box", kWidth, kHeight));
}

std::vector<float> readBuffer(const fs::path& dir, const std::string& technique, const std::string& name) {
    return readExr(dir / (technique + "-" + name + ".exr"), {"Y"}).at("Y");
}

double sum(const std::vector<float>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

// One .exr of the directory: a same-named .png of the same size, channel Y, only finite
// values; the camera's size, or a light-space one (one or more stacked squares: a map,
// cube faces, a summed-area table).
void checkExr(const fs::path& exr, const Camera& camera) {
    INFO(exr.filename().string());
    fs::path png = exr;
    png.replace_extension(".png");
    int pngWidth = 0, pngHeight = 0, channels = 0;
    REQUIRE(stbi_info(png.c_str(), &pngWidth, &pngHeight, &channels) == 1);
    const ImageChannels image = readExr(exr, {"Y"});
    CHECK(pngWidth == image.width);
    CHECK(pngHeight == image.height);
    const bool cameraSize = image.width == camera.width && image.height == camera.height;
    const bool lightSize = image.width > 0 && image.height > 0 && image.height % image.width == 0;
    CHECK((cameraSize || lightSize));
    const std::vector<float>& y = image.at("Y");
    CHECK(std::all_of(y.begin(), y.end(), [](float v) { return std::isfinite(v); }));
}

// The .exr files the technique wrote into `dir`, each checked; returns how many.
size_t checkDirectory(const fs::path& dir, const std::string& technique, const Camera& camera) {
    size_t exrs = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const fs::path& p = entry.path();
        CHECK(p.filename().string().rfind(technique + "-", 0) == 0);
        if (p.extension() != ".exr") continue;
        checkExr(p, camera);
        ++exrs;
    }
    return exrs;
}

}  // namespace

// The technique's stats with and without debug buffers, but for the timings (names in ms).
bool sameStats(const ShadowOutputs& a, const ShadowOutputs& b) {
    const auto untimed = [](const ShadowOutputs& o) {
        std::vector<std::pair<std::string, double>> stats;
        for (const TechniqueStat& s : o.stats) {
            if (s.name.find("ms") == std::string::npos) stats.emplace_back(s.name, s.value);
        }
        return stats;
    };
    return untimed(a) == untimed(b);
}

TEST_CASE("debug buffers of every technique: exr with a png, camera or light-space size, finite, V and stats unchanged") {
    for (const Technique& t : techniques()) {
        if (t.name == "none" || t.name == "reference" || t.name == "reference-soft") continue;
        // Radiance techniques write colour buffers, checked in tests/environment.
        if (t.output == TechniqueOutput::Radiance) continue;
        INFO(t.name);
        const SmallScene s = sceneFor(t.name);
        const ScratchDir dir("all-" + t.name);
        const Frame shown = s.run(t.name, dir.path), plain = s.run(t.name, {});
        CHECK(checkDirectory(dir.path, t.name, s.prepared.scene().camera) >= 1);
        CHECK(sameBytes(shown.shadow.visibility, plain.shadow.visibility));
        CHECK(sameBytes(shown.shadow.stencil, plain.shadow.stencil));
        CHECK(sameStats(shown.shadow, plain.shadow));
    }
}

TEST_CASE("shadow-volume debug stencil: equals ShadowOutputs::stencil, nonzero exactly where V = 0 on light-facing pixels") {
    const SmallScene s = sceneFor("shadow-volume");
    const ScratchDir dir("shadow-volume-stencil");
    const Frame f = s.run("shadow-volume", dir.path);
    const std::vector<float> stencil = readBuffer(dir.path, "shadow-volume", "stencil");
    CHECK(stencil == f.shadow.stencil);
    const Light light = pointLightFor(s.prepared.scene().lights[0]);
    size_t lit = 0, shadowed = 0, mismatched = 0;
    for (size_t k = 0; k < f.gbuffer.pixelCount(); ++k) {
        if (!f.gbuffer.hit[k] || !test::facesLight(f.gbuffer, k, light)) continue;
        (f.shadow.visibility[k] == 0.0f ? shadowed : lit)++;
        mismatched += (stencil[k] != 0.0f) != (f.shadow.visibility[k] == 0.0f);
    }
    INFO(lit << " lit, " << shadowed << " shadowed light-facing pixels");
    CHECK(lit > 1000);
    CHECK(shadowed > 100);
    CHECK(mismatched == 0);
}

TEST_CASE("shadow-volume debug fill: the sum over pixels is the stat fill fragments, in both counting modes") {
    const SmallScene s = sceneFor("shadow-volume");
    for (const char* mode : {"zpass", "zfail"}) {
        INFO(mode);
        const ScratchDir dir(std::string("shadow-volume-fill-") + mode);
        const Frame f = s.run("shadow-volume", dir.path, {{"mode", mode}});
        const double fragments = test::stat(f.shadow, "fill_fragments");
        CHECK(fragments > 0.0);
        CHECK(sum(readBuffer(dir.path, "shadow-volume", "fill")) == fragments);
    }
}

// Every receiver sits in exactly one texel's list (izb/lists.cpp: a counting sort of
// receiverTexels), so the lengths sum to the receivers and the occupied texels are the
// non-empty ones; the grid stacks `views` squares of `resolution` texels.
TEST_CASE("soft-shadow-volumes debug: stencil and visibility are the outputs, V = clamp(1 - stencil - correction), "
          "corrections only where wedges hold P") {
    const SmallScene s = sceneFor("soft-shadow-volumes");
    const ScratchDir dir("soft-shadow-volumes");
    const Frame f = s.run("soft-shadow-volumes", dir.path);
    const auto buffer = [&](const char* name) { return readBuffer(dir.path, "soft-shadow-volumes", name); };
    const std::vector<float> stencil = buffer("stencil"), wedges = buffer("wedges"), correction = buffer("correction");
    CHECK(stencil == f.shadow.stencil);
    CHECK(buffer("visibility") == f.shadow.visibility);
    const Light light = pointLightFor(s.prepared.scene().lights[0]);
    size_t inWedges = 0, mismatched = 0, outsideCorrected = 0;
    for (size_t k = 0; k < f.gbuffer.pixelCount(); ++k) {
        if (!f.gbuffer.hit[k]) continue;
        outsideCorrected += wedges[k] == 0.0f && correction[k] != 0.0f;
        if (!test::facesLight(f.gbuffer, k, light)) continue;
        inWedges += wedges[k] > 0.0f;
        const float expected = std::clamp(1.0f - stencil[k] - correction[k], 0.0f, 1.0f);
        mismatched += f.shadow.visibility[k] != expected;
    }
    INFO(inWedges << " light-facing pixels inside wedges");
    CHECK(inWedges > 50);
    CHECK(double(inWedges) <= test::stat(f.shadow, "wedge_inside_fragments"));
    CHECK(mismatched == 0);
    CHECK(outsideCorrected == 0);
}

TEST_CASE("izb debug list-length: sums to the stat receivers, and occupancy counts the non-empty texels") {
    const SmallScene s = sceneFor("izb");
    const ScratchDir dir("izb");
    const ShadowOutputs out = s.run("izb", dir.path).shadow;
    const ImageChannels lengths = readExr(dir.path / "izb-list-length.exr", {"Y"});
    const double resolution = test::stat(out, "resolution_texels"), views = test::stat(out, "views_count");
    CHECK(lengths.width == resolution);
    CHECK(lengths.height == views * resolution);
    const std::vector<float>& length = lengths.at("Y");
    CHECK(sum(length) == test::stat(out, "receiver_pixels"));
    CHECK(*std::max_element(length.begin(), length.end()) == test::stat(out, "list_max_receivers"));
    const double nonEmpty = double(length.size()) - test::stat(out, "empty_texels");
    CHECK(sum(readBuffer(dir.path, "izb", "occupancy")) == nonEmpty);
    CHECK(test::stat(out, "list_mean_nonempty_receivers") * nonEmpty == doctest::Approx(sum(length)));
}

// medianTexelDensity() (shadow_lookup.cpp) takes element n / 2 of the densities of the
// served pixels in its sample (every kDensitySampleStride-th pixel and row); with one map
// every hit pixel is served, and the EXR, measured at every pixel, holds the same floats.
TEST_CASE("shadow-map debug texel-density: its median over the sampled served pixels is the stat texels_per_pixel_median") {
    const SmallScene s = sceneFor("shadow-map");
    const ScratchDir dir("shadow-map");
    const Frame f = s.run("shadow-map", dir.path);
    REQUIRE(test::stat(f.shadow, "maps_count") == 1.0);
    const std::vector<float> density = readBuffer(dir.path, "shadow-map", "texel-density");
    std::vector<float> served;
    size_t measured = 0;
    for (size_t k = 0; k < density.size(); ++k) {
        const int i = int(k) % f.gbuffer.width, j = int(k) / f.gbuffer.width;
        measured += f.gbuffer.hit[k] && density[k] > 0.0f;
        if (f.gbuffer.hit[k] && i % kDensitySampleStride == 0 && j % kDensitySampleStride == 0) served.push_back(density[k]);
    }
    CHECK(measured > 10 * served.size());   // the debug view is measured at every pixel
    REQUIRE(!served.empty());
    std::nth_element(served.begin(), served.begin() + served.size() / 2, served.end());
    const double median = served[served.size() / 2];
    CHECK(median > 0.0);
    CHECK(median == test::stat(f.shadow, "median_texels_per_pixel"));
}

namespace {

// csm-cascades.png (shadow_map_debug.cpp, writeMapColouring): map m's colour, RTR Figure
// 7.20's, times 0.45 + 0.55 V. Returns the m whose colour the pixel shows exactly, or -1.
int decodeCascade(const unsigned char* rgb, float visibility) {
    static const int kColours[8][3] = {{150, 60, 200}, {60, 180, 60},  {230, 210, 40}, {210, 50, 40},
                                       {50, 90, 220},  {40, 200, 210}, {240, 140, 30}, {230, 230, 230}};
    const float shade = 0.45f + 0.55f * visibility;
    for (int m = 0; m < 8; ++m) {
        bool same = true;
        for (int c = 0; c < 3; ++c) same = same && rgb[c] == std::lround(float(kColours[m][c]) * shade);
        if (same) return m;
    }
    return -1;
}

// The cascade index of every hit pixel as csm-cascades.png shows it (-1: not decoded).
std::vector<int> shownCascades(const fs::path& png, const Frame& f) {
    int width = 0, height = 0, channels = 0;
    unsigned char* rgb = stbi_load(png.c_str(), &width, &height, &channels, 3);
    REQUIRE(rgb != nullptr);
    REQUIRE(size_t(width) * size_t(height) == f.gbuffer.pixelCount());
    std::vector<int> cascade(f.gbuffer.pixelCount(), -1);
    for (size_t k = 0; k < cascade.size(); ++k) {
        if (f.gbuffer.hit[k]) cascade[k] = decodeCascade(rgb + 3 * k, f.shadow.visibility[k]);
    }
    stbi_image_free(rgb);
    return cascade;
}

// cascadeOf() (cascades.cpp) from the reported splits: the first cascade whose far split
// lies beyond the depth, the last one beyond them all.
int cascadeOfSplits(const ShadowOutputs& out, int count, double depth) {
    for (int k = 0; k + 1 < count; ++k) {
        if (depth < test::stat(out, "cascade" + std::to_string(k) + "_split_far_m")) return k;
    }
    return count - 1;
}

}  // namespace

// A pixel's cascade is cascadeOf(its view depth), a step function of the depth, and every
// cascade holding a hit pixel has receivers and so a map: each hit pixel is served.
TEST_CASE("csm debug cascades.png: 4 cascades show at least 2 colours, the index never decreases with view depth") {
    const SmallScene s = sceneFor("csm");
    const ScratchDir dir("csm");
    const Frame f = s.run("csm", dir.path, {{"cascades", "4"}});
    const std::vector<int> cascade = shownCascades(dir.path / "csm-cascades.png", f);
    std::vector<std::pair<double, int>> byDepth;   // (view depth, cascade) of the hit pixels
    size_t undecoded = 0, offSplits = 0;
    for (size_t k = 0; k < cascade.size(); ++k) {
        if (!f.gbuffer.hit[k]) continue;
        const double depth = viewDepth(s.prepared.scene().camera, glm::dvec3(f.gbuffer.position[k]));
        undecoded += cascade[k] < 0;
        offSplits += cascade[k] != cascadeOfSplits(f.shadow, 4, depth);
        byDepth.emplace_back(depth, cascade[k]);
    }
    CHECK(undecoded == 0);
    CHECK(offSplits == 0);
    std::sort(byDepth.begin(), byDepth.end());
    const auto decreases = [](const auto& a, const auto& b) { return b.second < a.second; };
    CHECK(std::adjacent_find(byDepth.begin(), byDepth.end(), decreases) == byDepth.end());
    std::vector<int> shown(cascade.begin(), cascade.end());
    std::sort(shown.begin(), shown.end());
    shown.erase(std::unique(shown.begin(), shown.end()), shown.end());
    std::erase(shown, -1);
    INFO(shown.size() << " cascades shown");
    CHECK(shown.size() >= 2);
}
