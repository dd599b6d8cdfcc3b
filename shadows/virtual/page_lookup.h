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

#include "scenes/scene.h"
#include "shading/gbuffer.h"
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

LookupResult lookUpPages(const GBuffer& g, const Light& sun, const LightFrame& frame, const ClipmapSettings& clipmap,
                         const DepthRange& range, const BiasSettings& bias, const PcfKernel& filter,
                         const std::vector<PixelLevel>& levels, const PageTable& table, const PagePool& pool);

// How far from a pixel's texel coordinate its lookup reads, texels: the filter's taps
// (tapReachTexels) and the normal offset, which moves the lookup up to normalOffsetTexels
// texels from the surface point's texel. Marking marks this box, so that the two agree.
double lookupReachTexels(const BiasSettings& bias, const FilterSettings& filter);

}  // namespace shadowlab::vsm
