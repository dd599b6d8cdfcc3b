#include "shading/environment/environment_map.h"

#include <algorithm>
#include <cmath>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab {

double EnvironmentMap::rowEdgeTheta(int j) const { return kPi * double(j) / double(height); }

double EnvironmentMap::columnEdgePhi(int i) const {
    return 2.0 * kPi * (double(i) / double(width) - 0.5) - rotationRadians;
}

double EnvironmentMap::texelSolidAngle(int j) const {
    return (2.0 * kPi / double(width)) * (portable::cos(rowEdgeTheta(j)) - portable::cos(rowEdgeTheta(j + 1)));
}

glm::dvec3 EnvironmentMap::direction(double u, double v) const {
    const double phi = 2.0 * kPi * (u - 0.5) - rotationRadians, theta = kPi * v;
    const double sinTheta = portable::sin(theta);
    return {sinTheta * portable::sin(phi), portable::cos(theta), -sinTheta * portable::cos(phi)};
}

glm::dvec2 EnvironmentMap::coordinates(const glm::dvec3& d) const {
    const double length = std::sqrt(glm::dot(d, d));
    // The map's own azimuth: the world's plus the rotation, wrapped into [0, 1).
    double u = 0.5 + (portable::atan2(d.x, -d.z) + rotationRadians) / (2.0 * kPi);
    u -= std::floor(u);
    if (u >= 1.0) u = 0.0;   // -1e-17 - floor(-1e-17) rounds to 1
    return {u, portable::acos(std::clamp(d.y / length, -1.0, 1.0)) / kPi};
}

glm::ivec2 EnvironmentMap::texelToward(const glm::dvec3& d) const {
    const glm::dvec2 uv = coordinates(d);
    if (!(uv.x >= 0.0 && uv.y >= 0.0)) return {0, 0};   // a NaN direction: no undefined int conversion
    return {std::min(int(uv.x * width), width - 1), std::min(int(uv.y * height), height - 1)};
}

glm::dvec3 environmentPower(const EnvironmentMap& map) {
    glm::dvec3 total(0.0);
    for (int j = 0; j < map.height; ++j) {
        const double solidAngle = map.texelSolidAngle(j);
        for (int i = 0; i < map.width; ++i) total += glm::dvec3(map.at(i, j)) * solidAngle;
    }
    return total;
}

EnvironmentMap constantEnvironment(int width, int height, const glm::vec3& radiance) {
    EnvironmentMap map;
    map.width = width, map.height = height;
    map.radiance.assign(size_t(width) * size_t(height), radiance);
    map.source = "constant";
    return map;
}

}  // namespace shadowlab
