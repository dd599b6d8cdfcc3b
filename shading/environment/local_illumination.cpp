#include "shading/environment/local_illumination.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "raster/portable_constants.h"
#include "scenes/error_text.h"

namespace shadowlab {
namespace {

void refuseBlinnPhong(const Material& material) {
    if (material.model == MaterialModel::BlinnPhong) {
        throw std::invalid_argument("material " + inQuotes(material.name) +
                                    ": Blinn-Phong cannot be lit by a prefiltered environment; use phong or ggx");
    }
}

void requireTable(const PrefilteredLobes& table, const Material& material) {
    if (table.maps.empty()) {
        throw std::invalid_argument("material " + inQuotes(material.name) + ": no prefiltered table was built for its model");
    }
}

}  // namespace

LocalIllumination buildLocalIllumination(const EnvironmentMap& map, const std::vector<Material>& materials) {
    std::vector<double> shininess, roughness;
    for (const Material& material : materials) {
        refuseBlinnPhong(material);
        try {
            if (material.model == MaterialModel::Phong) {
                checkLobe(GlossyLobe::NormalisedPhong, material.shininess, map);
                shininess.push_back(material.shininess);
            } else if (material.model == MaterialModel::Ggx) {
                checkLobe(GlossyLobe::Ggx, material.roughness, map);
                roughness.push_back(material.roughness);
            }
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("material " + inQuotes(material.name) + ": " + e.what());
        }
    }
    LocalIllumination light;
    light.irradiance = irradianceOf(projectRadiance(map));
    // Each material's own parameter is an entry, so its lookup reads its own map.
    if (!shininess.empty()) light.phong = prefilterLobes(map, GlossyLobe::NormalisedPhong, shininess);
    if (!roughness.empty()) {
        light.ggx = prefilterLobes(map, GlossyLobe::Ggx, roughness);
        light.splitSum = buildSplitSumTable();
    }
    return light;
}

glm::dvec3 unshadowedRadiance(const LocalIllumination& light, const Material& material, const glm::vec3& albedo,
                              const glm::dvec3& N, const glm::dvec3& wo) {
    refuseBlinnPhong(material);
    const glm::dvec3 diffuse = glm::dvec3(albedo) / kPi * evaluateSh(light.irradiance, N);
    if (material.model == MaterialModel::Lambert) return diffuse;
    const double cosV = glm::dot(N, wo);
    if (cosV <= 0.0) return diffuse;   // seen from below its shading normal: no lobe above
    const glm::dvec3 mirror = 2.0 * cosV * N - wo;
    if (material.model == MaterialModel::Phong) {
        requireTable(light.phong, material);
        return diffuse + glm::dvec3(material.specular) * cosV * lookupPrefiltered(light.phong, material.shininess, mirror);
    }
    requireTable(light.ggx, material);
    const glm::dvec2 ab = lookupSplitSum(light.splitSum, cosV, material.roughness);
    const glm::dvec3 reflectance = glm::dvec3(material.specular) * ab.x + ab.y;
    return diffuse + reflectance * lookupPrefiltered(light.ggx, material.roughness, mirror);
}

}  // namespace shadowlab
