// The second pass of shadow mapping (Real-Time Rendering, 4th ed., section 7.4, Figure
// 7.10): every camera pixel's surface point is taken into the light's map, compared (with
// the bias and filter chosen) and turned into V. One map serves each pixel: a single map,
// a cube face or a cascade, as a selector decides. Pixels are independent; rows run in
// parallel and no value is reduced across threads.
//
// As in the reference, V = 0 where the light is behind the surface, dot(N, L - P) <= 0,
// and outside a spot light's cone.
//
// The pass goes row by row. Which map serves each pixel is decided in double by the
// selector. Then three stages run in float through the vector kernels of lookup_kernel.h,
// compiled for the filter and for the SIMD level asked for (every level gives the same
// bits): whether the light reaches the pixel, decided exactly as lightReaches() decides
// it in double (float where it can certify the sign, double where it cannot); the
// projection into the map with the bias; and the filter's taps. Float moves a receiver by
// at most 5e-4 texel and 3.6 steps of 2^-24 in depth from the double lookup it replaced
// (sphere-box, test_lookup_kernel.cpp), the order of the map's own float rounding, which
// the slope-scaled bias's 4 units cover; of the 32 golden cases three changed, each for the
// better or by a rounding (docs/shadow-maps.md, "Precision of the lookup").
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raster/tile_kernels.h"
#include "scenes/camera.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/lights.h"
#include "shadows/depth_map.h"
#include "shadows/maps/lookup_kernel.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

// A map selector is a functor, select(P) = the index of the map that serves the receiver
// at P, or -1 for none (V = 0). The one for a single map:
struct OneMap {
    int operator()(const glm::dvec3&) const { return 0; }
};

// The texel density is a diagnostic, not part of V: measured at every pixel for the debug
// view, and otherwise only at the pixels its median is taken over, every
// kDensitySampleStride-th pixel of every kDensitySampleStride-th row (a regular sample, the
// same whatever the thread count: 1/64 of the pixels, 16,000 at 1280 x 800).
inline constexpr int kDensitySampleStride = 8;

struct ShadowLookup {
    int width = 0;
    std::vector<float> visibility;     // per pixel
    std::vector<float> texelDensity;   // map texels per screen pixel (area ratio), 0 where none or not measured
    std::vector<int8_t> mapIndex;      // the map used, -1 where none
};

// The area in map texels of the footprint of camera pixel (i, j) on the receiver plane
// (P, N): |det| of the Jacobian of the map's texel coordinates across one pixel step.
double texelsPerPixel(const DepthMap& map, const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N);

// The lookup's kernels for a SIMD level this CPU supports (std::invalid_argument otherwise).
const LookupKernels& lookupKernels(raster::SimdLevel simd);

inline bool inDensitySample(int i, int j) { return i % kDensitySampleStride == 0 && j % kDensitySampleStride == 0; }

// The float lookup for one set of maps, bias and filter (lookup_kernel.h), ready to run
// on rows of receivers.
class LookupPass {
public:
    // The pass reads the maps and the light in place: they must outlive it.
    LookupPass(std::span<const DepthMap> maps, const Light& light, const BiasSettings& bias, const PcfKernel& kernel,
               raster::SimdLevel simd);
    // Percentage-closer soft shadows (the kernel's kLookupPcss filter) on one perspective map
    // from an area light's centre, with receiver-plane bias: the blocker search's and the
    // filter's Poisson disks (unit disk), the search region, and w_light of eq. 7.6 in
    // texels at unit distance.
    struct Pcss {
        const PcfKernel& search;
        double searchRegion = 1.0;
        const PcfKernel& filter;
        glm::dvec2 lightTexels{0.0};
        // The map's min/max hierarchy (min_max_hierarchy.h), which lets the kernel skip the
        // taps whose answer it proves; null: every tap is taken. It must outlive the pass.
        const LookupHierarchy* hierarchy = nullptr;
    };
    LookupPass(const DepthMap& map, const Light& light, const Pcss& pcss, raster::SimdLevel simd);
    // Contact-hardening soft shadows (the kernel's kLookupChs filter) on such a map, with
    // receiver-plane bias: nodes per side of the blocker search's reading level and N of the
    // filter's N x N grid, w_light as above, and the map's min/max hierarchy, which the
    // search reads. It must outlive the pass.
    struct Chs {
        int searchNodes = 8;
        int filterNodes = 8;
        glm::dvec2 lightTexels{0.0};
        const LookupHierarchy& hierarchy;
    };
    LookupPass(const DepthMap& map, const Light& light, const Chs& chs, raster::SimdLevel simd);
    // PCSS's blocker search alone (the kernel's kLookupBlockerSearch) on such a map: the
    // blockers' mean distance per pixel, V = 1 where it finds none, 0 where it does.
    struct BlockerSearch {
        const PcfKernel& search;
        double searchRegion = 1.0;
        glm::dvec2 lightTexels{0.0};
    };
    LookupPass(const DepthMap& map, const Light& light, const BlockerSearch& search, raster::SimdLevel simd);
    ~LookupPass();

