// The lookup of a virtual shadow map (docs/virtual-shadow-maps.md): each pixel reads the
// level marking chose for it, as a shadow map of that level's texels would be read (the
// shadow maps' receiver mapping and bias, shadow_bias.h, and their percentage-closer
// filters, pcf.h), every texel found through the page table in the physical pool; a tap
// may fall in a neighbouring page of the level, which marking marked (lookupReachTexels).
// A pixel with a tap in a page without memory (the pool overflowed) reads that tap as lit
// and is counted; a pixel that no level holds is lit, and counted.
#pragma once

#include <bit>
#include <climits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/lights.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// The texels of every level through the page table.
class PageTexels {
public:
    // pageTexels: a power of two (a clipmap's or a mip chain's pages).
    PageTexels(int pageTexels, const PageTable& table, const PagePool& pool)
        : pageTexels_(pageTexels), table_(table), pool_(pool), pageShift_(std::countr_zero(unsigned(pageTexels))) {}
    // The window depth texel (x, y) of `level` holds, or kMissingTexel where its page has no
    // current depth.
    static constexpr float kMissingTexel = -1.0f;
    float at(int level, int x, int y) const;
    // The same, remembering the page last read in `cursor`: a ray's or a kernel's next read
    // is most often in the same page, and skips the table.
    struct Cursor {
        PageKey key{0, INT32_MIN, INT32_MIN};
        const float* texels = nullptr;   // the page's, row-major; null: no current depth
    };
    float at(int level, int x, int y, Cursor& cursor) const;

private:
    // The page holding texel (x, y): floor(x / pageTexels), an arithmetic shift (pageTexels
    // is a power of two), where pageOf's double floor is a library call.
    PageKey pageOf(int level, int x, int y) const { return {level, x >> pageShift_, y >> pageShift_}; }

    int pageTexels_;
    const PageTable& table_;
    const PagePool& pool_;
    int pageShift_;
};

// Each level as the one map a receiver is mapped into (only its matrices are set), by index
// from the first level.
std::vector<DepthMap> levelMaps(const LightFrame& frame, const ClipmapSettings& clipmap, const DepthRange& range);

struct LookupResult {
    std::vector<float> visibility;   // V per pixel
    size_t missingPixels = 0;        // a tap read as lit for want of a page with memory
    size_t unleveledPixels = 0;      // lit: reached by the light but in no level's window
};

// The pass every lookup of a virtual map makes over the pixels (the sun's, a local light's,
// the rays'), rows in parallel: a pixel without a surface or that `light` does not reach
// keeps V = 0, one that no level holds is lit and counted, and every other gets
// V = read(k, its PixelLevel, missing), which sets `missing` where a read found no page
// (the pixel is then counted). The counts are sums, the same for any thread count.
template <class Read>
LookupResult lookUpEachPixel(const GBuffer& g, const Light& light, const std::vector<PixelLevel>& levels,
                             const Read& read) {
    const LightReach reaches(light);
    LookupResult out{std::vector<float>(g.pixelCount(), 0.0f)};
    struct Counts {
        size_t missing = 0, unleveled = 0;
    };
    const Counts counts = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, g.height), Counts{},
        [&](const tbb::blocked_range<int>& rows, Counts c) {
            for (int j = rows.begin(); j < rows.end(); ++j) {
                for (int i = 0; i < g.width; ++i) {
                    const size_t k = g.index(i, j);
                    if (!g.hit[k] || !reaches(g.position[k], g.normal[k])) continue;   // V = 0
                    const PixelLevel& p = levels[k];
                    if (p.level == kNoLevel) {
                        ++c.unleveled, out.visibility[k] = 1.0f;
                        continue;
                    }
                    bool missing = false;
                    out.visibility[k] = read(k, p, missing);
                    c.missing += missing;
                }
            }
            return c;
        },
        [](Counts a, const Counts& b) {
            a.missing += b.missing, a.unleveled += b.unleveled;
            return a;
        });
    out.missingPixels = counts.missing, out.unleveledPixels = counts.unleveled;
    return out;
}

LookupResult lookUpPages(const GBuffer& g, const Light& sun, const LightFrame& frame, const ClipmapSettings& clipmap,
                         const DepthRange& range, const BiasSettings& bias, const PcfKernel& filter,
                         const std::vector<PixelLevel>& levels, const PageTable& table, const PagePool& pool);

// How far from a pixel's texel coordinate its lookup reads, texels: the filter's taps
// (tapReachTexels) and the normal offset, which moves the lookup up to normalOffsetTexels
// texels from the surface point's texel. Marking marks this box, so that the two agree.
double lookupReachTexels(const BiasSettings& bias, const FilterSettings& filter);

}  // namespace shadowlab::vsm
