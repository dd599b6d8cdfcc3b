// Scenes and frame sequences the temporal tests share.
#pragma once

#include <cmath>
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

// Mean |a - b| over the pixels: the flicker from one frame to the next.
inline double meanChange(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    for (size_t k = 0; k < a.size(); ++k) sum += std::abs(double(a[k]) - double(b[k]));
    return sum / double(a.size());
}

}  // namespace shadowlab::temporal_test
