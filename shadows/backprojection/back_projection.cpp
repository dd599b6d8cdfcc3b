#include "shadows/backprojection/back_projection.h"

#include <algorithm>
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

}  // namespace

int backProjectPatches(const PatchGrid& grid, const SoftShadowMap& soft, const glm::dvec3& P,
                       const AreaLightPlane& light, const LightGrid& samples, double continuity, LightBitmask& mask,
                       BackProjectionScratch& s, std::vector<glm::vec2>* drawn) {
    const int cw = grid.width + 1, ch = grid.height + 1;
    const size_t corners = size_t(cw) * size_t(ch);
    s.cornerDepth.assign(corners, 1.0f), s.cornerState.assign(corners, 0), s.cornerOnLight.resize(corners);
    for (int j = 0; j < grid.height; ++j) {   // a corner takes the least depth of the patches around it
        for (int i = 0; i < grid.width; ++i) {
            const float depth = grid.at(i, j);
            for (int k = 0; k < 4 && depth < 1.0f; ++k) {
                float& corner = s.cornerDepth[size_t(j + k / 2) * size_t(cw) + size_t(i + k % 2)];
                corner = std::min(corner, depth);
            }
        }
    }
    const double nodeWidth = double(1 << grid.level);
    int projected = 0;
    for (int j = 0; j < grid.height; ++j) {
        for (int i = 0; i < grid.width; ++i) {
            const float depth = grid.at(i, j);
            if (depth >= 1.0f) continue;
            const double nearestShared = (1.0 - continuity) * soft.distanceOf(depth);
            glm::vec2 v[4];
            bool valid = true;
            for (int c = 0; c < 4 && valid; ++c) {
                const int ci = i + kLoop[c][0], cj = j + kLoop[c][1];
                const size_t k = size_t(cj) * size_t(cw) + size_t(ci);
                const double X = (grid.x0 + ci) * nodeWidth, Y = (grid.y0 + cj) * nodeWidth;
                if (soft.distanceOf(s.cornerDepth[k]) < nearestShared) {   // an edge: the patch's own depth
                    valid = projectOntoLight(soft, P, light, X, Y, depth, v[c]);
                    continue;
                }
                if (s.cornerState[k] == 0) {
                    const bool onPlane = projectOntoLight(soft, P, light, X, Y, s.cornerDepth[k], s.cornerOnLight[k]);
                    s.cornerState[k] = onPlane ? 1 : 2;
                }
                valid = s.cornerState[k] == 1;
                v[c] = s.cornerOnLight[k];
            }
            if (!valid) continue;
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
