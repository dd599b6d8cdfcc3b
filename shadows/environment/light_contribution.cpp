#include "shadows/environment/light_contribution.h"

#include <atomic>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/lights.h"
#include "shading/shade.h"
#include "shading/surface_albedo.h"

namespace shadowlab {
namespace {

struct DistantArrival {
    LightArrival arrival;
    LightArrival operator()(const glm::vec3&) const { return arrival; }
};

struct SceneArrival {
    const Light& light;
    LightArrival operator()(const glm::vec3& P) const { return lightArrival(light, P); }
};

// The one loop both kinds of light share; Arrival is compiled in, not called through a pointer.
template <class Arrival>
uint64_t addLight(const GBuffer& g, const std::vector<Material>& materials, const std::vector<AlbedoTexture>& albedoTextures,
                  const glm::vec3& eye, const Arrival& arrivalAt,
                  const std::vector<float>& V, LightPart part, std::vector<glm::vec3>& sum) {
    if (V.size() != g.pixelCount() || sum.size() != g.pixelCount())
        throw std::invalid_argument("light contribution: V and the sum need one entry per pixel");
    std::atomic<uint64_t> shaded{0};
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        uint64_t count = 0;
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                const float weight = part == LightPart::Lit ? V[k] : 1.0f - V[k];
                if (!g.hit[k] || weight == 0.0f) continue;
                const LightArrival a = arrivalAt(g.position[k]);
                const glm::vec3& N = g.shadingNormal[k];
                const float cosine = glm::dot(N, a.toLight);
                ++count;
                if (!(cosine > 0.0f)) continue;
                const glm::vec3 wo = glm::normalize(eye - g.position[k]);
                const Material& material = materials.at(g.material[k]);
                const glm::vec3 albedo = surfaceAlbedo(material, albedoTextures, g, k);
                sum[k] += weight * brdf(material, albedo, N, a.toLight, wo) * a.irradiance * cosine;
            }
        }
        shaded += count;   // an integer sum: the same in any order
    });
    return shaded.load();
}

}  // namespace

uint64_t addDistantLight(const GBuffer& g, const std::vector<Material>& materials,
                         const std::vector<AlbedoTexture>& albedoTextures, const glm::vec3& eye,
                         const glm::vec3& toLight, const glm::vec3& irradiance, const std::vector<float>& V,
                         LightPart part, std::vector<glm::vec3>& sum) {
    return addLight(g, materials, albedoTextures, eye, DistantArrival{{toLight, irradiance}}, V, part, sum);
}

uint64_t addSceneLight(const GBuffer& g, const std::vector<Material>& materials,
                       const std::vector<AlbedoTexture>& albedoTextures, const glm::vec3& eye, const Light& light,
                       const std::vector<float>& V, LightPart part, std::vector<glm::vec3>& sum) {
    return addLight(g, materials, albedoTextures, eye, SceneArrival{light}, V, part, sum);
}

}  // namespace shadowlab
