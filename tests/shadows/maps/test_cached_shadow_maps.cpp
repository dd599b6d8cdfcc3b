// Cached shadow maps (docs/cached-shadow-maps.md): shadow-map's cache=static keeps
// the static casters' map and draws the moving ones over a copy; csm's update-every draws
// far cascades every k-th frame. A cached map must equal a fresh one bit for bit, and redraw
// only what a move or the light invalidates.
#include <doctest/doctest.h>

#include <map>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/camera_path.h"
#include "shadows/maps/csm.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/maps/static_map_cache.h"
#include "tests/same_bits.h"
#include "tests/shadows/maps/shadow_map_test_util.h"
#include "tests/shadows/shadow_test_support.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

Scene flythroughScene(const std::string& name, int width, int height) {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/flythrough/" + name + ".json");
    scene.camera.width = width, scene.camera.height = height;
    return scene;
}

constexpr uint32_t kSphere = 1;   // sliding-sphere's moving instance

// Moves instance `index` by `offset`, m, in world space.
void move(PreparedScene& prepared, uint32_t index, const glm::vec3& offset) {
    const InstancePlacement placement{
        index, glm::translate(glm::mat4(1.0f), offset) * prepared.scene().instances[index].worldFromObject};
    REQUIRE(prepared.setInstanceTransforms({&placement, 1}) == 1);
}

// A map's view and settings for sliding-sphere's disk light (its centre), fitted to the world.
struct CachedMapFixture {
    PreparedScene prepared{flythroughScene("sliding-sphere", 160, 100)};
    DepthMapSettings settings{512, DepthLayer::First, polygonOffsetFor(BiasSettings{}), {}};
    StaticMapCache cache;
    DepthMap out;

    LightView view() const { return fitLightViewToWorld(pointLightFor(prepared.scene().lights[0]), prepared.world()); }
    // One frame of the cache; the map must equal the one drawn whole, fresh.
    CachedMapStats frame() {
        const LightView v = view();
        const CachedMapStats stats =
            drawCachedMap(prepared, prepared.geometryVersion(), v, settings, raster::bestSimdLevel(), cache, out);
        const DepthMap fresh = renderDepthMap(prepared, v, settings, raster::bestSimdLevel());
        const DepthMap& map = cachedFrameMap(cache, out);
        CHECK(map.size == fresh.size);
        CHECK(map.texelFromWorld == fresh.texelFromWorld);
        CHECK(sameBytes(map.image(), fresh.image()));
        return stats;
    }
    int64_t texels() const { return int64_t(settings.size) * settings.size; }
};

}  // namespace

TEST_CASE("cached map: with nothing moving, every frame equals a fresh map and redraws nothing after the first") {
    CachedMapFixture f;
    CHECK(f.frame().redrawnTexels == f.texels());
    for (int frame = 1; frame < 3; ++frame) {
        const CachedMapStats stats = f.frame();
        CHECK(stats.redrawnTexels == 0);
        CHECK(stats.staticTriangles == 0);
        CHECK(stats.dynamicTriangles == 0);
    }
}

TEST_CASE("cached map: a moved instance turns dynamic, redraws only its former bounds, and the map stays exact") {
    CachedMapFixture f;
    f.frame();
    const Aabb before = instanceBounds(f.prepared.scene(), f.prepared.world())[kSphere];
    const MapRect under = texelsUnder(before, f.cache.staticMap);
    move(f.prepared, kSphere, {1.0f, 0.0f, 0.0f});
    REQUIRE(f.view().clipFromWorld() == f.cache.staticMap.view.clipFromWorld());   // the world's box, so the view, stayed
    const CachedMapStats moved = f.frame();
    CHECK(moved.dynamicInstances == 1);
    CHECK(moved.redrawnTexels == under.area());   // the sphere's former bounds, no more
    CHECK(moved.redrawnTexels > 0);
    CHECK(moved.redrawnTexels < f.texels() / 4);   // a full redraw would be all
    const size_t sphereTriangles = instanceRanges(f.prepared.scene())[kSphere].triangleCount;
    CHECK(moved.dynamicTriangles == sphereTriangles);
    CHECK(moved.staticTriangles == f.prepared.world().triangles.size() - sphereTriangles);
    // Moving on: the static map stays, the sphere is drawn over its copy in its new bounds.
    for (int frame = 0; frame < 3; ++frame) {
        move(f.prepared, kSphere, {0.5f, 0.0f, 0.25f});
        const CachedMapStats stats = f.frame();
        CHECK(stats.redrawnTexels == 0);
        CHECK(stats.dynamicTriangles == sphereTriangles);
        CHECK(stats.dynamicTexels > 0);
        CHECK(stats.dynamicTexels < f.texels() / 4);
    }
}

