// The denoisers' test inputs: a still view's G-buffer with its motion and reprojection,
// the exact V of its shadow, and noisy V drawn from it.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "frame/render.h"
#include "shadows/denoise/denoise_inputs.h"
#include "shadows/temporal/reprojection.h"
#include "tests/shadows/temporal/temporal_test_support.h"

namespace shadowlab::denoise_test {

// A still view rendered twice in one sequence: the second frame's G-buffer carries its
// motion, and its reprojection (every pixel kept) serves every later frame of the view.
struct StillView {
    Scene scene;
    Frame frame;            // the technique's second frame: gbuffer with motion, its V
    Reprojection reprojection;
    DenoiseView view;

    StillView(const char* file, int width, int height, const std::string& technique,
              const std::map<std::string, std::string>& params = {})
        : scene(temporal_test::loadSmall(file, width, height)) {
        const PreparedScene prepared{Scene(scene)};
        FrameHistory history;
        FrameSettings settings;
        settings.params = params;
        settings.history = &history;
        renderFrame(prepared, findTechnique(technique), settings);
        const PreviousView before = *history.previousView();
        frame = renderFrame(prepared, findTechnique(technique), settings);
        reprojection = reproject(frame.gbuffer, before, {});
        view.eye = scene.camera.eye;
        view.focalPixels = float(height) / (2.0f * std::tan(glm::radians(scene.camera.fovyDeg) / 2.0f));
    }
};

inline uint32_t hash(uint32_t x) {   // a 32-bit integer finaliser (Wellons' lowbias32)
    x ^= x >> 16, x *= 0x7feb352du, x ^= x >> 15, x *= 0x846ca68bu, x ^= x >> 16;
    return x;
}

// One ray per pixel as a ray tracer would cast it: V = 1 with probability `exact`, else 0,
// from a seeded hash of pixel and frame.
inline std::vector<float> bernoulli(const std::vector<float>& exact, uint32_t frame, uint32_t seed) {
    std::vector<float> v(exact.size());
    for (size_t k = 0; k < exact.size(); ++k) {
        const uint32_t h = hash(uint32_t(k) ^ hash(frame * 0x9e3779b9u ^ hash(seed)));
        v[k] = float(double(h) / 4294967296.0) < exact[k] ? 1.0f : 0.0f;
    }
    return v;
}

// RMS of a - b over the hit pixels.
inline double rms(const GBuffer& g, const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t k = 0; k < a.size(); ++k)
        if (g.hit[k]) sum += (double(a[k]) - b[k]) * (double(a[k]) - b[k]), ++n;
    return std::sqrt(sum / double(n));
}

inline double maxDifference(const GBuffer& g, const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0;
    for (size_t k = 0; k < a.size(); ++k)
        if (g.hit[k]) worst = std::max(worst, std::abs(double(a[k]) - b[k]));
    return worst;
}

inline std::vector<float> noOccluders(size_t n) { return std::vector<float>(n, std::numeric_limits<float>::infinity()); }

}  // namespace shadowlab::denoise_test
