#include "scenes/procedural_casters.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "raster/portable_math.h"
#include "scenes/hash_random.h"

namespace shadowlab {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// One strand's random choices, drawn in a fixed order from its own indices.
struct Strand {
    double rootY, rootZ, phase, ribbonAngle;
};

Strand strandAt(const HairPatchSettings& s, int index, double amplitude) {
    const uint64_t k = 4 * uint64_t(index);
    const double spanY = s.size.y - 2.0 * amplitude, spanZ = s.size.z - 2.0 * amplitude;
    return {(unitHash(s.seed, k) - 0.5) * spanY, (unitHash(s.seed, k + 1) - 0.5) * spanZ,
            kTwoPi * unitHash(s.seed, k + 2), std::numbers::pi * unitHash(s.seed, k + 3)};
}

// Value noise: hashed values at the corners of the unit lattice, trilinearly interpolated.
double valueNoise(const glm::dvec3& p, uint64_t seed) {
    const glm::dvec3 cell(std::floor(p.x), std::floor(p.y), std::floor(p.z));
    const glm::dvec3 f = p - cell;
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
        const glm::i64vec3 c = glm::i64vec3(cell) + glm::i64vec3(o);
        const uint64_t key = uint64_t(c.x & 0xfffff) | uint64_t(c.y & 0xfffff) << 20 | uint64_t(c.z & 0xfffff) << 40;
        const double w = (o.x ? f.x : 1.0 - f.x) * (o.y ? f.y : 1.0 - f.y) * (o.z ? f.z : 1.0 - f.z);
        sum += w * unitHash(seed, key);
    }
    return sum;
}

}  // namespace

Mesh makeHairPatch(const HairPatchSettings& s) {
    Mesh mesh;
    mesh.source = "procedural:hair";
    const double amplitude = 0.1 * std::min(s.size.y, s.size.z), halfWidth = 0.5 * s.width;
    constexpr double kTurns = 1.5;
    for (int index = 0; index < s.strands; ++index) {
        const Strand strand = strandAt(s, index, amplitude);
        const glm::dvec3 across(0.0, portable::cos(strand.ribbonAngle), portable::sin(strand.ribbonAngle));
        const uint32_t first = uint32_t(mesh.positions.size());
        for (int k = 0; k <= s.segments; ++k) {
            const double t = double(k) / s.segments, angle = kTwoPi * kTurns * t + strand.phase;
            const glm::dvec3 axis((t - 0.5) * s.size.x, strand.rootY + amplitude * portable::sin(angle),
                                  strand.rootZ + amplitude * portable::cos(angle));
            mesh.positions.emplace_back(glm::vec3(axis - halfWidth * across));
            mesh.positions.emplace_back(glm::vec3(axis + halfWidth * across));
        }
        for (uint32_t k = 0; k < uint32_t(s.segments); ++k) {
            const uint32_t a = first + 2 * k, b = a + 1, c = a + 3, d = a + 2;
            mesh.triangles.emplace_back(a, b, c);
            mesh.triangles.emplace_back(a, c, d);
        }
    }
    return mesh;
}

DensityVolume makeConstantVolume(glm::vec3 min, glm::vec3 max, float sigma) {
    return {.name = "constant", .min = min, .max = max, .resolution = glm::ivec3(1), .sigma = {sigma}};
}

DensityVolume makeSmokePuff(glm::vec3 min, glm::vec3 max, int resolution, float sigmaMax, uint64_t seed) {
    DensityVolume volume{.name = "smoke-puff", .min = min, .max = max, .resolution = glm::ivec3(resolution),
                         .sigma = {}};
    volume.sigma.reserve(size_t(resolution) * size_t(resolution) * size_t(resolution));
    for (int z = 0; z < resolution; ++z) {
        for (int y = 0; y < resolution; ++y) {
            for (int x = 0; x < resolution; ++x) {
                // The voxel's centre in [-1, 1]^3 of the box.
                const glm::dvec3 q = (glm::dvec3(x, y, z) + 0.5) / double(resolution) * 2.0 - 1.0;
                const double r2 = glm::dot(q, q), falloff = r2 < 1.0 ? (1.0 - r2) * (1.0 - r2) : 0.0;
                const double noise =
                    0.65 * valueNoise(2.0 * q + 7.0, seed) + 0.35 * valueNoise(5.0 * q + 3.0, seed + 1);
                volume.sigma.push_back(float(sigmaMax * falloff * (0.35 + 0.65 * noise)));
            }
        }
    }
    return volume;
}

}  // namespace shadowlab