TEST_CASE("cached map: the light moving redraws the whole static map") {
    CachedMapFixture f;
    f.frame();
    move(f.prepared, kSphere, {1.0f, 0.0f, 0.0f});
    f.frame();
    std::vector<Light> lights = f.prepared.scene().lights;
    lights[0].position += glm::vec3(0.25f, 0.0f, 0.0f);
    f.prepared.setLights(lights);
    const CachedMapStats stats = f.frame();
    CHECK(stats.redrawnTexels == f.texels());
    CHECK(stats.dynamicTriangles > 0);   // the sphere stays dynamic
}

TEST_CASE("cached map: texelsUnder covers a box's projection and is the whole map across a perspective apex") {
    CachedMapFixture f;
    f.frame();
    const DepthMap& map = f.cache.staticMap;
    const MapRect whole = texelsUnder({glm::dvec3(-100.0), glm::dvec3(100.0)}, map);
    CHECK(whole.area() == f.texels());
    const glm::dvec3 light(f.prepared.scene().lights[0].position);
    CHECK(texelsUnder({light - 0.1, light + 0.1}, map).area() == f.texels());   // the apex inside the box
    const MapRect box = texelsUnder({glm::dvec3(1.5, 0.0, -1.5), glm::dvec3(2.5, 1.5, -0.5)}, map);
    CHECK(box.area() > 0);
    CHECK(box.area() < f.texels() / 4);
}

namespace {

// A fly-through's frames: shadow-map (or csm) with `params`, with a kept history and alone.
struct PathFrames {
    PreparedScene prepared;
    Scene initial;
    FrameHistory history;

    PathFrames(const std::string& name, int width, int height)
        : prepared(flythroughScene(name, width, height)), initial(flythroughScene(name, width, height)) {}
    int frames() const { return initial.flythrough.frames; }
    // Places the camera, the light and the moving instances at frame `frame` of `frames`.
    void place(int frame, int frames) {
        const PathSample sample = samplePath(initial.flythrough, frame, frames);
        Camera camera = initial.camera;
        std::vector<Light> lights = initial.lights;
        placeOnPath(sample, frame, camera, lights);
        prepared.setCamera(camera), prepared.setLights(lights);
        if (!sample.placements.empty()) prepared.setInstanceTransforms(sample.placements);
    }
    Frame run(const std::string& technique, std::map<std::string, std::string> params, FrameHistory* kept) {
        FrameSettings s;
        s.params = std::move(params);
        s.history = kept;
        return renderFrame(prepared, findTechnique(technique), s);
    }
};

}  // namespace

TEST_CASE("shadow-map cache=static: V equals the uncached map's on every frame of the sliding sphere, either fit") {
    std::map<std::string, double> redrawn;   // percent of the map, summed over the frames after the first
    for (const char* fit : {"scene", "receivers"}) {
        CAPTURE(fit);
        PathFrames path("sliding-sphere", 160, 100);
        const std::map<std::string, std::string> off{{"resolution", "512"}, {"fit", fit}};
        std::map<std::string, std::string> cached = off;
        cached["cache"] = "static";
        for (int frame = 0; frame < path.frames(); ++frame) {
            CAPTURE(frame);
            path.place(frame, path.frames());
            const Frame kept = path.run("shadow-map", cached, &path.history);
            CHECK(sameBytes(kept.shadow.visibility, path.run("shadow-map", off, nullptr).shadow.visibility));
            if (frame > 0) redrawn[fit] += stat(kept.shadow, "cache_redrawn_texels_percent");
        }
    }
    // Fitted to the world, only the sphere's first move redraws (its former bounds); fitted to
    // the receivers, the near plane follows the sphere, and a new view redraws the whole map.
    CHECK(redrawn["scene"] > 0.0);
    CHECK(redrawn["scene"] < 25.0);
    CHECK(redrawn["receivers"] > 4.0 * redrawn["scene"]);
}

