// The vector core of the shadow-map lookup (shadow_lookup.h; Real-Time Rendering, 4th ed.,
// sections 7.4 and 7.5): for a row of receivers that a map serves, project each into the
// map, apply the bias, take the filter's taps and return the lit fraction. Single-precision
// floats in structure-of-arrays vectors, written once (lookup_kernel.inl) against the SIMD
// value types of raster/simd/ and compiled for scalar, AVX2 and AVX-512; every lane does
// the same IEEE operations in the same order, so every level gives the same bits and the
// scalar build is the plain reference twin the vector ones are held to.
//
// Plain data only: the per-ISA translation units include this header, and no inline
// function built for a wider instruction set may reach the rest of the program.
#pragma once

#include <cstdint>

namespace shadowlab {

// A min/max depth hierarchy of a map (min_max_hierarchy.h) as the kernel reads it: level
// l = firstLevel .. levels has size[l - firstLevel] nodes of 2^l x 2^l texels per side,
// row-major from offset[l - firstLevel] in each of the arrays: the depth range, and the
// plane with its residuals.
inline constexpr int kMaxHierarchyLevels = 16;
struct LookupHierarchy {
    const float* least;
    const float* greatest;
    const float* planeDepth;
    const float* slopeX;
    const float* slopeY;
    const float* residualLow;
    const float* residualHigh;
    int firstLevel;
    int levels;
    int size[kMaxHierarchyLevels];
    int offset[kMaxHierarchyLevels];
};

// One depth map as the kernel reads it.
struct LookupMap {
    float texelFromWorld[16];   // column-major (as glm), rounded from DepthMap::texelFromWorld
    float worldFromTexel[16];   // its inverse, likewise
    const float* depth;         // block-linear (raster::blockLinearIndex)
    int size;                   // texels per side
    int tilesX;                 // tiles per row of the block-linear buffer
    // pcss: where the hierarchy proves every tap's answer, the taps are skipped; null: none.
    // chs: the hierarchy its blocker search reads (never null).
    const LookupHierarchy* hierarchy;
};

// The bias modes and filters, numbered as BiasMode and FilterKind (checked where they meet).
enum LookupBias : int { kLookupConstant, kLookupSlopeScaled, kLookupNormalOffset, kLookupReceiverPlane };
// kLookupPcss is percentage-closer soft shadows, the filter of shadows/filtered/pcss.cpp;
// kLookupChs contact-hardening soft shadows, that of shadows/filtered/contact_hardening.cpp;
// kLookupBlockerSearch PCSS's blocker search alone, for the filtered maps' width=pcss.
enum LookupFilter : int {
    kLookupNearest, kLookupBilinear, kLookupGrid, kLookupPoisson, kLookupPcss, kLookupChs, kLookupBlockerSearch,
    kLookupFilterCount
};

struct LookupConstants {
    const LookupMap* maps;      // the maps a selector chooses from
    int mapCount;
    int bias;                   // LookupBias
    float constantMetres;       // constant and normal-offset: the move towards the light
    float normalOffsetTexels;   // normal-offset: texels at a grazing light
    bool directional;           // light: a unit direction towards it, else its position
    float light[3];
    float reachAnchor[3];       // lightReaches' A: the light's direction as given, or its position
    bool spot;                  // a spot light: its cone is decided by the caller, in double
    int gridSize;               // grid: taps per side
    const float* diskX;         // poisson, pcss: the unit-disk taps of the filter
    const float* diskY;
    int diskTaps;
    float radiusTexels;         // poisson: the disk's radius, texels
    // pcss and the blocker search: the search's unit-disk taps and the fraction of the light's cone it
    // covers, the light's width in texels at unit distance per axis (w_light of eq. 7.6),
    // and the perspective map's near and far distances.
    const float* searchX;
    const float* searchY;
    int searchTaps;
    float searchRegion;
    float lightTexels[2];
    float zNear, zFar;
    // chs (the light's and the map's figures above too): nodes per side of the blocker
    // search's reading level, and N of the filter's N x N grid.
    int searchNodes;
    int filterNodes;
};

// Receivers as the map serving them sees them, one value per pixel of a run: where each
// falls (texel units), its biased window depth, and for receiver planes the plane's depth
// slope per texel and the compare's tolerance.
struct ReceiverArrays {
    float* texelX;
    float* texelY;
    float* depth;
    float* slopeX;
    float* slopeY;
    float* tolerance;
    float* distance;            // clip w, for a perspective map the distance along its axis (pcss, chs, blocker
                                // search; null otherwise)
};

// One run of pixels of a row; count is a multiple of the kernel's width.
struct LookupRow {
    const float* position;      // x, y, z per pixel (the G-buffer's, world space)
    const float* normal;        // likewise
    // 1 + the index of the map serving the pixel, else 0; the reach stage sets it to 0
    // where the light cannot reach the pixel, and marks with kReachUndecided the pixels
    // whose answer float could not certify.
    uint8_t* served;
    const float* rotationCos;   // poisson: the pixel's rotation of the disk
    const float* rotationSin;
    ReceiverArrays receivers;   // written by the projection, read by the filter
    float* visibility;          // out: the lit fraction, 0 where served = 0
    // out, pcss, chs and the blocker search only (zeroed by the caller: vectors with no
    // served pixel are not written); the width not for the blocker search:
    float* blockerDistance;     // the blockers' mean distance d_o, 0 without blockers
    float* penumbraWidth;       // the filter's width in texels (eq. 7.6), 0 likewise
    // out, pcss with a hierarchy only (else null): the taps whose answer the hierarchy proved
    float* knownTaps;
    // out, chs only (else null): the level its blocker search read, 0 without blockers
    float* searchLevel;
    int count;
};

using LookupKernel = void (*)(const LookupConstants&, const LookupRow&);

inline constexpr uint8_t kReachUndecided = 0x80;

// The three stages: whether the light reaches each receiver; the projection, for plain
// receivers [0] and for receiver planes [1] (receiver-plane bias: the compare is against
// the plane's depth at each tap); and the filter, one kernel per filter, likewise.
struct LookupKernels {
    int width;                                      // pixels per vector
    LookupKernel reach;
    LookupKernel project[2];
    LookupKernel filter[kLookupFilterCount][2];
};

const LookupKernels& lookupKernelsScalar();
const LookupKernels& lookupKernelsAvx2();
const LookupKernels& lookupKernelsAvx512();

}  // namespace shadowlab
