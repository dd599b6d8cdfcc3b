// Shared by the shadow-map tests: scenes, frames and error figures against the reference.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shadows/light_view.h"

namespace shadowlab::test {

// sphere-box with its disk light replaced by a sun from the same direction, normalize(4, 8, 3).
inline Scene sunSphereBox(int width, int height) {
    Scene scene = loadScene("sphere-box");
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(4, 8, 3));
    scene.lights = {sun};
    scene.camera.width = width, scene.camera.height = height;
    return scene;
}

inline Frame frameOf(const PreparedScene& prepared, const std::string& technique,
                     const std::map<std::string, std::string>& params = {}) {
    FrameSettings settings;
    settings.params = params;
    return renderFrame(prepared, findTechnique(technique), settings);
}

inline double statOf(const Frame& frame, const std::string& name) {
    for (const TechniqueStat& s : frame.shadow.stats) {
        if (s.name == name) return s.value;
    }
    return NAN;
}

struct BandedErrors {
    int lit = 0, shadowed = 0;           // in the reference, over hit pixels
    int falseShadow = 0, falseLight = 0;
    int falseLightOffBoundary = 0;       // leaks farther than `band` pixels from a reference boundary
    int falseShadowOffBoundary = 0;
};

// Error figures of `test` against `reference` (lit: V >= 0.5, as `shadowlab compare`),
// and how many errors lie more than `band` pixels from a pixel whose 4-neighbour has the
// other reference classification.
inline BandedErrors bandedErrors(const Frame& reference, const Frame& test, int band) {
    const GBuffer& g = reference.gbuffer;
    const auto lit = [&](const std::vector<float>& v, int i, int j) { return v[g.index(i, j)] >= 0.5f; };
    const auto boundary = [&](int i, int j) {
        if (!g.hit[g.index(i, j)]) return false;
        const bool here = lit(reference.shadow.visibility, i, j);
        const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
        for (int n = 0; n < 4; ++n) {
            const int a = i + di[n], b = j + dj[n];
            if (a >= 0 && b >= 0 && a < g.width && b < g.height && g.hit[g.index(a, b)] &&
                lit(reference.shadow.visibility, a, b) != here)
                return true;
        }
        return false;
    };
    const auto nearBoundary = [&](int i, int j) {
        for (int b = std::max(0, j - band); b <= std::min(g.height - 1, j + band); ++b) {
            for (int a = std::max(0, i - band); a <= std::min(g.width - 1, i + band); ++a) {
                if (boundary(a, b)) return true;
            }
        }
        return false;
    };
    BandedErrors m;
    for (int j = 0; j < g.height; ++j) {
        for (int i = 0; i < g.width; ++i) {
            if (!g.hit[g.index(i, j)]) continue;
            const bool ref = lit(reference.shadow.visibility, i, j), got = lit(test.shadow.visibility, i, j);
            (ref ? m.lit : m.shadowed) += 1;
            if (ref && !got) m.falseShadow += 1, m.falseShadowOffBoundary += !nearBoundary(i, j);
            if (!ref && got) m.falseLight += 1, m.falseLightOffBoundary += !nearBoundary(i, j);
        }
    }
    return m;
}

// Texels of a `resolution`-texel map per screen pixel, measured here rather than taken from
// the technique's median_texels_per_pixel: the light's view fitted to the frame's receivers
// (fitLightView, the stage the technique runs), each pixel's right and lower neighbours on
// the same surface moved into texel coordinates, and the area of the parallelogram they
// span (the Jacobian's determinant, RTR 7.4 "perspective aliasing"). The median over the
// pixels whose two neighbours share their normal: flat surfaces only (the ground and the
// box on sphere-box, most of the view), which is where the leaks the band bounds lie. It
// shares fitLightView with the technique, so it checks the lookup's density figure and the
// band, not the fitting.
inline double measuredTexelsPerPixel(const Frame& frame, const PreparedScene& prepared, int resolution) {
    const GBuffer& g = frame.gbuffer;
    const LightView view = fitLightView(pointLightFor(prepared.scene().lights[0]), g, prepared.world(), {.resolution = resolution});
    const glm::dmat4 clipFromWorld = view.clipFromWorld();
    const auto texel = [&](size_t k) {
        const glm::dvec4 c = clipFromWorld * glm::dvec4(glm::dvec3(g.position[k]), 1.0);
        return glm::dvec2(c.x / c.w, c.y / c.w) * (0.5 * resolution);
    };
    std::vector<double> density;
    for (int j = 0; j + 1 < g.height; ++j) {
        for (int i = 0; i + 1 < g.width; ++i) {
            const size_t k = g.index(i, j), right = g.index(i + 1, j), below = g.index(i, j + 1);
            if (!g.hit[k] || !g.hit[right] || !g.hit[below] || g.normal[right] != g.normal[k] || g.normal[below] != g.normal[k])
                continue;
            const glm::dvec2 t = texel(k), du = texel(right) - t, dv = texel(below) - t;
            density.push_back(std::abs(du.x * dv.y - du.y * dv.x));
        }
    }
    if (density.empty()) return 0.0;
    std::nth_element(density.begin(), density.begin() + density.size() / 2, density.end());
    return density[density.size() / 2];
}

// The leak band: a hard shadow-map edge is off by up to about one texel (the nearest texel
// centre is half a texel diagonal away, the occluder's own rasterization another half), so
// a leak lies within ~1 texel footprint of the true boundary; in screen pixels that is
// 1 / sqrt(texels per pixel). Doubled for the spread of the density around its median.
inline int leakBandPixels(double texelsPerPixelMedian) {
    return int(std::ceil(2.0 / std::sqrt(texelsPerPixelMedian))) + 1;
}

}  // namespace shadowlab::test