TEST_CASE("shadow-map cache: the midpoint layer and cube faces are refused") {
    PathFrames path("sliding-sphere", 80, 50);
    CHECK_THROWS_AS(path.run("shadow-map", {{"cache", "static"}, {"layer", "midpoint"}}, nullptr), std::invalid_argument);
    CHECK_THROWS_AS(path.run("shadow-map", {{"cache", "static"}, {"cube", "always"}}, nullptr), std::invalid_argument);
}

TEST_CASE("csm update-every: k = 1 is csm as before, and a still camera's frames with k = 2 and 4 equal k = 1's") {
    PathFrames path("avenue", 160, 100);
    path.place(0, path.frames());
    const std::map<std::string, std::string> base{{"resolution", "512"}};
    const std::vector<float> today = path.run("csm", base, nullptr).shadow.visibility;
    for (const char* k : {"1", "2", "4"}) {
        CAPTURE(k);
        std::map<std::string, std::string> stepped = base;
        stepped["update-every"] = k;
        FrameHistory history;
        for (int frame = 0; frame < 6; ++frame) {
            CAPTURE(frame);
            const Frame f = path.run("csm", stepped, &history);
            CHECK(sameBytes(f.shadow.visibility, today));
            if (frame == 0 || std::string(k) == "1") CHECK(stat(f.shadow, "cache_stale_cascades_count") == 0.0);
        }
    }
}

TEST_CASE("csm update-every=4 on the avenue: the far cascades' stale frames are counted, staggered") {
    PathFrames path("avenue", 160, 100);
    const std::map<std::string, std::string> stepped{{"resolution", "512"}, {"update-every", "4"}};
    int stale = 0, expected = 0;
    const int frames = 12;
    for (int frame = 0; frame < frames; ++frame) {
        CAPTURE(frame);
        path.place(frame, path.frames());
        const Frame f = path.run("csm", stepped, &path.history);
        REQUIRE(stat(f.shadow, "cascades_count") == 4.0);
        const int now = int(stat(f.shadow, "cache_stale_cascades_count"));
        // Cascades 1-3 each drawn on one frame of four ((frame + i) % 4 == 0): two stale a frame,
        // three on frames that are multiples of 4, none on the first.
        const int rule = frame == 0 ? 0 : frame % 4 == 0 ? 3 : 2;
        CHECK(now <= rule);   // a cascade with no receivers has no map to be stale
        stale += now, expected += rule;
    }
    CHECK(stale > expected / 2);
}

TEST_CASE("csm update-every=4 with a sliding sphere under a still sun: V equals k = 1's when moved casters redraw") {
    // The camera and the sun stay: only the sphere moves, and a stale cascade its bounds touch
    // is drawn anyway, so every frame equals k = 1's; kept stale, the sphere's shadow lags.
    PathFrames path("sliding-sphere-still-sun", 160, 100);
    const std::map<std::string, std::string> every{{"resolution", "512"}};
    std::map<std::string, std::string> redraw = every, keep = every;
    redraw["update-every"] = keep["update-every"] = "4";
    keep["moved-casters"] = "keep";
    FrameHistory redrawHistory, keepHistory;
    int differing = 0;
    for (int frame = 0; frame < path.frames(); ++frame) {
        CAPTURE(frame);
        path.place(frame, path.frames());
        const std::vector<float> fresh = path.run("csm", every, nullptr).shadow.visibility;
        CHECK(sameBytes(path.run("csm", redraw, &redrawHistory).shadow.visibility, fresh));
        differing += !sameBytes(path.run("csm", keep, &keepHistory).shadow.visibility, fresh);
    }
    CHECK(differing > 0);
}
