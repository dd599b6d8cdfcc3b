// The specular lobes of brdf() (shading/shade.h) integrated over the hemisphere of incident
// directions: normalised Phong seen along the normal reflects exactly its specular
// reflectance, and GGX's directional albedo is the split-sum table's F0 A + B
// (shading/environment/split_sum_table.h, itself held to an independent brute force), so the
// BRDF that shades a pixel is the one the environment's split sum was built for.
#include <doctest/doctest.h>

#include <cmath>

#include "raster/portable_constants.h"
#include "shading/environment/split_sum_table.h"
#include "shading/shade.h"

using namespace shadowlab;

namespace {

// integral of f(wi, wo) (N . wi) dwi over the upper hemisphere, N = +Z, wo in the xz-plane;
// a midpoint grid fine in theta, and in phi finer towards the mirror's azimuth (phi = pi,
// where narrow lobes are), phi = pi (1 - (1 - t)^2) over the half y > 0, doubled.
glm::dvec3 directionalAlbedo(const Material& material, double cosV) {
    constexpr int kTheta = 2048, kPhi = 1024;
    const glm::vec3 N(0, 0, 1), wo(float(std::sqrt(1.0 - cosV * cosV)), 0.0f, float(cosV));
    glm::dvec3 sum(0.0);
    for (int a = 0; a < kTheta; ++a) {
        const double theta = 0.5 * kPi * (a + 0.5) / kTheta;
        for (int b = 0; b < kPhi; ++b) {
            const double t = (b + 0.5) / kPhi, phi = kPi * (1.0 - (1.0 - t) * (1.0 - t)), dPhi = 2.0 * kPi * (1.0 - t);
            const glm::vec3 wi(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                               float(std::cos(theta)));
            sum += glm::dvec3(brdf(material, material.albedo, N, wi, wo)) * (std::cos(theta) * std::sin(theta) * dPhi);
        }
    }
    return sum * (kPi / (double(kTheta) * kPhi));
}

// A material with its specular lobe alone.
Material specularOnly(MaterialModel model, const glm::vec3& specular) {
    Material m;
    m.model = model;
    m.albedo = glm::vec3(0.0f);
    m.specular = specular;
    return m;
}

}  // namespace

TEST_CASE("normalised Phong seen along the normal reflects exactly its specular reflectance") {
    for (float shininess : {1.0f, 40.0f, 500.0f}) {
        Material phong = specularOnly(MaterialModel::Phong, glm::vec3(1.0f, 0.5f, 0.25f));
        phong.shininess = shininess;
        const glm::dvec3 albedo = directionalAlbedo(phong, 1.0);
        CAPTURE(shininess);
        for (int c = 0; c < 3; ++c) CHECK(albedo[c] == doctest::Approx(phong.specular[c]).epsilon(2e-3));
        // Viewed obliquely, the part of the lobe below the horizon is lost.
        CHECK(directionalAlbedo(phong, 0.3).r < 0.99);
    }
}

TEST_CASE("GGX's directional albedo is the split-sum table's F0 A + B, and Lambert's is its albedo") {
    const SplitSumTable table = buildSplitSumTable(32);
    for (double cosV : {0.203125, 0.515625, 0.984375}) {
        for (float roughness : {0.140625f, 0.515625f, 0.984375f}) {
            Material ggx = specularOnly(MaterialModel::Ggx, glm::vec3(1.0f, 0.5f, 0.04f));
            ggx.roughness = roughness;
            const glm::dvec2 ab = lookupSplitSum(table, cosV, roughness);
            const glm::dvec3 albedo = directionalAlbedo(ggx, cosV);
            CAPTURE(cosV);
            CAPTURE(roughness);
            for (int c = 0; c < 3; ++c) CHECK(std::abs(albedo[c] - (ggx.specular[c] * ab.x + ab.y)) < 2e-3);
        }
    }
    Material lambert;
    lambert.albedo = glm::vec3(0.5f, 0.25f, 1.0f);
    const glm::dvec3 albedo = directionalAlbedo(lambert, 0.5);
    for (int c = 0; c < 3; ++c) CHECK(albedo[c] == doctest::Approx(lambert.albedo[c]).epsilon(1e-5));
}
