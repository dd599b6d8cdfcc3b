#include "shadows/environment/light_lobes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "raster/portable_math.h"

namespace shadowlab {

std::vector<Material> widenedForRegion(std::vector<Material> materials, double solidAngle) {
    const double cosRho = std::clamp(1.0 - solidAngle / (2.0 * std::numbers::pi), -1.0, 1.0);
    const double rho = portable::acos(cosRho), rho2 = rho * rho;
    for (Material& m : materials) {
        switch (m.model) {
            case MaterialModel::Lambert: break;
            case MaterialModel::Phong: m.shininess = float(1.0 / (1.0 / m.shininess + rho2 / 4.0)); break;
            case MaterialModel::BlinnPhong: m.shininess = float(1.0 / (1.0 / m.shininess + rho2 / 16.0)); break;
            case MaterialModel::Ggx:
                m.roughness = float(std::min(1.0, std::sqrt(double(m.roughness) * m.roughness + rho2 / 4.0)));
                break;
        }
    }
    return materials;
}

std::vector<Material> lightMaterials(const Scene& scene, const EnvironmentLight& light, LightLobes lobes) {
    if (lobes == LightLobes::Point) return scene.materials;
    return widenedForRegion(scene.materials, light.solidAngle);
}

}  // namespace shadowlab
