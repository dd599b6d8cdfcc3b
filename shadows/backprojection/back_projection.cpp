#include "shadows/backprojection/back_projection.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace shadowlab {
namespace {

constexpr int kLoop[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};   // a patch's corners in order

// Where the ray from P through the map's point (texel X, Y at window depth z) meets the
// light's plane, in (a, b); false unless the point lies between P and that plane.
bool projectOntoLight(const SoftShadowMap& soft, const glm::dvec3& P, const AreaLightPlane& light, double X, double Y,
                      double z, glm::vec2& onLight) {
    const glm::dvec4 h = soft.map.worldFromTexel * glm::dvec4(X, Y, z, 1.0);
    const glm::dvec3 d = glm::dvec3(h) / h.w - P;
    const double towards = glm::dot(light.normal, light.centre - P), along = glm::dot(light.normal, d);
    const double t = towards / along;   // P + t d is on the light's plane; t >= 1: beyond the point
    if (!(t >= 1.0) || !std::isfinite(t)) return false;
    const glm::dvec3 hit = P + t * d - light.centre;
    onLight = glm::vec2(float(glm::dot(light.dualA, hit)), float(glm::dot(light.dualB, hit)));
    return std::isfinite(onLight.x) && std::isfinite(onLight.y);
}

// The patches around a corner of the grid by quadrant: 0 above left, 1 above right, 2 below
// left, 3 below right; the edges that meet there: bit 0 joins quadrants 0 and 1, bit 1 2
// and 3, bit 2 0 and 2, bit 3 1 and 3. kGroups[edges][q]: the quadrants joined to q, as a
// mask (the far one is two edges away). Two joined patches are in one group at both ends
// of their shared edge, so they give it the same depth at each end: no gap along it.
constexpr auto kGroups = [] {
    constexpr int kEnds[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
    std::array<std::array<uint8_t, 4>, 16> groups{};
    for (int edges = 0; edges < 16; ++edges) {
        for (int q = 0; q < 4; ++q) {
            unsigned group = 1u << q;
            for (int pass = 0; pass < 2; ++pass) {
                for (int e = 0; e < 4; ++e) {
                    const unsigned ends = (1u << kEnds[e][0]) | (1u << kEnds[e][1]);
                    if ((edges >> e & 1) && (group & ends)) group |= ends;
                }
            }
            groups[size_t(edges)][size_t(q)] = uint8_t(group);
        }
    }
    return groups;
}();

// Per grid node, bit 0: joined to the node on its right, bit 1: to the one below, where both
// occlude and the map shows them on one surface (surface_joins.h).
void joinGridPatches(const PatchGrid& grid, const SurfaceJoins& joins, std::vector<uint8_t>& out) {
    out.assign(size_t(grid.width) * size_t(grid.height), 0);
    for (int j = 0; j < grid.height; ++j) {
        for (int i = 0; i < grid.width; ++i) {
            if (grid.at(i, j) >= 1.0f) continue;
            const int x = grid.x0 + i, y = grid.y0 + j;
            uint8_t& bits = out[size_t(j) * size_t(grid.width) + size_t(i)];
            if (i + 1 < grid.width && grid.at(i + 1, j) < 1.0f && joins.right(grid.level, x, y)) bits |= 1u;
            if (j + 1 < grid.height && grid.at(i, j + 1) < 1.0f && joins.down(grid.level, x, y)) bits |= 2u;
        }
    }
}

// The edges that meet at corner (ci, cj), as kGroups reads them.
unsigned cornerEdges(const PatchGrid& grid, const std::vector<uint8_t>& joined, int ci, int cj) {
    const auto bits = [&](int i, int j) -> unsigned {
        const bool inside = i >= 0 && j >= 0 && i < grid.width && j < grid.height;
        return inside ? joined[size_t(j) * size_t(grid.width) + size_t(i)] : 0u;
    };
    const unsigned aboveLeft = bits(ci - 1, cj - 1), belowLeft = bits(ci - 1, cj), aboveRight = bits(ci, cj - 1);
    return (aboveLeft & 1u) | (belowLeft & 1u) << 1 | (aboveLeft & 2u) << 1 | (aboveRight & 2u) << 2;
}

// The least depth of a group's patches: where they meet, the one nearest the light.
float groupDepth(const PatchGrid& grid, int ci, int cj, unsigned group) {
    float least = 1.0f;
    for (int q = 0; q < 4; ++q) {
        if (group & (1u << q)) least = std::min(least, grid.at(ci - 1 + (q & 1), cj - 1 + (q >> 1)));
    }
    return least;
}

// The four corners of grid patch (i, j) on the light, each at its group's least depth
// (projected once per corner and group); false if one does not reach the light's plane, or
// if the patch, between its corners' depths, lies off the light (light_pyramid.h).
bool gridPatchOnLight(const PatchGrid& grid, const SoftShadowMap& soft, const glm::dvec3& P,
                      const AreaLightPlane& light, const LightPyramid& pyramid, int i, int j,
                      BackProjectionScratch& s, glm::vec2 (&v)[4]) {
    const int cw = grid.width + 1;
    const double nodeWidth = double(1 << grid.level);
    unsigned groups[4];
    float nearest = grid.at(i, j);   // a corner's group holds the patch: no corner is deeper
    for (int c = 0; c < 4; ++c) {
        const int ci = i + kLoop[c][0], cj = j + kLoop[c][1];
        groups[c] = kGroups[cornerEdges(grid, s.joined, ci, cj)][size_t((1 - kLoop[c][0]) + 2 * (1 - kLoop[c][1]))];
        nearest = std::min(nearest, groupDepth(grid, ci, cj, groups[c]));
    }
    const double x = (grid.x0 + i) * nodeWidth, y = (grid.y0 + j) * nodeWidth;
    if (pyramid.misses(x, y, x + nodeWidth, y + nodeWidth, nearest, grid.at(i, j))) return false;
    for (int c = 0; c < 4; ++c) {
        const int ci = i + kLoop[c][0], cj = j + kLoop[c][1];
        const size_t k = 4 * (size_t(cj) * size_t(cw) + size_t(ci)) + size_t(std::countr_zero(groups[c]));
        if (s.cornerState[k] == 0) {
            const double X = (grid.x0 + ci) * nodeWidth, Y = (grid.y0 + cj) * nodeWidth;
            const bool onPlane =
                projectOntoLight(soft, P, light, X, Y, groupDepth(grid, ci, cj, groups[c]), s.cornerOnLight[k]);
            s.cornerState[k] = onPlane ? 1 : 2;
        }
        if (s.cornerState[k] != 1) return false;
        v[c] = s.cornerOnLight[k];
    }
    return true;
}

}  // namespace

int backProjectPatches(const PatchGrid& grid, const SurfaceJoins& joins, const SoftShadowMap& soft,
                       const glm::dvec3& P, const AreaLightPlane& light, const LightPyramid& pyramid,
                       const LightGrid& samples, LightBitmask& mask, BackProjectionScratch& s,
                       std::vector<glm::vec2>* drawn) {
    const size_t slots = 4 * size_t(grid.width + 1) * size_t(grid.height + 1);   // a corner's four groups at most
    s.cornerState.assign(slots, 0), s.cornerOnLight.resize(slots);
    joinGridPatches(grid, joins, s.joined);
    int projected = 0;
    for (int j = 0; j < grid.height; ++j) {
        for (int i = 0; i < grid.width; ++i) {
            glm::vec2 v[4];
            if (grid.at(i, j) >= 1.0f || !gridPatchOnLight(grid, soft, P, light, pyramid, i, j, s, v)) continue;
            samples.cover(mask, v, 4);
            ++projected;
            if (drawn) drawn->insert(drawn->end(), v, v + 4);
            if (samples.full(mask)) return projected;
        }
    }
    // The refined mixed nodes' patches, each at its own depth.
    for (const FinePatch& p : grid.fine) {
        const double width = double(1 << p.level);
        glm::vec2 v[4];
        bool valid = true;
        for (int c = 0; c < 4 && valid; ++c) {
            valid = projectOntoLight(soft, P, light, (p.x + kLoop[c][0]) * width, (p.y + kLoop[c][1]) * width, p.depth,
                                     v[c]);
        }
        if (!valid) continue;
        samples.cover(mask, v, 4);
        ++projected;
        if (drawn) drawn->insert(drawn->end(), v, v + 4);
        if (samples.full(mask)) return projected;
    }
    return projected;
}

}  // namespace shadowlab
