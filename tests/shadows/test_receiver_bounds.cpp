// The receivers' bounds kernel of light-view fitting (shadows/receiver_bounds.h): the AVX2
// and AVX-512 builds against the scalar twin, and the twin against glm's double expressions
// it replaces; and the fitted views the same at every SIMD level.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shadows/light_view.h"
#include "shadows/receiver_bounds.h"
#include "tests/raster/raster_test_util.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using test::sameBits;

namespace {

// Every level's kernels, chosen as light_view.cpp chooses them.
const BoundsKernels& boundsKernelsOf(raster::SimdLevel level) {
    return raster::forSimdLevel(level, boundsKernelsScalar, boundsKernelsAvx2, boundsKernelsAvx512);
}

}  // namespace

TEST_CASE("receiver bounds: the scalar twin is glm's double expression, every SIMD level gives its bits") {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const size_t n = 1000 + 5;   // a tail shorter than any vector
    std::vector<glm::vec3> position(n);
    std::vector<uint8_t> served(n);
    for (size_t k = 0; k < n; ++k) {
        position[k] = glm::vec3(4.0f * unit(rng), 2.0f * unit(rng) - 1.0f, 4.0f * unit(rng));
        served[k] = k % 5 != 0;
    }
    // A point far outside that is not served, so it must not move any bound.
    position[7] = glm::vec3(1e6f, -1e6f, 1e6f), served[7] = 0;
    const glm::dmat4 view = glm::lookAtRH(glm::dvec3(0.5, 6.0, 0.3), glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(1, 0, 0));
    const float* p = glm::value_ptr(position[0]);
    for (const int space : {int(kWorldBox), int(kOrthographicView), int(kPerspectiveView)}) {
        CAPTURE(space);
        BoundsResult expected = emptyBounds();
        for (size_t k = 0; k < n; ++k) {
            if (!served[k]) continue;
            glm::dvec3 v(position[k]);
            if (space != kWorldBox) {
                const glm::dvec3 q = glm::dvec3(view * glm::dvec4(v, 1.0));
                v = space == kPerspectiveView ? glm::dvec3(q.x / -q.z, q.y / -q.z, -q.z) : glm::dvec3(q.x, q.y, -q.z);
            }
            for (int c = 0; c < 3; ++c) expected.lo[c] = std::min(expected.lo[c], v[c]), expected.hi[c] = std::max(expected.hi[c], v[c]);
        }
        BoundsResult scalar = emptyBounds();
        boundsKernelsScalar().space[space]({p, served.data(), n, glm::value_ptr(view)}, scalar);
        for (int c = 0; c < 3; ++c) {
            CHECK(sameBits(scalar.lo[c], expected.lo[c]));
            CHECK(sameBits(scalar.hi[c], expected.hi[c]));
        }
        CHECK_FALSE(scalar.behindApex);
        for (raster::SimdLevel level : test::supportedLevels()) {
            CAPTURE(raster::simdLevelName(level));
            const BoundsKernels& k = boundsKernelsOf(level);
            const size_t body = n / size_t(k.width) * size_t(k.width);
            BoundsResult vector = emptyBounds();
            k.space[space]({p, served.data(), body, glm::value_ptr(view)}, vector);
            boundsKernelsScalar().space[space]({p + 3 * body, served.data() + body, n - body, glm::value_ptr(view)}, vector);
            for (int c = 0; c < 3; ++c) {
                CHECK(sameBits(vector.lo[c], scalar.lo[c]));
                CHECK(sameBits(vector.hi[c], scalar.hi[c]));
            }
            CHECK(vector.behindApex == scalar.behindApex);
        }
    }
    // A served point behind the apex is flagged at every level; the same point unserved is not.
    position[8] = glm::vec3(0.5f, 9.0f, 0.3f);
    for (const uint8_t flag : {uint8_t(1), uint8_t(0)}) {
        served[8] = flag;
        BoundsResult scalar = emptyBounds();
        boundsKernelsScalar().space[kPerspectiveView]({p, served.data(), n, glm::value_ptr(view)}, scalar);
        CHECK(scalar.behindApex == bool(flag));
        for (raster::SimdLevel level : test::supportedLevels()) {
            const BoundsKernels& k = boundsKernelsOf(level);
            BoundsResult vector = emptyBounds();
            k.space[kPerspectiveView]({p, served.data(), n / size_t(k.width) * size_t(k.width), glm::value_ptr(view)}, vector);
            CHECK(vector.behindApex == bool(flag));
        }
    }
}

TEST_CASE("fitLightView gives the same view at every SIMD level, for point, spot and directional lights") {
    Scene scene = loadScene("sphere-box");
    const WorldGeometry world = flatten(scene);
    const GBuffer g = renderGBuffer(world, scene.camera, raster::SimdLevel::Scalar);
    Light point = pointLightFor(scene.lights[0]);
    Light spot = point;
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(glm::vec3(0.0f) - spot.position);
    spot.coneAngleDeg = 25.0f;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    for (const Light& light : {point, spot, sun}) {
        CAPTURE(int(light.type));
        LightFitOptions options;
        options.simd = raster::SimdLevel::Scalar;
        const LightView scalar = fitLightView(light, g, world, options);
        for (raster::SimdLevel level : test::supportedLevels()) {
            options.simd = level;
            const LightView other = fitLightView(light, g, world, options);
            CHECK(std::memcmp(glm::value_ptr(other.viewFromWorld), glm::value_ptr(scalar.viewFromWorld), 16 * sizeof(double)) == 0);
            CHECK(std::memcmp(glm::value_ptr(other.clipFromView), glm::value_ptr(scalar.clipFromView), 16 * sizeof(double)) == 0);
        }
    }
}
