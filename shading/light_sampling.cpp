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

namespace {

// The disk point of the concentric map in polar form, r (cos phi, sin phi); the square's
// centre, where phi is undefined, is the disk's.
struct ConcentricPolar {
    bool centre;
    double r, phi;
};

ConcentricPolar concentricPolar(const glm::dvec2& u) {
    const glm::dvec2 s = 2.0 * u - 1.0;  // [-1, 1]^2
    // The square of "radius" max(|x|, |y|) maps to the circle of that radius; the position
    // along the square's side maps linearly to the angle within the matching quarter. Both
    // quarters' angles are computed and one kept, for which one is a coin flip per stratum
    // that a branch would mispredict; the centre's is 0 (0/0 there is never kept).
    const double quarter = std::numbers::pi / 4.0;
    const bool centre = s.x == 0.0 && s.y == 0.0;
    const bool nearXAxis = std::abs(s.x) > std::abs(s.y);
    const double nearX = quarter * (s.y / s.x), nearY = 2.0 * quarter - quarter * (s.x / s.y);
    return {centre, nearXAxis ? s.x : s.y, centre ? 0.0 : nearXAxis ? nearX : nearY};
}

glm::dvec3 lightPointAt(const AreaLightFrame& frame, const glm::dvec2& m) {
    return frame.centre + m.x * frame.axisA + m.y * frame.axisB;
}

// sin(r + turns pi/2) from sin r and cos r, turns taken modulo 4 (two's complement): the
// pick of portable::sin and cos by quadrant (raster/portable_math.h, sinQuarterTurns: sin r,
// cos r, -sin r, -cos r), as selects, for the quadrant is random from stratum to stratum.
double quarterTurns(int turns, double sinR, double cosR) {
    const double value = turns & 1 ? cosR : sinR;
    return turns & 2 ? -value : value;
}

// portable_math.h's reduceHalfPi of an angle in [-pi/4, 3pi/4], the concentric map's, with
// the same operations but for the quadrant: k = floor(phi 2/pi + 1/2) is a small integer
// (-1 to 2, rounding at the ends), so int(k) is exact, and quarterTurns' `& 1`, `& 2` read
// it modulo 4 as reduceHalfPi's fmod does, with no library call.
double reduceConcentricAngle(double phi, int& quadrant) {
    const double k = std::floor(phi * portable::detail::kTwoOverPi + 0.5);
    quadrant = int(k);
    return (phi - k * portable::detail::kHalfPiHigh) - k * portable::detail::kHalfPiLow;
}

// An orthonormal basis (a, b) around a unit n, without a branch on an arbitrary "up"
// vector: Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin, "Building an
// Orthonormal Basis, Revisited", JCGT 6(1), 2017.
struct Basis {
    glm::dvec3 a, b;
};
Basis orthonormalBasis(const glm::dvec3& n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return {glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), glm::dvec3(b, sign + n.y * n.y * a, -n.y)};
}

}  // namespace

glm::dvec2 concentricSquareToDisk(const glm::dvec2& u) {
    const ConcentricPolar p = concentricPolar(u);
    return p.centre ? glm::dvec2(0.0) : p.r * glm::dvec2(portable::cos(p.phi), portable::sin(p.phi));
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
    const Basis basis = orthonormalBasis(areaLightNormal(light));
    const double radius = double(light.radius);
    frame.disk = true;
    frame.axisA = radius * basis.a;
    frame.axisB = radius * basis.b;
    return frame;
}

SunCap sunCap(const Light& light) {
    if (light.type != LightType::Directional || !(light.angularDiameterDeg > 0.0f)) {
        throw std::invalid_argument("sunCap: not a directional light with an angular size");
    }
    const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
    const Basis basis = orthonormalBasis(axis);
    // theta_max / 2 in radians; 1 - cos(theta_max) = 2 sin^2(theta_max / 2).
    const double quarterAngle = double(light.angularDiameterDeg) * (std::numbers::pi / 720.0);
    const double s = portable::sin(quarterAngle);
    return {.axis = axis, .tangentA = basis.a, .tangentB = basis.b, .oneMinusCosMax = 2.0 * s * s};
}

glm::dvec3 sunCapDirection(const SunCap& cap, const glm::dvec2& m) {
    const double h = cap.oneMinusCosMax, r2h = glm::dot(m, m) * h;
    return (1.0 - r2h) * cap.axis + std::sqrt(h * (2.0 - r2h)) * (m.x * cap.tangentA + m.y * cap.tangentB);
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
    return lightPointAt(frame, frame.disk ? concentricSquareToDisk(u) : 2.0 * u - 1.0);
}

glm::dvec2 jitteredSample(int a, int b, int n, Pcg32& rng) {
    const double jitterA = rng.nextDouble();
    const double jitterB = rng.nextDouble();
    return glm::dvec2((a + jitterA) / n, (b + jitterB) / n);
}

}  // namespace shadowlab


namespace shadowlab {

void AreaLightPoints::jitter(int n, Pcg32& rng) {
    const size_t count = size_t(n) * size_t(n);
    u_.resize(count);
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) u_[size_t(a) + size_t(n) * size_t(b)] = jitteredSample(a, b, n, rng);
    }
}

void AreaLightPoints::squaresToDisk() {
    const size_t count = u_.size();
    centre_.resize(count), radius_.resize(count), reduced_.resize(count), sine_.resize(count), cosine_.resize(count),
        quadrant_.resize(count);
    for (size_t k = 0; k < count; ++k) {   // the centre's phi is reduced, then unused
        const ConcentricPolar p = concentricPolar(u_[k]);
        centre_[k] = p.centre, radius_[k] = p.r;
        reduced_[k] = reduceConcentricAngle(p.phi, quadrant_[k]);
    }
    for (size_t k = 0; k < count; ++k) {   // no branch: vectorised
        sine_[k] = portable::detail::sinReduced(reduced_[k]);
        cosine_[k] = portable::detail::cosReduced(reduced_[k]);
    }
    for (size_t k = 0; k < count; ++k) {
        const double c = quarterTurns(quadrant_[k] + 1, sine_[k], cosine_[k]);
        const double s = quarterTurns(quadrant_[k], sine_[k], cosine_[k]);
        u_[k] = centre_[k] ? glm::dvec2(0.0) : radius_[k] * glm::dvec2(c, s);
    }
}

void AreaLightPoints::place(const AreaLightFrame& frame) {
    points_.resize(u_.size());
    if (frame.disk) {
        squaresToDisk();
    } else {
        for (glm::dvec2& u : u_) u = 2.0 * u - 1.0;
    }
    for (size_t k = 0; k < u_.size(); ++k) points_[k] = lightPointAt(frame, u_[k]);
}

void AreaLightPoints::place(const SunCap& cap) {
    points_.resize(u_.size());
    squaresToDisk();
    for (size_t k = 0; k < u_.size(); ++k) points_[k] = sunCapDirection(cap, u_[k]);
}

void AreaLightPoints::fill(const AreaLightFrame& frame, int n, Pcg32& rng) {
    jitter(n, rng);
    place(frame);
}

void AreaLightPoints::fill(const SunCap& cap, int n, Pcg32& rng) {
    jitter(n, rng);
    place(cap);
}

void AreaLightPoints::fill(const AreaLightFrame& frame, std::span<const glm::dvec2> u) {
    u_.assign(u.begin(), u.end());
    place(frame);
}

void AreaLightPoints::fill(const SunCap& cap, std::span<const glm::dvec2> u) {
    u_.assign(u.begin(), u.end());
    place(cap);
}

}  // namespace shadowlab
