// Stratified area-light sampling; see light_sampling.h for the sources.
#include "shading/light_sampling.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "raster/portable_math.h"
#include "shading/lights.h"

namespace shadowlab {

Pcg32::Pcg32(uint64_t seed, uint64_t stream) : increment_((stream << 1u) | 1u) {
    // pcg32_srandom_r: step once, add the seed, step again.
    next();
    state_ += seed;
    next();
}

uint32_t Pcg32::next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + increment_;
    const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rotation = uint32_t(old >> 59u);
    return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
}

double Pcg32::nextDouble() { return double(next()) * 0x1p-32; }

glm::dvec2 sobol02(uint32_t k) {
    uint32_t reversed = k, sobol = 0;
    // Bit reversal: the radical inverse in base 2.
    reversed = (reversed << 16) | (reversed >> 16);
    reversed = ((reversed & 0x00ff00ffu) << 8) | ((reversed & 0xff00ff00u) >> 8);
    reversed = ((reversed & 0x0f0f0f0fu) << 4) | ((reversed & 0xf0f0f0f0u) >> 4);
    reversed = ((reversed & 0x33333333u) << 2) | ((reversed & 0xccccccccu) >> 2);
    reversed = ((reversed & 0x55555555u) << 1) | ((reversed & 0xaaaaaaaau) >> 1);
    for (uint32_t v = 1u << 31; k != 0; k >>= 1, v ^= v >> 1) {
        if (k & 1u) sobol ^= v;
    }
    return glm::dvec2(reversed, sobol) * 0x1p-32;
}

glm::dvec2 shiftedSobol02(uint32_t k, const glm::dvec2& shift) {
    const glm::dvec2 p = sobol02(k) + shift;
    return p - glm::floor(p);   // multiples of 2^-32 below 2 (Pcg32's shifts too): exact
}

glm::dvec2 concentricSquareToDisk(const glm::dvec2& u) {
    const glm::dvec2 s = 2.0 * u - 1.0;  // [-1, 1]^2
    if (s.x == 0.0 && s.y == 0.0) {
        return glm::dvec2(0.0);
    }
    // The square of "radius" max(|x|, |y|) maps to the circle of that radius; the position
    // along the square's side maps linearly to the angle within the matching quarter.
    const double quarter = std::numbers::pi / 4.0;
    const bool nearXAxis = std::abs(s.x) > std::abs(s.y);
    const double r = nearXAxis ? s.x : s.y;
    const double phi = nearXAxis ? quarter * (s.y / s.x) : 2.0 * quarter - quarter * (s.x / s.y);
    return r * glm::dvec2(portable::cos(phi), portable::sin(phi));
}

AreaLightFrame areaLightFrame(const Light& light) {
    AreaLightFrame frame;
    frame.centre = glm::dvec3(light.position);
    if (light.type == LightType::Rectangle) {
        frame.axisA = glm::dvec3(light.halfEdgeU);
        frame.axisB = glm::dvec3(light.halfEdgeV);
        return frame;
    }
    if (light.type != LightType::Disk) {
        throw std::invalid_argument("areaLightFrame: not an area light");
    }
    // Orthonormal basis around the normal without a branch on an arbitrary "up" vector:
    // Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin, "Building an Orthonormal
    // Basis, Revisited", JCGT 6(1), 2017.
    const glm::dvec3 n = areaLightNormal(light);
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    const double radius = double(light.radius);
    frame.disk = true;
    frame.axisA = radius * glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    frame.axisB = radius * glm::dvec3(b, sign + n.y * n.y * a, -n.y);
    return frame;
}

AreaLightPlane areaLightPlane(const AreaLightFrame& frame) {
    const glm::dvec3 n = glm::cross(frame.axisA, frame.axisB);
    const double n2 = glm::dot(n, n);
    return {.disk = frame.disk,
            .centre = frame.centre,
            .normal = n / std::sqrt(n2),
            .dualA = glm::cross(frame.axisB, n) / n2,
            .dualB = glm::cross(n, frame.axisA) / n2};
}

glm::dvec3 areaLightPoint(const AreaLightFrame& frame, const glm::dvec2& u) {
    const glm::dvec2 m = frame.disk ? concentricSquareToDisk(u) : 2.0 * u - 1.0;
    return frame.centre + m.x * frame.axisA + m.y * frame.axisB;
}

glm::dvec2 jitteredSample(int a, int b, int n, Pcg32& rng) {
    const double jitterA = rng.nextDouble();
    const double jitterB = rng.nextDouble();
    return glm::dvec2((a + jitterA) / n, (b + jitterB) / n);
}

}  // namespace shadowlab

