// Scenes for the environment techniques' tests: a constant environment written to a scratch
// EXR (the furnace), a Lambert floor with or without a ceiling that hides the whole sky,
// and the shipped glossy sphere under a sky map, all small.
#pragma once

#include <string>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include "frame/render.h"
#include "scenes/procedural.h"
#include "scenes/scene_file.h"
#include "shading/image_io.h"
#include "shading/luminance.h"
#include "tests/scratch_directory.h"
#include "tests/shadows/maps/shadow_map_test_util.h"   // frameOf

namespace shadowlab::test {

inline constexpr glm::vec3 kFurnaceRadiance{0.5f, 1.0f, 2.0f};
inline constexpr glm::vec3 kFloorAlbedo{0.5f, 0.6f, 0.7f};

// A W x H map of one radiance, as an EXR file in `dir`.
inline std::string writeConstantMap(const ScratchDirectory& dir, glm::vec3 radiance, int width = 64, int height = 32) {
    ImageChannels image;
    image.width = width, image.height = height;
    const size_t n = size_t(width) * size_t(height);
    image.set("R", std::vector<float>(n, radiance.r));
    image.set("G", std::vector<float>(n, radiance.g));
    image.set("B", std::vector<float>(n, radiance.b));
    const std::string path = (dir.path / "constant.exr").string();
    writeExr(path, image);
    return path;
}

// A floor 1000 m wide at y = 0 (Lambert, kFloorAlbedo) under the map; with `ceiling`, the
// same plane facing down at y = 1, so that no direction above the floor reaches the sky.
// The camera stands at 0.5 m and looks down at the floor ahead.
inline Scene furnaceScene(const std::string& map, bool ceiling, int width = 48, int height = 32) {
    Scene scene;
    scene.name = ceiling ? "furnace-ceiling" : "furnace";
    scene.meshes.push_back(makeGrid({1000.0f, 1000.0f}, {4, 4}));
    scene.materials.push_back({.name = "floor", .albedo = kFloorAlbedo});
    scene.instances.push_back({.name = "floor", .mesh = 0, .material = 0});
    if (ceiling) {
        glm::mat4 flip(1.0f);   // a half turn about x, then up 1 m
        flip[1][1] = -1.0f, flip[2][2] = -1.0f, flip[3][1] = 1.0f;
        scene.instances.push_back({.name = "ceiling", .mesh = 0, .material = 0, .worldFromObject = flip});
    }
    scene.camera = {.eye = {0.0f, 0.5f, 0.0f}, .target = {0.0f, 0.0f, -2.0f}, .fovyDeg = 60.0f,
                    .width = width, .height = height};
    scene.environment.map = map;
    return scene;
}

inline Scene skyScene(int width, int height) {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/environment/sphere-sky.json");
    scene.camera.width = width, scene.camera.height = height;
    return scene;
}

// The mean luminance of the frame's image over its hit pixels.
inline double meanLuminance(const Frame& f) {
    double sum = 0.0;
    size_t hits = 0;
    for (size_t k = 0; k < f.radiance.size(); ++k) {
        if (f.gbuffer.hit[k]) sum += luminance(glm::dvec3(f.radiance[k])), ++hits;
    }
    return hits ? sum / double(hits) : 0.0;
}

// A stat of the frame's technique; fails the test if it has none of that name.
inline double stat(const Frame& f, const std::string& name) {
    for (const TechniqueStat& s : f.shadow.stats) {
        if (s.name == name) return s.value;
    }
    FAIL("no stat " << name);
    return 0.0;
}

}  // namespace shadowlab::test
