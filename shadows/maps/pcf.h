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
//             shared between threads and the result does not depend on them.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shadows/depth_map.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

enum class FilterKind { Nearest, Bilinear, Grid, Poisson };

struct FilterSettings {
    FilterKind kind = FilterKind::Nearest;
    int gridSize = 3;                  // grid: taps per side
    int poissonTaps = 16;              // poisson: taps
    double poissonRadiusTexels = 1.5;  // poisson: radius of the disk
};

// A filter ready to use: the settings and, for poisson, its taps on the unit disk.
struct PcfKernel {
    FilterSettings settings;
    std::vector<glm::dvec2> disk;
};

PcfKernel makePcfKernel(const FilterSettings& settings);

// How far (texels) from the receiver the kernel reaches, for fitting margins.
double kernelRadiusTexels(const FilterSettings& settings);

// The per-pixel rotation of the poisson kernel: one of kPoissonRotations angles evenly
// spaced over the turn, picked by a hash of the pixel index. A quantised angle lets a
// receiver pass read its cosine and sine from a table of kPoissonRotations entries instead
// of calling the library per pixel; adjacent angles are 0.35 degrees apart, far finer
// than the spacing of 16 taps, so the noise looks the same.
inline constexpr int kPoissonRotations = 1024;
int poissonRotationIndex(uint64_t pixel);
// Radians in [0, 2 pi): 2 pi poissonRotationIndex(pixel) / kPoissonRotations.
double poissonRotation(uint64_t pixel);
double poissonRotationAngle(int index);

// Offset (texels) of unit-disk tap d rotated by (cos, sin) = rotation and scaled by
// radiusTexels per axis (an ellipse where a map's texels are not square in the world).
inline glm::dvec2 rotatedTap(const glm::dvec2& d, const glm::dvec2& rotation, const glm::dvec2& radiusTexels) {
    return radiusTexels * glm::dvec2(rotation.x * d.x - rotation.y * d.y, rotation.y * d.x + rotation.x * d.y);
}

}  // namespace shadowlab
