// The irregular z-buffer against the exact reference on every built-in scene and hard case
// (the exact techniques' bound, test::kExactBoundPercent: at most 0.01% of pixels
// misclassified, each within one pixel of a shadow boundary of the reference), its determinism over thread counts, and its parameters.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include "frame/render.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "shadows/izb/izb.h"
#include "shadows/reference/reference.h"

using namespace shadowlab;

namespace {

struct Views {
    PreparedScene prepared;
    const Scene& scene;
    const WorldGeometry& world;
    GBuffer gbuffer;

    explicit Views(const std::string& nameOrPath)
        : prepared(loadScene(nameOrPath)), scene(prepared.scene()), world(prepared.world()),
          gbuffer(renderGBuffer(world, scene.camera, raster::bestSimdLevel())) {}
};

ShadowOutputs run(const std::string& technique, const Views& v, const std::map<std::string, std::string>& given = {}) {
    const Technique& t = findTechnique(technique);
    const TechniqueParams params(t.name, t.params, given);
    return t.run({v.prepared, v.gbuffer, v.scene.lights[0], raster::bestSimdLevel(), params, {}});
}

// A pixel lies within one pixel of a shadow boundary of the reference when one of its eight
// neighbours with a surface has the other reference value.
bool nearReferenceBoundary(const GBuffer& g, const std::vector<float>& reference, int i, int j) {
    for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
            const int x = i + di, y = j + dj;
            if (x < 0 || y < 0 || x >= g.width || y >= g.height || !g.hit[g.index(x, y)]) continue;
            if (reference[g.index(x, y)] != reference[g.index(i, j)]) return true;
        }
    }
    return false;
}

void checkAgainstReference(const std::string& nameOrPath) {
    CAPTURE(nameOrPath);
    const Views v(nameOrPath);
    const std::vector<float> reference = run("reference", v).visibility;
    const std::vector<float> izb = run("izb", v).visibility;
    REQUIRE(izb.size() == reference.size());
    size_t pixels = 0, wrong = 0, wrongAwayFromBoundary = 0, litBackground = 0;
    for (int j = 0; j < v.gbuffer.height; ++j) {
        for (int i = 0; i < v.gbuffer.width; ++i) {
            const size_t k = v.gbuffer.index(i, j);
            if (!v.gbuffer.hit[k]) {
                litBackground += izb[k] != 0.0f;
                continue;
            }
            ++pixels;
            if (izb[k] == reference[k]) continue;
            ++wrong;
            wrongAwayFromBoundary += !nearReferenceBoundary(v.gbuffer, reference, i, j);
        }
    }
    MESSAGE(nameOrPath << ": " << wrong << " of " << pixels << " pixels misclassified");
    CHECK(pixels > 0);
    CHECK(litBackground == 0);
    CHECK(double(wrong) <= 1e-4 * double(pixels));
    CHECK(wrongAwayFromBoundary == 0);
}

}  // namespace

TEST_CASE("izb agrees with the reference on the built-in scenes") {
    for (const char* scene : {"sphere-box", "bunny", "throughput"}) checkAgainstReference(scene);
}

// docs/hard-cases.md: grazing light, a light 5 cm from an occluder (cube faces), a 10 km
// depth range, an open mesh, coincident faces, a faceted terminator, a light inside a
// closed room (six faces) and a directional light, among others. The izb holds its bound
// on all of them (docs/hard-shadows.md gives the measured figures).
TEST_CASE("izb agrees with the reference on every hard case") {
    for (const auto& entry : std::filesystem::directory_iterator(builtinSceneDir() + "/hard")) {
        if (entry.path().extension() == ".json") checkAgainstReference(entry.path().string());
    }
}

TEST_CASE("izb lists and V are the same bytes with 1 and 2 threads") {
    const Views v("sphere-box");
    const Light light = pointLightFor(v.scene.lights[0]);
    const double diagonal = sceneDiagonal(v.world);
    auto build = [&](int threads) {
        return withThreads(threads, [&] {
            std::vector<float> V;
            const izb::Receivers receivers = izb::gatherReceivers(v.gbuffer, light, diagonal, V, raster::bestSimdLevel());
            const izb::LightGrid grid = izb::makeLightGrid(izb::fitViews(light, v.gbuffer, v.world, raster::bestSimdLevel()), 512, diagonal);
            const izb::TexelLists lists = izb::buildTexelLists(izb::receiverTexels(grid.resolution, izb::placeReceivers(grid.views, receivers)), grid.texelCount());
            const izb::TileBins bins = izb::binOccluders(grid, lists, izb::projectOccluders(grid, v.world));
            return std::tuple(lists.first, lists.entry, bins.triangles.entry, run("izb", v).visibility);
        });
    };
    const auto one = build(1), two = build(2);
    CHECK(std::get<0>(one) == std::get<0>(two));
    CHECK(std::get<1>(one) == std::get<1>(two));
    CHECK(std::get<2>(one) == std::get<2>(two));
    CHECK(std::get<3>(one) == std::get<3>(two));
}

TEST_CASE("izb resolution: auto or 16..8192, a fixed resolution gives the same V") {
    const Views v("sphere-box");
    const std::vector<float> automatic = run("izb", v).visibility;
    CHECK(run("izb", v, {{"resolution", "64"}}).visibility == automatic);
    for (const char* bad : {"8", "9000", "abc", "", "1.5"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(run("izb", v, {{"resolution", bad}}), std::invalid_argument);
    }
    CHECK_THROWS_AS(run("izb", v, {{"grid", "64"}}), std::invalid_argument);
}

TEST_CASE("izb reports its list-length figures") {
    const Views v("sphere-box");
    const ShadowOutputs out = run("izb", v);
    std::map<std::string, double> stat;
    for (const TechniqueStat& s : out.stats) stat[s.name] = s.value;
    for (const char* name : {"resolution_texels", "list_max_receivers", "list_mean_nonempty_receivers", "list_p99_nonempty_receivers", "empty_texels"}) {
        CHECK(stat.count(name) == 1);
    }
    // The automatic resolution aims at about two receivers per non-empty list.
    CHECK(stat["list_mean_nonempty_receivers"] >= 1.0);
    CHECK(stat["list_mean_nonempty_receivers"] <= 4.0);
    CHECK(stat["list_p99_nonempty_receivers"] >= 1.0);
    CHECK(stat["list_max_receivers"] >= stat["list_mean_nonempty_receivers"]);
}

TEST_CASE("izb: a light inside a closed room needs all six cube faces, a light above the scene one view") {
    const auto views = [](const std::string& scene) {
        for (const TechniqueStat& s : run("izb", Views(scene)).stats) {
            if (s.name == "views_count") return s.value;
        }
        FAIL("no views stat");
        return 0.0;
    };
    CHECK(views(builtinSceneDir() + "/hard/point-light-inside.json") == 6.0);
    CHECK(views("sphere-box") == 1.0);
}
