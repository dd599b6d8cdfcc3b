// Percentage-closer filtering (Real-Time Rendering, 4th ed., section 7.5; Reeves et al.
// 1987): compare the receiver with several texels and average the lit/unlit results, never
// the depths. Every kernel returns the weighted fraction of its taps that are lit:
//
//   nearest   the one texel the receiver falls in (plain shadow mapping, section 7.4).
//   bilinear  the 2x2 texels around it, weighted bilinearly (DirectX 10 comparison
//             sampling; section 7.5): across a straight edge the result ramps linearly
//             over one texel.
//   grid      N x N nearest taps one texel apart, centred on the receiver, equal weights
//             (Figure 7.23, far left).
//   poisson   a Poisson-disk pattern of taps (best-candidate sampling of the unit disk,
//             fixed), scaled to a radius in texels and rotated per pixel by one of 1024
//             angles hashed from the pixel index (Figure 7.23, middle right: aliasing
//             becomes noise). The hash is a pure function of the index, so no random state is
//             shared between threads and the result does not depend on them. Or, for a
//             filter a temporal resolve averages over frames (docs/temporal.md), one of the
//             1024 angles picked by interleaved gradient noise, which moves with the frame.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shadows/depth_map.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

enum class FilterKind { Nearest, Bilinear, Grid, Poisson };

// What turns the Poisson disk from pixel to pixel.
enum class RotationNoise {
    Hash,                  // a hash of the pixel index: the same noise every frame
    InterleavedGradient,   // interleaved gradient noise at the frame (Jimenez 2014)
};

struct FilterSettings {
    FilterKind kind = FilterKind::Nearest;
    int gridSize = 3;                  // grid: taps per side
    int poissonTaps = 16;              // poisson: taps
    double poissonRadiusTexels = 1.5;  // poisson: radius of the disk
    RotationNoise rotation = RotationNoise::Hash;   // poisson
};

// A filter ready to use: the settings, for poisson its taps on the unit disk, and the frame
// of a sequence it filters (what interleaved gradient noise moves with).
struct PcfKernel {
    FilterSettings settings;
    std::vector<glm::dvec2> disk;
    uint64_t frame = 0;
};

PcfKernel makePcfKernel(const FilterSettings& settings, uint64_t frame = 0);

// How far (texels) from the receiver the kernel reaches, for fitting margins.
double kernelRadiusTexels(const FilterSettings& settings);

// How far its taps' coordinates lie from the receiver's, per axis: every tap reads a texel
// in [floor(u - r), floor(u + r)] (nearest 0, bilinear 0.5, grid (n - 1) / 2, poisson the
// radius widened by 1e-4 for the rotation's rounding). What a lookup whose texels must be
// in memory first reserves (a virtual map's marking).
double tapReachTexels(const FilterSettings& settings);

// The per-pixel rotation of the poisson kernel: one of kPoissonRotations angles evenly
// spaced over the turn, picked by a hash of the pixel index. A quantised angle lets a
// receiver pass read its cosine and sine from a table of kPoissonRotations entries instead
// of calling the library per pixel; adjacent angles are 0.35 degrees apart, far finer
// than the spacing of 16 taps, so the noise looks the same.
inline constexpr int kPoissonRotations = 1024;
int poissonRotationIndex(uint64_t pixel);
// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare": shading/pixel_sequence.h) at the pixel centre (i + 0.5, j + 0.5) shifted
// by 5.588238 pixels along both axes per frame, frame modulo 64 (the talk's temporal
// variant). Neighbouring pixels get angles far apart in a pattern a 3x3 neighbourhood
// averages well, and a pixel walks through well-spread angles over frames.
double frameGradientNoise(int i, int j, uint64_t frame);
// The rotation of pixel (i, j) of a row-major image `width` pixels wide at a sequence's
// `frame`: the noise picks one of the kPoissonRotations angles.
int poissonRotationIndex(RotationNoise noise, uint64_t frame, int i, int j, int width);
// Radians in [0, 2 pi): 2 pi poissonRotationIndex(pixel) / kPoissonRotations.
double poissonRotation(uint64_t pixel);
double poissonRotationAngle(int index);

// The (cos, sin) of angle `index` (poissonRotationAngle), as the shadow maps' lookup
// tabulates them.
glm::dvec2 poissonRotationCosSin(int index);
// The (cos, sin) `kernel` turns its disk by at pixel `pixel` of a row-major image `width`
// pixels wide: its noise's angle for a poisson kernel, (1, 0) for the others.
glm::dvec2 kernelRotation(const PcfKernel& kernel, size_t pixel, int width);

// Offset (texels) of unit-disk tap d rotated by (cos, sin) = rotation and scaled by
// radiusTexels per axis (an ellipse where a map's texels are not square in the world).
inline glm::dvec2 rotatedTap(const glm::dvec2& d, const glm::dvec2& rotation, const glm::dvec2& radiusTexels) {
    return radiusTexels * glm::dvec2(rotation.x * d.x - rotation.y * d.y, rotation.y * d.x + rotation.x * d.y);
}

// The kernel's lit fraction for a receiver at texel coordinate `texel`, in double:
// litAt(x, y) says whether texel (x, y) lights it, `rotation` is the pixel's
// poissonRotationCosSin. The taps and weights of the shadow maps' float filters
// (lookup_kernel.inl), for a lookup that finds its texels another way (a virtual map's
// pages); tests/shadows/virtual holds the two to the same answers on the same texels.
template <class LitAt>
double pcfLitFraction(const PcfKernel& kernel, const glm::dvec2& texel, const glm::dvec2& rotation,
                      const LitAt& litAt) {
    const FilterSettings& s = kernel.settings;
    const auto lit = [&](int x, int y) { return litAt(x, y) ? 1.0 : 0.0; };
    switch (s.kind) {
        case FilterKind::Nearest: return lit(texelIndexOf(texel.x), texelIndexOf(texel.y));
        case FilterKind::Bilinear: {
            // The four texel centres around the receiver, weighted bilinearly (RTR 7.5).
            const glm::dvec2 base = texel - 0.5;
            const int x0 = texelIndexOf(base.x), y0 = texelIndexOf(base.y);
            const double fx = base.x - x0, fy = base.y - y0;
            const double top = (1.0 - fx) * lit(x0, y0) + fx * lit(x0 + 1, y0);
            const double bottom = (1.0 - fx) * lit(x0, y0 + 1) + fx * lit(x0 + 1, y0 + 1);
            return (1.0 - fy) * top + fy * bottom;
        }
        case FilterKind::Grid: {
            // N x N taps one texel apart centred on the receiver (RTR Figure 7.23).
            const double first = -0.5 * double(s.gridSize - 1);
            double sum = 0.0;
            for (int b = 0; b < s.gridSize; ++b)
                for (int a = 0; a < s.gridSize; ++a)
                    sum += lit(texelIndexOf(texel.x + first + a), texelIndexOf(texel.y + first + b));
            return sum / double(s.gridSize * s.gridSize);
        }
        case FilterKind::Poisson: {
            double sum = 0.0;
            for (const glm::dvec2& d : kernel.disk) {
                const glm::dvec2 t = texel + rotatedTap(d, rotation, glm::dvec2(s.poissonRadiusTexels));
                sum += lit(texelIndexOf(t.x), texelIndexOf(t.y));
            }
            return sum / double(kernel.disk.size());
        }
    }
    return 1.0;
}

}  // namespace shadowlab
