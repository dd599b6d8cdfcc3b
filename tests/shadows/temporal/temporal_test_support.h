// Scenes and frame sequences the temporal tests share.
#pragma once

#include <string>
#include <vector>

#include "frame/render.h"
#include "scenes/camera_path.h"
#include "scenes/scene_file.h"

namespace shadowlab::temporal_test {

inline Scene loadSmall(const char* file, int width, int height) {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/" + file);
    scene.camera.width = width;
    scene.camera.height = height;
    return scene;
}

// Moves `prepared` to frame f of `frames` of its scene's own fly-through path.
inline void placeAtPathFrame(PreparedScene& prepared, const Scene& base, int f, int frames) {
    const PathSample sample = samplePath(base.flythrough, f, frames);
    Camera camera = base.camera;
    std::vector<Light> lights = base.lights;
    placeOnPath(sample, f, camera, lights);
    prepared.setCamera(camera);
    prepared.setLights(lights);
    prepared.setInstanceTransforms(sample.placements);
}

}  // namespace shadowlab::temporal_test
