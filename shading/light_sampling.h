// Stratified points on area lights, for the exact reference (and any technique that needs
// the same samples).
//
// The unit square is cut into n x n strata with one uniformly jittered point in each
// (stratified or "jittered" sampling, Cook, Porter, Carpenter 1984; Pharr, Jakob, Humphreys,
// Physically Based Rendering, 4th ed., section 8.5). Squares map to the light by
// area-preserving maps, so every stratum covers the same area of the light and the fraction
// of visible samples is an unbiased estimate of the visible fraction of the light's area.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// PCG32 (O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation", 2014; the pcg32 "minimal C" generator): 64-bit
// LCG state, 32-bit xorshift-rotate output. `stream` selects one of 2^63 independent
// sequences, so seeding by (fixed seed, pixel index) gives every pixel its own jitter,
// independent of which thread computes it.
class Pcg32 {
public:
    Pcg32(uint64_t seed, uint64_t stream);
    uint32_t next();
    double nextDouble();  // uniform in [0, 1), multiples of 2^-32

private:
    uint64_t state_ = 0;
    uint64_t increment_ = 0;
};

// Point k of the (0, 2)-sequence in base 2 (Kollig and Keller, "Efficient Multidimensional
// Sampling", 2002): the van der Corput radical inverse and Sobol's second dimension. Every
// block of 2^m points puts one point in each of the 2^m elementary rectangles of any shape,
// so integrals converge faster than with independent points. Shifted by a random offset
// modulo 1 (Cranley and Patterson 1976), each point is uniform and an estimate stays unbiased.
glm::dvec2 sobol02(uint32_t k);
glm::dvec2 shiftedSobol02(uint32_t k, const glm::dvec2& shift);

// Shirley & Chiu, "A Low Distortion Map Between Disk and Square", JGT 2(3), 1997: maps
// concentric squares of [0,1]^2 to concentric circles of the unit disk, preserving
// relative area and keeping strata compact (unlike r = sqrt(u), phi = 2 pi v).
glm::dvec2 concentricSquareToDisk(const glm::dvec2& u);

// An area light as centre + a * axisA + b * axisB: for a rectangle (a, b) in [-1, 1]^2 and
// the axes are its half-edges; for a disk (a, b) in the unit disk and the axes are an
// orthonormal basis of the disk's plane scaled by the radius.
struct AreaLightFrame {
    bool disk = false;
    glm::dvec3 centre{0.0}, axisA{0.0}, axisB{0.0};
};
// Throws std::invalid_argument unless light.type is Disk or Rectangle.
AreaLightFrame areaLightFrame(const Light& light);

// The light's plane and its coordinates (a, b) above: a point Y on the plane has
// a = dot(Y - centre, dualA), b = dot(Y - centre, dualB), the dual basis of axisA and
// axisB (a rectangle's half-edges need not be orthogonal). What a technique that projects
// onto the light reads (penumbra wedges, backprojection).
struct AreaLightPlane {
    bool disk = false;
    glm::dvec3 centre{0.0}, normal{0.0};     // normal: unit, along axisA x axisB
    glm::dvec3 dualA{0.0}, dualB{0.0};
};
AreaLightPlane areaLightPlane(const AreaLightFrame& frame);

// The point of the light for a sample u in [0, 1)^2.
glm::dvec3 areaLightPoint(const AreaLightFrame& frame, const glm::dvec2& u);

// Sample u of stratum (a, b) of n x n, jittered with two draws from rng.
glm::dvec2 jitteredSample(int a, int b, int n, Pcg32& rng);

// A sun of angular diameter a (a directional light's angularDiameterDeg > 0) is the cap of
// directions within theta_max = a/2 of its unit `axis` (towards the sun), a disk on the sky.
// tangentA, tangentB: an orthonormal basis around the axis; h = 1 - cos(theta_max), kept
// as 2 sin^2(theta_max / 2), which keeps its digits for a sun of a fraction of a degree.
struct SunCap {
    glm::dvec3 axis{0.0}, tangentA{0.0}, tangentB{0.0};
    double oneMinusCosMax = 0.0;
};
// Throws std::invalid_argument unless the light is directional with angularDiameterDeg > 0.
SunCap sunCap(const Light& light);

// The cap's direction for a point m = r (cos phi, sin phi) of the unit disk, equal-area: the
// cap between the axis and theta has solid angle 2 pi (1 - cos theta), the fraction
// (1 - cos theta) / h of the whole cap, and the disk within r the fraction r^2 of the disk,
// so the map that keeps relative area (and phi) has
//     cos theta = 1 - r^2 h,   sin theta = r sqrt(h (2 - r^2 h)),
//     direction = cos theta axis + sqrt(h (2 - r^2 h)) (m.x tangentA + m.y tangentB)
// (the factor r of sin theta cancels the 1/r of the unit vector m / r: no division at the
// centre). Composed with concentricSquareToDisk, strata of the unit square become cells of
// equal solid angle.
glm::dvec3 sunCapDirection(const SunCap& cap, const glm::dvec2& m);

// The light's points of all n x n strata, stratum (a, b) at a + n b: the bits of
// areaLightPoint(frame, jitteredSample(a, b, n, rng)) over b, then a, from 0, and the same
// draws from rng. Computed in stages over arrays, so that the disk's sine and cosine
// polynomials of many strata run side by side (vectorised) where one sample at a time waits
// on their latency; the same double operations in the same order per stratum. Reused from
// call to call: a steady state allocates nothing.
class AreaLightPoints {
public:
    void fill(const AreaLightFrame& frame, int n, Pcg32& rng);
    // A sun's: points() are then the unit directions sunCapDirection(cap,
    // concentricSquareToDisk(jitteredSample(a, b, n, rng))), in the same order and draws.
    void fill(const SunCap& cap, int n, Pcg32& rng);
    // The same maps of given samples u in [0, 1)^2 instead of the strata's, in their order
    // (a pixel's samples of a frame, pixel_sequence.h).
    void fill(const AreaLightFrame& frame, std::span<const glm::dvec2> u);
    void fill(const SunCap& cap, std::span<const glm::dvec2> u);
    const std::vector<glm::dvec3>& points() const { return points_; }

private:
    void jitter(int n, Pcg32& rng);   // u_: the strata's samples
    void squaresToDisk();             // u_: concentricSquareToDisk of each
    void place(const AreaLightFrame& frame);   // points_ of the samples u_
    void place(const SunCap& cap);
    std::vector<glm::dvec3> points_;
    std::vector<glm::dvec2> u_;   // per stratum: the sample, then the point in [-1, 1]^2 or the disk
    std::vector<uint8_t> centre_;   // the disk's: the square's centre, the disk's
    std::vector<double> radius_, reduced_, sine_, cosine_;   // concentricSquareToDisk's r, its angle less
    std::vector<int> quadrant_;                              // its quarter turns, their sin and cos
};

}  // namespace shadowlab
