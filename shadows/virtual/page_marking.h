// Page marking (docs/virtual-shadow-maps.md): from the camera's G-buffer, the pages of the
// virtual map that this frame's lookups will read, so that only those get memory and only
// those not already valid get rendered (Lefohn et al. 2007, resolution-matched shadow maps:
// the view's samples decide the pages, as in Unreal Engine 5's marking from the depth
// buffer).
//
// Each pixel the light reaches picks the level whose texel matches its footprint: the
// finest level l with texel(l) <= footprint * 2^lodBias (clamped to the clipmap's levels), where the footprint is the pixel's
// side on a plane facing the camera at the pixel's view depth; a positive bias trades
// resolution for fewer pages. It then marks every page under the texels its lookup reads:
// the texel box [floor(u - reach), floor(u + reach)] around its texel coordinate u, reach
// being the filter's half-width in texels (0 for a nearest-texel lookup). A box that leaves
// the level's window moves the pixel to the next coarser level, so every texel a lookup
// reads lies in a marked page of its level; a pixel that no level holds is left unmarked
// (level kNoLevel) and is lit.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/lights.h"
#include "shadows/virtual/clipmap.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

inline constexpr int8_t kNoLevel = -1;

// A pixel's side, m, on the plane facing the camera at a point's view depth: the footprint
// marking matches a level's or a mip's texel to, and the debug buffers divide by.
class PixelFootprint {
public:
    explicit PixelFootprint(const Camera& camera);
    double at(const glm::dvec3& P) const { return perDepth_ * glm::dot(P - eye_, forward_); }

private:
    glm::dvec3 eye_, forward_;
    double perDepth_;   // a pixel's side at unit view depth, m per m
};

// The binary exponent e of x = m 2^e, m in [0.5, 1), for x > 0, as std::frexp gives it,
// read from the bits (frexp is a library call per pixel; marking picks a level or a mip by
// it); a subnormal x gets the smallest normal's, -1021, which chooses the same (finest)
// level as its own would.
inline int binaryExponent(double x) {
    return x >= std::numeric_limits<double>::min() ? int((std::bit_cast<uint64_t>(x) >> 52) & 0x7ff) - 1022 : -1021;
}

// Shadow-map ray tracing's reach (smrt.h): a pixel's rays climb from it to the top of the
// light's depth range (zNear, m along the beam) and drift across the beam by at most
// tanHalfAngle m per m climbed; a sample reads the finest level, from the pixel's own, at
// which the drift is at most reachTexels of its texels (rayLevel). Marking marks, at each
// level a pixel's rays read, the box of reachTexels (plus the lookup's reach) around it.
struct RayReach {
    double tanHalfAngle = 0.0;   // 0: no rays
    double reachTexels = 0.0;
    double zNear = 0.0;
};

// The level a sample `heightM` above a pixel of `level` reads: the finest l >= level with
// tanHalfAngle * heightM <= reachTexels * texel(l), at most the last level.
int rayLevel(const ClipmapSettings& clipmap, int level, double heightM, const RayReach& rays);

struct MarkingSettings {
    int lodBias = 0;            // in levels: + coarser, - finer
    double reachTexels = 0.0;   // the lookup filter's half-width, texels
    RayReach rays = {};
};

// The half-width, texels, of the box marking marks at each level a pixel's rays read: the
// lookup's reach (the receiver's texel moves by its bias) plus the rays' drift.
inline double rayBoxReach(const MarkingSettings& s) { return s.reachTexels + s.rays.reachTexels; }

// Whether `window` holds the pages of the box of `reach` texels around `local`'s texel in
// its level (`local`: a point in the light's frame).
bool windowHoldsBox(const ClipmapSettings& clipmap, const LevelWindow& window, const glm::dvec3& local, double reach);

// The level a ray's sample reads: from `level` (rayLevel's), the first whose window holds
// the pixel's rays' box (windowHoldsBox with rayBoxReach), where marking marked it; the
// last level where none does (its reads then find no page, and are counted). `windows` by
// level from the first, as PageTable::windows() has them.
int heldRayLevel(const ClipmapSettings& clipmap, const std::vector<LevelWindow>& windows, int level,
                 const glm::dvec3& local, double reach);

// A pixel's level and texel coordinate, as marking chose them and the lookup reads them.
struct PixelLevel {
    int8_t level = kNoLevel;   // index from settings.firstLevel, or kNoLevel
    glm::dvec2 texel{0.0};
};

// The marked pages go into `table` (after its beginFrame), and each pixel's level into
// `levels` (resized to the pixels; kNoLevel where the pixel has no surface, the light does
// not reach it or no level holds its box): last frame's memory, where the technique keeps
// it. Rows run in parallel; the result is the same for any thread count.
void markPages(const GBuffer& g, const Camera& camera, const Light& sun, const LightFrame& frame,
               const ClipmapSettings& clipmap, const MarkingSettings& settings, PageTable& table,
               std::vector<PixelLevel>& levels);

// Every page the box of texel coordinate `texel` covers at a level: [first, last] in each axis.
struct PageBox {
    int32_t x0, y0, x1, y1;
    bool operator==(const PageBox&) const = default;
};
PageBox pagesRead(const glm::dvec2& texel, double reachTexels, int pageTexels);

// Requests every page of a box of one level (a table's levels: a clipmap's, or a mip chain's
// mip * faces + face). A box just requested is not requested again: neighbouring pixels,
// and a ray's next samples, mostly read the same pages, and a request only sets a flag, so
// the table ends the same. One per task of rows.
class BoxRequests {
public:
    explicit BoxRequests(PageTable& table) : table_(table) {}
    void request(int level, const PageBox& box) {
        if (level == lastLevel_ && box == last_) return;
        for (int32_t py = box.y0; py <= box.y1; ++py)
            for (int32_t px = box.x0; px <= box.x1; ++px) table_.request({level, px, py});
        lastLevel_ = level, last_ = box;
    }

private:
    PageTable& table_;
    int lastLevel_ = 0;
    PageBox last_{1, 1, 0, 0};   // none: x0 > x1
};

// The pass every marking of a virtual map makes over the pixels (the sun's, a local
// light's), rows in parallel with one BoxRequests per task: `levels` is resized to the
// pixels, a pixel without a surface or that `light` does not reach keeps kNoLevel, and
// every other gets levels[k] = mark(k, requests), which requests its pages. The table ends
// the same for any thread count.
template <class Mark>
void markEachPixel(const GBuffer& g, const Light& light, PageTable& table, std::vector<PixelLevel>& levels,
                   const Mark& mark) {
    const LightReach reaches(light);
    levels.assign(g.pixelCount(), PixelLevel{});
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        BoxRequests requests(table);
        for (int j = rows.begin(); j < rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                if (g.hit[k] && reaches(g.position[k], g.normal[k])) levels[k] = mark(k, requests);
            }
        }
    });
}

}  // namespace shadowlab::vsm
