// Stage 1 of every volumetric shadow map: what the light sees through each texel of one view
// (light_view.h: the frustum fitted to the receivers, or one cube face of a point light they
// surround; volumetric_frame.h chooses), one rasterizer pass per kind of caster:
//   - the opaque casters into an ordinary depth map, drawn with the shadow map's bias;
//   - the translucent casters, depth-tested against it but not writing depth, into
//     per-tile fragment lists (FragmentOutput::FragmentList): every layer in front of the
//     nearest opaque surface at once, as the A-buffer and per-pixel linked lists of the
//     GPU methods gather them (Real-Time Rendering, 4th ed., sections 5.5 and 7.8);
//   - the density volumes marched along each texel's ray (volume_march.h) up to the opaque
//     surface, cut into pieces of small optical depth.
// The result, per texel and nearest first, is a list of attenuation events: a surface at
// one depth, or a piece of volume from one depth to another, each with the optical depth
// it adds (-ln of the luminance it passes) and the light it passes per channel.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shadows/caster_transmission.h"
#include "shadows/depth_map.h"
#include "shadows/light_view.h"
#include "shadows/technique.h"

namespace shadowlab {

// A volume piece adds at most this optical depth, so that a curve linear in transmittance
// between a piece's ends stays within 1.3e-3 of the exponential (the largest gap between
// exp(-x) and its chord over [0, 0.1]).
inline constexpr double kMaxPieceOpticalDepth = 0.1;

struct VolumetricLayers {
    DepthMap opaque;                    // the nearest opaque surface per texel
    // Per texel (row-major, row 0 at the top) its events, nearest first: those of texel t
    // are [start[t], start[t + 1]).
    std::vector<uint32_t> start;
    std::vector<float> depthNear;       // window depth where the event begins
    std::vector<float> depthFar;        // ... and ends: = depthNear for a surface
    std::vector<float> opticalDepth;    // -ln(luminance passed), >= 0
    std::vector<glm::vec3> passed;      // the light it passes per channel
    std::vector<uint32_t> triangle;     // the surface's triangle, kVolumePiece for a volume piece
    uint64_t translucentFragments = 0;  // surfaces drawn
    uint64_t volumePieces = 0;
    float nearestDepth = 1.0f, farthestDepth = 0.0f;   // over every event

    static constexpr uint32_t kVolumePiece = UINT32_MAX;
    int size() const { return opaque.size; }
    uint32_t eventCount(size_t texel) const { return start[texel + 1] - start[texel]; }
};

struct VolumetricLayerSettings {
    int resolution = 512;
    raster::PolygonOffset opaqueOffset;   // the opaque map's bias
};

// The layers seen through `view`, a map of settings.resolution texels per side.
VolumetricLayers renderVolumetricLayers(const ShadowInputs& in, const LightView& view,
                                        const CasterTransmission& transmission,
                                        const VolumetricLayerSettings& settings);

}  // namespace shadowlab
