// Small scenes on which every technique runs, and settings that keep its frame quick: the
// techniques that need a directional light run on the sun case (and the shadow map, there
// in its LiSPSM warp), the environment techniques on a sphere under a sky map, the others
// on sphere-box (a disk light, which the soft techniques need).
#pragma once

#include <map>
#include <string>

#include "frame/render.h"
#include "scenes/scene_file.h"

namespace shadowlab::test {

inline Scene smallScene(const std::string& nameOrPath, int width = 96, int height = 60) {
    Scene scene = loadScene(nameOrPath);
    scene.camera.width = width, scene.camera.height = height;
    return scene;
}

inline std::string sunScene() { return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/hard/sun.json"; }
inline std::string skyScene() { return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/environment/sphere-sky.json"; }

// csm's cascades and the virtual map's clipmap are for a sun (any other light gets
// shadow-map's frame): test them on one.
inline bool runsOnASun(const Technique& t) { return t.name == "csm" || t.name == "virtual-shadow-map"; }

// Settings that keep each technique's frame small: few samples and lights.
inline std::map<std::string, std::string> quickSettings(const Technique& t) {
    if (t.name == "reference-soft") return {{"samples-per-axis", "2"}};
    if (t.name == "shadow-map") return {{"warp", "lispsm"}};
    if (t.name == "reference-env") return {{"samples", "2"}};
    if (t.output == TechniqueOutput::Radiance) return {{"lights", "4"}};
    return {};
}

// The three scenes at one size, and which one a technique runs on.
struct TechniqueScenes {
    explicit TechniqueScenes(int width = 96, int height = 60)
        : disk(smallScene("sphere-box", width, height)), sun(smallScene(sunScene(), width, height)),
          sky(smallScene(skyScene(), width, height)) {}
    const PreparedScene& sceneFor(const Technique& t) const {
        if (t.output == TechniqueOutput::Radiance) return sky;
        return runsOnASun(t) || t.name == "shadow-map" ? sun : disk;
    }
    PreparedScene disk, sun, sky;
};

}  // namespace shadowlab::test
