// The illuminance buffer's vector kernels (shadows/fins/illuminance_kernel.h): the AVX2 and
// AVX-512 builds against their scalar twin, bit for bit, and the scalar twin against the
// plain double expressions of the paper (Cai et al. 2006, section 3.4, eqs. 2 to 5) written
// here from the receiver the shadow-map code makes (mapReceiverFromPoint).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "shadows/fins/fin_maps.h"
#include "shadows/fins/illuminance_buffer.h"
#include "shadows/fins/illuminance_kernel.h"
#include "shadows/maps/shadow_bias.h"
#include "tests/raster/raster_test_util.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using test::sameBits;

namespace {

fins::IlluminanceKernels illuminanceKernelsOf(raster::SimdLevel level) {
    return raster::forSimdLevel(level, fins::illuminanceKernelsScalar, fins::illuminanceKernelsAvx2,
                                fins::illuminanceKernelsAvx512);
}

// A disk light at y = 6 facing down (tilted, so every term of L_r counts), its view a perspective frustum along -y, and a map of
// `size` texels: the fins' configuration (fin_shadows.cpp), with receivers below the light.
struct Setup {
    int size = 256;
    LightPlane light{{0.3, 6.0, -0.2}, glm::normalize(glm::dvec3(0.15, -1.0, 0.1)), 0.5};
    LightView view;
    DepthMap map;
    Setup() {
        view.zNear = 0.5, view.zFar = 12.0;
        view.clipFromView = glm::perspective(1.2, 1.0, view.zNear, view.zFar);
        view.viewFromWorld = glm::lookAt(light.centre, light.centre + light.normal, glm::dvec3(0.0, 0.0, 1.0));
        map.size = size;
        map.texelFromWorld = texelFromWorldOf(glm::mat4(view.clipFromView * view.viewFromWorld), size);
    }
    fins::PlaceConstants place() const { return placeConstants(map, light); }
};

// Receivers inside the frustum, some beyond its sides (clamped texels), on the light's plane
// and above it (w <= 0: texels at the saturation limits or NaN).
std::vector<float> receivers(size_t n, std::mt19937& rng) {
    std::uniform_real_distribution<float> across(-9.0f, 9.0f), height(-4.0f, 5.9f);
    std::vector<float> p(3 * n);
    for (size_t k = 0; k < n; ++k) {
        p[3 * k] = across(rng), p[3 * k + 1] = k % 97 == 0 ? 6.0f : k % 89 == 0 ? 7.5f : height(rng), p[3 * k + 2] = across(rng);
    }
    return p;
}

struct Placed {
    std::vector<double> column[4];
    explicit Placed(size_t n) {
        for (std::vector<double>& c : column) c.assign(n, -7.0);
    }
    fins::PlacedColumns columns() { return {column[0].data(), column[1].data(), column[2].data(), column[3].data()}; }
};

// The receivers P placed by a level's kernel.
Placed placedBy(raster::SimdLevel level, const Setup& setup, const std::vector<float>& P) {
    Placed placed(P.size() / 3);
    illuminanceKernelsOf(level).place(setup.place(), P.data(), uint32_t(P.size() / 3), placed.columns());
    return placed;
}

// The maps' values at the placed texels: hard depths around the receivers' own (some empty,
// 1), fin depths in front of and behind them (some uncovered, 1), weights in [0, 1].
struct Texels {
    std::vector<double> column[5];
    Texels(const Placed& placed, std::mt19937& rng) {
        std::uniform_real_distribution<double> jitter(-0.02, 0.02), weight(0.0, 1.0), fin(0.2, 1.0);
        const size_t n = placed.column[0].size();
        for (std::vector<double>& c : column) c.resize(n);
        for (size_t k = 0; k < n; ++k) {
            const double depth = placed.column[2][k];
            column[0][k] = k % 11 == 0 ? 1.0 : double(float(depth + jitter(rng)));
            column[1][k] = k % 5 == 0 ? 1.0 : double(float(fin(rng)));
            column[3][k] = k % 7 == 0 ? 1.0 : double(float(fin(rng)));
            column[2][k] = double(float(weight(rng))), column[4][k] = double(float(weight(rng)));
        }
    }
    fins::TexelColumns columns(bool inner) const {
        return {column[0].data(), inner ? column[1].data() : nullptr, inner ? column[2].data() : nullptr, column[3].data(),
                column[4].data()};
    }
};

// Eqs. 2 to 5 for one fin over a receiver at L_r, and the fall-off (illuminance_buffer.h).
double finTerm(double finDepth, double s0, double Lr, const LightView& view, double L0, double e, bool bernstein) {
    if (!(finDepth < 1.0)) return 0.0;
    const double Lb = lightDistanceOfDepth(view, finDepth);
    if (!(Lb < Lr)) return 0.0;
    const double widthRatio = ((L0 - Lb) / L0) * (Lr / (Lr - Lb));   // B_0 / B_r
    const double s = std::clamp(e + widthRatio * (s0 - e), 0.0, e);
    return bernstein ? s * s * (3.0 - 2.0 * s) : s;
}

}  // namespace

