// Procedural casters that are not opaque surfaces: a hair patch (thousands of thin strands
// as ribbons, the hard case of deep and opacity shadow maps, whose shadows fall inside the
// hair itself) and density volumes (a smoke puff, and a constant slab whose transmittance
// has a closed form). Deterministic: every random choice is unitHash(seed, index)
// (hash_random.h), and positions are computed in double and rounded once.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct HairPatchSettings {
    glm::vec3 size{1.0f, 0.2f, 0.6f};   // the box the strands fill: along x, then y, z; centred on the origin
    int strands = 4000;
    float width = 0.003f;               // of each ribbon, m
    int segments = 8;                   // straight pieces per strand
    uint64_t seed = 1;
};

// Strands run along +x across the box from roots spread uniformly over its -x face, each a
// gentle helix of random phase, a ribbon of `width` turned about its axis at a random angle.
// 2 * strands * segments triangles. Requires size > 0, strands, segments >= 1, width > 0.
Mesh makeHairPatch(const HairPatchSettings& settings);
inline uint64_t hairPatchTriangleCount(int strands, int segments) { return 2 * uint64_t(strands) * uint64_t(segments); }

// sigma everywhere: a slab of constant density (one voxel).
DensityVolume makeConstantVolume(glm::vec3 min, glm::vec3 max, float sigma);

// A puff of smoke filling the box: sigmaMax times a falloff from the centre, (1 - r^2)^2 in
// the box's normalised coordinates, times two octaves of value noise between 0.35 and 1.
// `resolution` voxels per axis, each holding the density at its centre.
DensityVolume makeSmokePuff(glm::vec3 min, glm::vec3 max, int resolution, float sigmaMax, uint64_t seed);

}  // namespace shadowlab
