// BRDF sampling (brdf_sampling.h): for every model the mixture's density integrates to 1
// over the sphere, and a drawn direction's stated density is brdfPdf of it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "shading/brdf_sampling.h"
#include "shading/light_sampling.h"

using namespace shadowlab;

namespace {

std::vector<Material> materials() {
    return {{.name = "lambert", .albedo = glm::vec3(0.5f)},
            {.name = "phong", .model = MaterialModel::Phong, .albedo = glm::vec3(0.3f), .specular = glm::vec3(0.4f), .shininess = 40},
            {.name = "blinn", .model = MaterialModel::BlinnPhong, .albedo = glm::vec3(0.2f), .specular = glm::vec3(0.6f), .shininess = 60},
            {.name = "ggx", .model = MaterialModel::Ggx, .albedo = glm::vec3(0.1f), .specular = glm::vec3(0.9f), .roughness = 0.3f}};
}

}  // namespace

TEST_CASE("brdf sampling: the density of every model integrates to 1 over the sphere") {
    const glm::dvec3 N(0.0, 0.0, 1.0), wo = glm::normalize(glm::dvec3(0.5, 0.1, 0.8));
    for (const Material& m : materials()) {
        INFO(m.name);
        // Midpoint rule in (cos theta, phi): 2000 x 1000 cells, uniform in solid angle.
        const int nz = 2000, nphi = 1000;
        double integral = 0.0;
        for (int a = 0; a < nz; ++a) {
            const double z = -1.0 + (a + 0.5) * 2.0 / nz, r = std::sqrt(1.0 - z * z);
            for (int b = 0; b < nphi; ++b) {
                const double phi = (b + 0.5) * 2.0 * 3.141592653589793 / nphi;
                integral += brdfPdf(m, N, wo, {r * std::cos(phi), r * std::sin(phi), z});
            }
        }
        integral *= (2.0 / nz) * (2.0 * 3.141592653589793 / nphi);
        CHECK(integral == doctest::Approx(1.0).epsilon(0.01));
    }
}

TEST_CASE("brdf sampling: draws follow the stated density (sum g / pdf estimates the integral of g)") {
    // g is positive on the upper hemisphere only, which every mixture covers (albedo > 0),
    // and peaks about the mirror direction, where the specular lobes put their draws; a
    // sampler whose draws did not follow brdfPdf (a lost Jacobian, a wrong lobe) would miss.
    const glm::dvec3 N = glm::normalize(glm::dvec3(0.2, 0.9, -0.1)), wo = glm::normalize(glm::dvec3(0.6, 0.7, 0.3));
    const glm::dvec3 R = 2.0 * glm::dot(N, wo) * N - wo;
    const auto g = [&](const glm::dvec3& w) {
        const double c = glm::dot(N, w);
        return c > 0.0 ? c * (1.0 + 10.0 * std::pow(std::max(0.0, glm::dot(R, w)), 20.0)) : 0.0;
    };
    // The integral by the midpoint rule in (cos theta, phi) about N.
    const glm::dvec3 t = glm::normalize(glm::cross(N, glm::dvec3(1.0, 0.0, 0.0))), b = glm::cross(N, t);
    const int nz = 2000, nphi = 2000;
    double exact = 0.0;
    for (int a = 0; a < nz; ++a) {
        const double z = (a + 0.5) / nz, r = std::sqrt(1.0 - z * z);
        for (int k = 0; k < nphi; ++k) {
            const double phi = (k + 0.5) * 2.0 * 3.141592653589793 / nphi;
            exact += g(r * std::cos(phi) * t + r * std::sin(phi) * b + z * N);
        }
    }
    exact *= (1.0 / nz) * (2.0 * 3.141592653589793 / nphi);
    for (const Material& m : materials()) {
        INFO(m.name);
        Pcg32 rng(11, 5);
        const int n = 400000;
        double sum = 0.0;
        for (int s = 0; s < n; ++s) {
            const BrdfSample draw = sampleBrdf(m, N, wo, {rng.nextDouble(), rng.nextDouble(), rng.nextDouble()});
            CHECK(std::abs(glm::length(draw.direction) - 1.0) < 1e-12);
            if (draw.pdf > 0.0) sum += g(draw.direction) / draw.pdf;
        }
        CHECK(sum / n == doctest::Approx(exact).epsilon(0.01));
    }
}
