#include "shadows/virtual/mip_chain.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/fixed_point.h"
#include "raster/portable_math.h"
#include "scenes/camera.h"
#include "shadows/depth_map.h"

namespace shadowlab::vsm {
namespace {

// The nearest distance from P to the box (0 inside it) and the farthest corner's.
glm::dvec2 distancesTo(const Aabb& box, const glm::dvec3& P) {
    const glm::dvec3 nearest = glm::clamp(P, box.min, box.max);
    const glm::dvec3 farthest = glm::max(glm::abs(box.min - P), glm::abs(box.max - P));
    return {glm::length(nearest - P), glm::length(farthest)};
}

// The near plane's floor for a far plane: 1e-4 of it.
double nearFloor(double zFar) { return 1e-4 * zFar; }

}  // namespace

PageLayout MipChain::layout() const {
    PageLayout layout{0, {}};
    for (int level = 0; level < levelCount(); ++level) layout.pagesPerSide.push_back(pagesPerSide(mipOfLevel(level)));
    return layout;
}

std::vector<LevelWindow> MipChain::windows() const {
    std::vector<LevelWindow> windows;
    for (int level = 0; level < levelCount(); ++level) windows.push_back({level, 0, 0});
    return windows;
}

glm::dmat4 MipChain::clipFromView() const {
    const double n = range.zNear, side = n * tanHalf;
    return glm::frustumRH_NO(-side, side, -side, side, n, range.zFar);
}

glm::dmat4 MipChain::texelFromWorld(int level) const {
    return texelFromClip(mipTexels(mipOfLevel(level))) * clipFromView() * faces[size_t(faceOfLevel(level))];
}

int MipChain::cellTexels(int mip) const { return std::min(mipTexels(mip), raster::kMaxViewport); }

PageView MipChain::pageView(const PageKey& key) const {
    const int mip = mipOfLevel(key.level), cell = cellTexels(mip), pagesPerCell = cell / pageTexels;
    const int32_t cx = key.x / pagesPerCell, cy = key.y / pagesPerCell;   // pages count from 0
    // The cell's texels [cx C, (cx+1) C) x [cy C, (cy+1) C) of a mip of S texels span
    // normalised device x from -1 + 2 cx C / S, y (rows downwards) from 1 - 2 (cy+1) C / S;
    // scaled by the near plane's half side, the window of the face's frustum.
    const double S = mipTexels(mip), C = cell, side = range.zNear * tanHalf;
    const double x0 = -1.0 + 2.0 * cx * C / S, x1 = -1.0 + 2.0 * (cx + 1) * C / S;
    const double y0 = 1.0 - 2.0 * (cy + 1) * C / S, y1 = 1.0 - 2.0 * cy * C / S;
    PageView v;
    v.cell.viewFromWorld = faces[size_t(faceOfLevel(key.level))];
    v.cell.clipFromView = glm::frustumRH_NO(x0 * side, x1 * side, y0 * side, y1 * side, range.zNear, range.zFar);
    v.cell.zNear = range.zNear, v.cell.zFar = range.zFar;
    v.window = {cell, cell, (key.x - cx * pagesPerCell) * pageTexels, (key.y - cy * pagesPerCell) * pageTexels};
    return v;
}

std::vector<DepthMap> levelMaps(const MipChain& chain) {
    std::vector<DepthMap> maps(size_t(chain.levelCount()));
    for (int l = 0; l < chain.levelCount(); ++l) {
        DepthMap& map = maps[size_t(l)];
        map.size = chain.mipTexels(chain.mipOfLevel(l));
        map.texelFromWorld = chain.texelFromWorld(l);
        map.worldFromTexel = glm::inverse(map.texelFromWorld);
    }
    return maps;
}

int MipChain::faceHolding(const glm::dvec3& P) const {
    for (int f = 0; f < faceCount(); ++f) {
        if (pyramidHolds(glm::dvec3(faces[size_t(f)] * glm::dvec4(P, 1.0)))) return f;
    }
    return -1;
}

DepthRange depthRangeAround(const std::vector<Aabb>& boxes, const glm::dvec3& apex, double tanHalf, bool tight) {
    double nearest = INFINITY, farthest = 0.0;
    for (const Aabb& box : boxes) {
        const glm::dvec2 d = distancesTo(box, apex);
        nearest = std::min(nearest, d.x), farthest = std::max(farthest, d.y);
    }
    if (!(nearest <= farthest)) nearest = farthest = 1.0;   // no boxes
    // A point at distance r inside a face's pyramid lies at least r / sqrt(1 + 2 tan^2) along
    // its axis (in its corner); no point is farther along the axis than from the apex.
    const double nearestAlong = nearest / std::sqrt(1.0 + 2.0 * tanHalf * tanHalf);
    const double zFar = 1.1 * farthest + 0.01;
    // The floor is the widened far's in both forms, so that a kept range still holds a tight
    // one whose near is the floor. Half the nearest distance lets a caster come halfway to
    // the light before the table starts afresh, for at most one bit of depth precision
    // (window depth resolves about z^2 / near).
    if (tight) return {std::max(nearestAlong, nearFloor(zFar)), farthest};
    return {std::max(0.5 * nearestAlong, nearFloor(zFar)), zFar};
}

MipChain mipChainFor(const Light& light, const ClipmapSettings& settings, const std::vector<Aabb>& boxes) {
    MipChain chain;
    chain.resolution = settings.resolution, chain.pageTexels = settings.pageTexels;
    chain.mipCount = std::countr_zero(unsigned(settings.resolution / settings.pageTexels)) + 1;   // powers of two
    chain.apex = glm::dvec3(light.position);
    if (light.type == LightType::Spot && double(light.coneAngleDeg) <= kMaxSpotFaceDeg) {
        // One face round the cone, 1 % wider so that every point the cone holds (tested in
        // float, insideSpotCone) falls inside it.
        const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
        // portable::tan, not libm's, whose bits depend on the CPU it dispatches to.
        chain.tanHalf = 1.01 * portable::tan(glm::radians(double(light.coneAngleDeg)));
        chain.faces.push_back(glm::lookAtRH(chain.apex, chain.apex + axis, lookAtUp(axis)));
    } else {
        for (int face = 0; face < 6; ++face) chain.faces.push_back(cubeFaceViewFromWorld(chain.apex, face));
    }
    chain.range = depthRangeAround(boxes, chain.apex, chain.tanHalf, false);
    return chain;
}

std::optional<TexelRect> texelRectOf(const Aabb& box, const glm::dmat4& texelFromWorld, bool& behind) {
    TexelRect rect{glm::dvec2(INFINITY), glm::dvec2(-INFINITY)};
    int behindCorners = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 P{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z};
        const glm::dvec4 h = texelFromWorld * glm::dvec4(P, 1.0);
        if (!(h.w > 0.0)) {
            ++behindCorners;
            continue;
        }
        const glm::dvec2 t = glm::dvec2(glm::dvec3(h) / h.w);
        rect.lo = glm::min(rect.lo, t), rect.hi = glm::max(rect.hi, t);
    }
    behind = behindCorners == 8;
    if (behindCorners > 0) return std::nullopt;
    return rect;
}

}  // namespace shadowlab::vsm
