// The intermediate buffers of the fin techniques (`--debug-buffers DIR`, debug_buffers.h),
// named <technique>-<name>.exr/.png:
//   layer-NN-shadow-map      the layer's hard shadow map (window depth, light space)
//   layer-NN-inner-weight    the inner penumbra map's weights (min of s_0), 0 where no fin
//   layer-NN-inner-depth     ... its depths as distances L_b from the light's plane (m)
//   layer-NN-outer-weight    the outer penumbra map's weights (max of s_0)
//   layer-NN-outer-depth     ... its depths (m)
//   layer-NN-illuminance     the illuminance buffer after layer NN (camera space)
//                            (layers without objects are skipped and write nothing)
//   fin-coverage             how many fin triangles cover each texel, inner and outer
//                            together (light space): the fins' outline and overlaps
//   layers                   the layer of each pixel's object, -1 where none (camera space)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/debug_buffers.h"
#include "shadows/depth_map.h"
#include "shadows/fins/fin_geometry.h"
#include "shadows/fins/fin_maps.h"

namespace shadowlab {

class FinDebug {
public:
    FinDebug(std::filesystem::path directory, const std::string& technique, const LightView& view);
    bool enabled() const { return debug_.enabled(); }

    // edgeWeight: the largest weight (eq. 1: 0.5; outer-only methods: 1), for the PNGs' scale.
    void writeLayer(int layer, const DepthMap& hard, const PenumbraMap* inner, const PenumbraMap& outer,
                    float edgeWeight, const GBuffer& gbuffer, const std::vector<float>& illuminance) const;
    void writeFinCoverage(const Fins& fins, int size, raster::SimdLevel simd) const;
    // The layer of each pixel's object (instanceLayer: per scene instance).
    void writePixelLayers(const GBuffer& gbuffer, const WorldGeometry& world, const std::vector<int>& instanceLayer,
                          int layerCount) const;

private:
    void writePenumbraMap(const std::string& prefix, const PenumbraMap& map, float edgeWeight) const;

    DebugBuffers debug_;
    LightView view_;
};

}  // namespace shadowlab
