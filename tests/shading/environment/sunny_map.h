// The environment tests' synthetic map, with the shipped maps' contrast between sun and sky.
#pragma once

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"

// A map with smooth sky, a darker ground and a small bright sun of 2 x 2 texels: the sun is
// 10^4 times the sky, as in the shipped maps.
inline shadowlab::EnvironmentMap sunnyMap(int width, int height) {
    using namespace shadowlab;
    EnvironmentMap map = constantEnvironment(width, height, glm::vec3(0.0f));
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const float v = (j + 0.5f) / height, u = (i + 0.5f) / width;
            map.radiance[size_t(j) * width + i] = v < 0.5f ? glm::vec3(0.4f + 0.6f * v, 0.6f, 1.0f - u * 0.5f)
                                                           : glm::vec3(0.2f, 0.15f + 0.1f * u, 0.1f);
        }
    }
    for (int j = height / 4; j < height / 4 + 2; ++j) {
        for (int i = width / 3; i < width / 3 + 2; ++i) map.radiance[size_t(j) * width + i] = glm::vec3(1e4f, 9e3f, 8e3f);
    }
    map.rotationRadians = 0.3;
    return map;
}

