// Shared by the shadow-volume and planar tests: a scene rendered to a G-buffer with the
// exact reference's V, a technique run on it, and the error figures exact techniques are held to:
// misclassified pixels against the reference, and which of them are more than one pixel
// away from a shadow boundary of the reference.
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "shadows/reference/reference.h"
#include "shadows/technique.h"
#include "tests/same_bits.h"

namespace shadowlab::test {

inline std::string hardCase(const std::string& name) {
    return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/hard/" + name + ".json";
}

struct HardScene {
    shadowlab::PreparedScene prepared;
    const Scene& scene;
    const WorldGeometry& world;
    GBuffer gbuffer;
    CasterTransmission transmission;   // the reference's: cut-outs' holes, translucent casters
    std::vector<float> reference;   // exact V (point light at the light's centre)

    explicit HardScene(const std::string& nameOrPath, raster::SimdLevel simd = raster::bestSimdLevel())
        : HardScene(loadScene(nameOrPath), simd) {}
    // A scene changed after loading (another camera, another size).
    explicit HardScene(Scene s, raster::SimdLevel simd = raster::bestSimdLevel())
        : prepared(std::move(s)), scene(prepared.scene()), world(prepared.world()),
          gbuffer(renderGBuffer(world, scene.camera, simd)),
          transmission(scene, world),
          reference(ReferenceVisibility(world, &transmission).visibility(gbuffer, pointLightFor(scene.lights[0]))) {}

    Light light() const { return pointLightFor(scene.lights[0]); }

    // With `debugDir`, the technique's intermediate buffers are written there.
    ShadowOutputs run(const std::string& technique, const std::map<std::string, std::string>& given = {},
                      raster::SimdLevel simd = raster::bestSimdLevel(), const std::filesystem::path& debugDir = {}) const {
        const Technique& t = findTechnique(technique);
        const TechniqueParams params(t.name, t.params, given);
        return t.run({.prepared = prepared,
                      .gbuffer = gbuffer,
                      .light = scene.lights[0],
                      .simd = simd,
                      .params = params,
                      .debugDir = debugDir});
    }
};

struct Misclassified {
    size_t hitPixels = 0;
    size_t count = 0;                 // hit pixels whose V differs from the reference
    size_t falseShadow = 0, falseLight = 0;
    size_t awayFromBoundary = 0;      // ... with no 8-neighbour of another reference V
    double percent() const { return hitPixels ? 100.0 * double(count) / double(hitPixels) : 0.0; }
};

// A shadow ray in double precision, by brute force over every triangle: is the light's
// centre L visible from P? No offset: P's own triangle is skipped and hits closer than
// 10 um are ignored (the float rounding of P is below 1 um in these scenes).
inline bool visibleByBruteForce(const WorldGeometry& world, const glm::dvec3& P, uint32_t ownTriangle, const glm::dvec3& L) {
    const glm::dvec3 d = L - P;
    const double minT = 1e-5 / glm::length(d);
    for (uint32_t t = 0; t < world.triangles.size(); ++t) {
        if (t == ownTriangle) continue;
        const glm::dvec3 a(world.positions[world.triangles[t].x]), b(world.positions[world.triangles[t].y]),
            c(world.positions[world.triangles[t].z]);
        const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (det == 0.0) continue;
        const glm::dvec3 s = P - a, q = glm::cross(s, e1);
        const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, tHit = glm::dot(e2, q) / det;
        if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && tHit > minT && tHit < 1.0) return false;
    }
    return true;
}


// The light's side of the surface at pixel k, as the reference decides it (reference.h):
// dot(N, L - P) > 0 for the light's centre (or its direction).
inline bool facesLight(const GBuffer& g, size_t k, const Light& light) {
    const glm::dvec3 towards = light.type == LightType::Directional
                                   ? glm::dvec3(light.direction)
                                   : glm::dvec3(light.position) - glm::dvec3(g.position[k]);
    return glm::dot(glm::dvec3(g.normal[k]), towards) > 0.0;
}

// A shadow boundary of the reference passes next to pixel (i, j) if one of its 8
// neighbours with a surface has the other reference V (a cast-shadow edge or the
// terminator seen against lit surface), or lies on the other side of the terminator (the
// attached-shadow boundary, where the surface turns away from the light: on a lit-facing
// triangle next to it a cast shadow may begin that V cannot show, since V = 0 on both
// sides of it).
inline bool nearReferenceBoundary(const GBuffer& g, const std::vector<float>& reference, const Light& light, int i,
                                  int j) {
    const size_t k = g.index(i, j);
    for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
            const int x = i + di, y = j + dj;
            if (x < 0 || y < 0 || x >= g.width || y >= g.height || !g.hit[g.index(x, y)]) continue;
            const size_t n = g.index(x, y);
            if (reference[n] != reference[k] || facesLight(g, n, light) != facesLight(g, k, light)) return true;
        }
    }
    return false;
}

inline Misclassified misclassified(const GBuffer& g, const std::vector<float>& reference, const Light& light,
                                   const std::vector<float>& test) {
    Misclassified m;
    for (int j = 0; j < g.height; ++j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            m.hitPixels++;
            if ((reference[k] >= 0.5f) == (test[k] >= 0.5f)) continue;
            m.count++;
            (reference[k] >= 0.5f ? m.falseShadow : m.falseLight)++;
            m.awayFromBoundary += !nearReferenceBoundary(g, reference, light, i, j);
        }
    }
    return m;
}

// What an exact technique may differ from the reference by: ties where the reference's
// float rays and the technique's own arithmetic round differently, which happen only right
// at a shadow boundary. At most kExactBoundPercent of the hit pixels misclassified, each
// within one pixel of a shadow boundary of the reference.
inline constexpr double kExactBoundPercent = 0.01;

inline void requireBound(const HardScene& s, const ShadowOutputs& out, const std::string& what) {
    const Misclassified m = misclassified(s.gbuffer, s.reference, s.light(), out.visibility);
    INFO(what << ": " << m.count << " misclassified of " << m.hitPixels << " (" << m.percent() << "%), "
              << m.falseShadow << " false shadow, " << m.falseLight << " false light, " << m.awayFromBoundary
              << " more than one pixel from a reference boundary");
    CHECK(m.percent() <= kExactBoundPercent);
    CHECK(m.awayFromBoundary == 0);
}

inline double stat(const ShadowOutputs& out, const std::string& name) {
    const auto it = std::find_if(out.stats.begin(), out.stats.end(), [&](const TechniqueStat& s) { return s.name == name; });
    REQUIRE(it != out.stats.end());
    return it->value;
}

// Holds `run(level, threads)`, a V buffer, to `twin`'s bytes at every SIMD level this CPU
// has, on 1 and 2 threads.
template <class Run>
void checkSameBytesEverywhere(const std::vector<float>& twin, const Run& run) {
    for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (!raster::simdLevelSupported(level)) continue;
        for (int threads : {1, 2}) {
            INFO(raster::simdLevelName(level) << " with " << threads << " thread(s)");
            const std::vector<float> v = withThreads(threads, [&] { return run(level); });
            REQUIRE(v.size() == twin.size());
            CHECK(test::sameBytes(v, twin));
        }
    }
}

}  // namespace shadowlab::test
