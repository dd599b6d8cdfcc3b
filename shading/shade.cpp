// Deferred shading: ambient plus the frame's lights, with visibility supplied by a shadow technique
// (or by the exact reference, shadows/reference/reference.h).
//
// The ambient term treats Environment::ambient as a constant radiance arriving from every
// direction: a Lambertian surface under uniform radiance La reflects albedo * La (the
// cosine-weighted hemisphere integral of albedo/pi is albedo). Threads own rows; each pixel
// is written once, so the output does not depend on the thread count.
#include "shading/shade.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/portable_math.h"
#include "shading/gbuffer_build.h"
#include "shading/lights.h"
#include "shading/microfacet_ggx.h"
#include "shading/surface_albedo.h"

namespace shadowlab {

namespace {

// The specular lobe of each model, for unit N, wi, wo (shade.h).
float blinnPhongLobe(float shininess, const glm::vec3& N, const glm::vec3& wi, const glm::vec3& wo) {
    const float cosH = std::max(0.0f, glm::dot(N, glm::normalize(wi + wo)));
    return (shininess + 8.0f) * (std::numbers::inv_pi_v<float> / 8.0f) * float(portable::pow(cosH, shininess));
}

float phongLobe(float shininess, const glm::vec3& N, const glm::vec3& wi, const glm::vec3& wo) {
    const glm::vec3 mirror = 2.0f * glm::dot(N, wo) * N - wo;
    const float cosR = std::max(0.0f, glm::dot(mirror, wi));
    return (shininess + 2.0f) * (std::numbers::inv_pi_v<float> / 2.0f) * float(portable::pow(cosR, shininess));
}

glm::vec3 ggxLobe(const Material& material, const glm::vec3& N, const glm::vec3& wi, const glm::vec3& wo) {
    const float cosL = glm::dot(N, wi), cosV = glm::dot(N, wo);
    if (cosL <= 0.0f || cosV <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 H = glm::normalize(wi + wo);
    const float w = schlickWeight(std::max(0.0f, glm::dot(wo, H)));
    const float dv = ggxDistribution(glm::dot(N, H), material.roughness) * smithVisibility(cosL, cosV, material.roughness);
    return dv * (material.specular * (1.0f - w) + w);
}

}  // namespace

glm::vec3 brdf(const Material& material, const glm::vec3& albedo, const glm::vec3& N, const glm::vec3& wi,
               const glm::vec3& wo) {
    const glm::vec3 diffuse = albedo * std::numbers::inv_pi_v<float>;
    switch (material.model) {
        case MaterialModel::Lambert: return diffuse;
        case MaterialModel::BlinnPhong: return diffuse + material.specular * blinnPhongLobe(material.shininess, N, wi, wo);
        case MaterialModel::Phong: return diffuse + material.specular * phongLobe(material.shininess, N, wi, wo);
        case MaterialModel::Ggx: return diffuse + ggxLobe(material, N, wi, wo);
    }
    return diffuse;
}

namespace {

glm::vec3 shadePixel(const Scene& scene, std::span<const ShadedLight> lights, const GBuffer& g, size_t index) {
    if (!g.hit[index]) {
        return glm::vec3(0.0f);
    }
    if (g.material[index] >= scene.materials.size()) {
        throw std::out_of_range("shade: material index " + std::to_string(g.material[index]) +
                                " out of range");
    }
    const Material& material = scene.materials[g.material[index]];
    const glm::vec3 P = g.position[index];
    const glm::vec3 N = g.normal[index];
    const glm::vec3 albedo = surfaceAlbedo(material, scene.albedoTextures, g, index);
    glm::vec3 radiance = scene.environment.ambient * albedo;
    for (const ShadedLight& shaded : lights) {
        const LightArrival arrival = lightArrival(scene.lights[shaded.light], P);
        const float cosIncidence = glm::dot(N, arrival.toLight);
        if (cosIncidence <= 0.0f) continue;   // the light is behind the surface
        const glm::vec3 wo = glm::normalize(scene.camera.eye - P);
        const glm::vec3 direct = brdf(material, albedo, N, arrival.toLight, wo) * arrival.irradiance * cosIncidence;
        const glm::vec3 visibility = shaded.colouredV.empty() ? glm::vec3(shaded.V[index]) : shaded.colouredV[index];
        radiance += visibility * direct;
    }
    return radiance;
}

void requireShadeable(const Scene& scene, const GBuffer& gbuffer, const ShadedLight& shaded) {
    if (shaded.light >= scene.lights.size()) {
        throw std::out_of_range("shade: light index " + std::to_string(shaded.light) + " but the scene has " +
                                std::to_string(scene.lights.size()) + " lights");
    }
    if (shaded.V.size() != gbuffer.pixelCount()) {
        throw std::invalid_argument("shade: visibility buffer has " + std::to_string(shaded.V.size()) +
                                    " entries, G-buffer has " + std::to_string(gbuffer.pixelCount()));
    }
    if (!shaded.colouredV.empty() && shaded.colouredV.size() != shaded.V.size()) {
        throw std::invalid_argument("shade: the coloured visibility has " + std::to_string(shaded.colouredV.size()) +
                                    " entries, V has " + std::to_string(shaded.V.size()));
    }
}

}  // namespace

std::vector<glm::vec3> shade(const Scene& scene, const GBuffer& gbuffer, std::span<const ShadedLight> lights) {
    requireConsistent(gbuffer, "shade");
    for (const ShadedLight& shaded : lights) requireShadeable(scene, gbuffer, shaded);
    std::vector<glm::vec3> radiance(gbuffer.pixelCount());
    tbb::parallel_for(tbb::blocked_range<int>(0, gbuffer.height), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < gbuffer.width; ++i) {
                const size_t index = gbuffer.index(i, j);
                radiance[index] = shadePixel(scene, lights, gbuffer, index);
            }
        }
    });
    return radiance;
}

std::vector<glm::vec3> shade(const Scene& scene, const GBuffer& gbuffer, size_t lightIndex,
                             const std::vector<float>& V, std::span<const glm::vec3> colouredV) {
    const ShadedLight one{lightIndex, V, colouredV};
    return shade(scene, gbuffer, std::span(&one, 1));
}

}  // namespace shadowlab