TEST_CASE("fins illuminance place kernel: every SIMD level gives the scalar twin's bits, which are mapReceiver's") {
    std::mt19937 rng(11);
    const Setup setup;
    const size_t n = 2048;
    const std::vector<float> P = receivers(n, rng);
    const Placed twin = placedBy(raster::SimdLevel::Scalar, setup, P);
    int clampedOrSaturated = 0;
    for (size_t k = 0; k < n; ++k) {
        const glm::dvec3 p(P[3 * k], P[3 * k + 1], P[3 * k + 2]);
        const MapReceiver r = mapReceiverFromPoint(setup.map, p, glm::dvec3(0.0, 1.0, 0.0), setup.light.centre, BiasSettings{});
        const int x = std::clamp(texelIndexOf(r.texel.x), 0, setup.size - 1), y = std::clamp(texelIndexOf(r.texel.y), 0, setup.size - 1);
        clampedOrSaturated += x != texelIndexOf(r.texel.x) || y != texelIndexOf(r.texel.y);
        INFO("receiver " << k);
        CHECK(twin.column[0][k] == x);
        CHECK(twin.column[1][k] == y);
        CHECK(sameBits(twin.column[2][k], r.depthAt(glm::dvec2(x + 0.5, y + 0.5))));
        CHECK(sameBits(twin.column[3][k], setup.light.distance(p)));
    }
    CHECK(clampedOrSaturated > 100);   // the border cases were exercised
    for (raster::SimdLevel level : test::supportedLevels()) {
        INFO(raster::simdLevelName(level));
        const Placed got = placedBy(level, setup, P);
        for (int c = 0; c < 4; ++c) {
            for (size_t k = 0; k < n; ++k) REQUIRE(sameBits(got.column[c][k], twin.column[c][k]));
        }
    }
}

TEST_CASE("fins illuminance kernel: every SIMD level gives the scalar twin's bits, which are eqs. 2 to 5 and min(I, local)") {
    std::mt19937 rng(12);
    const Setup setup;
    const size_t n = 2048;
    const std::vector<float> P = receivers(n, rng);
    Placed placed = placedBy(raster::SimdLevel::Scalar, setup, P);
    const Texels texels(placed, rng);
    std::vector<float> before(n);
    for (size_t k = 0; k < n; ++k) before[k] = k % 3 == 0 ? 0.0f : k % 3 == 1 ? 1.0f : 0.6f;
    const double L0 = setup.view.zFar;
    for (bool inner : {true, false}) {
        for (bool bernstein : {false, true}) {
            const double e = inner ? 0.5 : 1.0;
            const fins::IlluminateConstants c{setup.view.clipFromView[2][2], setup.view.clipFromView[3][2], L0, e, bernstein};
            std::vector<float> twin = before;
            illuminanceKernelsOf(raster::SimdLevel::Scalar).illuminate(c, placed.columns(), texels.columns(inner), uint32_t(n), twin.data());
            int penumbra = 0;
            for (size_t k = 0; k < n; ++k) {
                const double stored = texels.column[0][k], Lr = placed.column[3][k];
                double local = stored >= 1.0 || placed.column[2][k] <= stored ? 1.0 : 0.0;
                if (inner) local += finTerm(texels.column[1][k], texels.column[2][k], Lr, setup.view, L0, e, bernstein);
                local -= finTerm(texels.column[3][k], texels.column[4][k], Lr, setup.view, L0, e, bernstein);
                const float expected = std::min(before[k], float(std::clamp(local, 0.0, 1.0)));
                penumbra += expected > 0.0f && expected < 1.0f && expected != before[k];
                INFO("pixel " << k << " inner " << inner << " bernstein " << bernstein);
                REQUIRE(std::memcmp(&twin[k], &expected, sizeof expected) == 0);
            }
            CHECK(penumbra > 50);   // fin weights reached the buffer, not only 0 and 1
            for (raster::SimdLevel level : test::supportedLevels()) {
                INFO(raster::simdLevelName(level));
                std::vector<float> got = before;
                illuminanceKernelsOf(level).illuminate(c, placed.columns(), texels.columns(inner), uint32_t(n), got.data());
                CHECK(std::memcmp(got.data(), twin.data(), n * sizeof(float)) == 0);
            }
        }
    }
}