    // A row's working memory: which map serves each pixel, the receivers as the maps see
    // them, the Poisson rotations. One per task, reused for its rows.
    struct Scratch {
        std::vector<uint8_t> served;   // 1 + the serving map, else 0 (LookupRow::served)
        std::vector<float> receivers, rotationCos, rotationSin;
        explicit Scratch(int count)
            : served(size_t(count)), receivers(7 * size_t(count)), rotationCos(size_t(count)), rotationSin(size_t(count)) {}
    };

    // Whole images the pass writes, row by row; the blocker distance only for pcss, chs and
    // the blocker search, the width for the first two, known taps only for pcss with a
    // hierarchy, the search level only for chs (LookupRow).
    struct Outputs {
        float* visibility;
        float* blockerDistance = nullptr;
        float* penumbraWidth = nullptr;
        float* knownTaps = nullptr;
        float* searchLevel = nullptr;
    };

    // Row j's pixels into the outputs, given which map serves each in scratch.served; the
    // scratch holds a row. Decides where the light reaches, as lightReaches() does.
    void lookUpRow(const GBuffer& g, int j, Scratch& scratch, const Outputs& out) const;

private:
    struct Tables;
    std::unique_ptr<Tables> tables_;
};

// The pass over every row of g, rows in parallel, its one map serving every surface pixel
// (no selector, no texel density): PCSS, contact hardening and multi-sample.
void lookUpEveryRow(const GBuffer& g, const LookupPass& pass, const LookupPass::Outputs& out);

// everyPixelDensity: measure the texel density at every pixel (the debug view), not only
// at the sample its median is taken over.
template <class MapSelector>
ShadowLookup lookUpShadows(const GBuffer& g, const Camera& camera, const Light& light, std::span<const DepthMap> maps,
                           const MapSelector& select, const BiasSettings& bias, const PcfKernel& kernel,
                           raster::SimdLevel simd, bool everyPixelDensity = false) {
    ShadowLookup out;
    out.width = g.width;
    out.visibility.assign(g.pixelCount(), 0.0f);
    out.texelDensity.assign(g.pixelCount(), 0.0f);
    out.mapIndex.assign(g.pixelCount(), -1);
    const PixelRays rays(camera);
    const LookupPass pass(maps, light, bias, kernel, simd);
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        LookupPass::Scratch scratch(g.width);
        for (int j = rows.begin(); j < rows.end(); ++j) {
            // The map serving each surface pixel, whether or not the light reaches it: the
            // debug views show it, and the texel density is measured wherever there is a surface.
            // The row's arrays and width are held in locals: through the containers, every byte
            // stored could alias them, and the loop reloaded them per pixel.
            const int width = g.width;
            const size_t k0 = g.index(0, j);
            const uint8_t* hit = g.hit.data() + k0;
            const glm::vec3* position = g.position.data() + k0;
            int8_t* mapIndex = out.mapIndex.data() + k0;
            uint8_t* served = scratch.served.data();
            for (int i = 0; i < width; ++i) {
                const int m = hit[i] ? select(glm::dvec3(position[i])) : -1;
                mapIndex[i] = int8_t(m);
                served[i] = uint8_t(m + 1);
            }
            // Only the sampled columns are visited: this runs per row of the hot pass.
            for (int i = 0; i < g.width; i += everyPixelDensity ? 1 : kDensitySampleStride) {
                const size_t k = g.index(i, j);
                if (out.mapIndex[k] < 0 || !(everyPixelDensity || inDensitySample(i, j))) continue;
                out.texelDensity[k] = float(texelsPerPixel(maps[size_t(out.mapIndex[k])], rays, i, j,
                                                           glm::dvec3(g.position[k]), glm::dvec3(g.normal[k])));
            }
            pass.lookUpRow(g, j, scratch, {out.visibility.data()});
        }
    });
    return out;
}

// The median of the texel density over the sampled pixels a map served (0 if none).
double medianTexelDensity(const ShadowLookup& lookup);

}  // namespace shadowlab
