// The area light as a bitmask of sample points (Schwarz and Stamminger 2007, "Bitmask Soft
// Shadows", section 3): the light is covered by an n x n grid of cells in its own
// coordinates (a, b) in [-1, 1]^2 (shading/light_sampling.h's AreaLightFrame: a rectangle's
// half-edges, a disk's radius), each cell's centre one sample, one bit. A disk keeps the
// cells whose centre lies inside it. Every occluder back-projected onto the light sets the
// bits of the samples it hides; the union of bits is the hidden part of the light, so
// overlapping occluders count once (occluder fusion, which summing covered areas, as
// Guennebaud et al. 2006 do, gets wrong). V = 1 - (hidden samples) / (samples).
#pragma once

#include <array>
#include <cstdint>
#include <utility>

#include <glm/glm.hpp>

namespace shadowlab {

inline constexpr int kMaxLightSamplesPerAxis = 32;   // a row of the grid is one 32-bit word

struct LightBitmask {
    std::array<uint32_t, kMaxLightSamplesPerAxis> rows{};   // bit i of row j: cell (i, j)

    LightBitmask& operator|=(const LightBitmask& o);
};

class LightGrid {
public:
    // n samples per axis (1 .. kMaxLightSamplesPerAxis), a disk or a rectangle.
    LightGrid(int n, bool disk);

    int perAxis() const { return n_; }
    int sampleCount() const { return count_; }
    const LightBitmask& onLight() const { return onLight_; }   // the samples of the light
    float centre(int i) const { return -1.0f + (2.0f * float(i) + 1.0f) / float(n_); }   // a or b of cell i

    // Sets the samples inside a convex polygon (3 or 4 vertices in (a, b), either winding).
    void cover(LightBitmask& mask, const glm::vec2* vertices, int count) const;
    // Sets the samples where alpha a + beta b + gamma <= 0 (behind a receiver's plane).
    void coverHalfPlane(LightBitmask& mask, double alpha, double beta, double gamma) const;
    // Whether every sample of the light is set.
    bool full(const LightBitmask& mask) const;
    // Samples of the light that are set.
    int hidden(const LightBitmask& mask) const;

private:
    // The cells whose centre lies in [lo, hi], first and last (first > last: none), and
    // their bits.
    std::pair<int, int> cells(float lo, float hi) const;
    uint32_t span(float lo, float hi) const;

    int n_ = 0;
    int count_ = 0;
    LightBitmask onLight_;
};

}  // namespace shadowlab
