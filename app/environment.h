// `shadowlab environment MAP`: reads an environment map as the techniques would, and writes
// its intermediate buffers (docs/environment-lighting.md): the map, its nine-coefficient
// spherical-harmonic reconstruction, the irradiance of a white Lambert surface facing each
// direction, the median-cut and structured-importance lights drawn on the map and, on request, prefiltered maps for
// Phong and GGX lobes (with GGX, the split-sum scale and bias table), with the figures printed.
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

struct EnvironmentArgs {
    std::string map, outDir = "out/environment";
    double rotationDegrees = 0.0, shWindow = 0.0;
    int lights = 16;
    std::vector<double> phongShininess, ggxRoughness;   // a prefiltered map for each
    float exposure = 0.0f;
};

void runEnvironmentCommand(const EnvironmentArgs& args);

}  // namespace shadowlab
