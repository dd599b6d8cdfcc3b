// A frame of differential rendering (Gibson et al. 2003, sections 6.1, 7 and 8): the
// synthetic object's box traversed through the shaft hierarchy gives the sources it may
// occlude and the receivers that may see it; the sources become n clusters (Figure 6), each
// with a shadow map of the simplified object from the centre of its most energetic patch;
// every receiver pixel a map shadows loses that cluster's transfers, interpolated from the
// patch's vertices (the occlusion mask M_ij and equations 1 and 2). The object itself is
// drawn from the whole mesh, shaded from the irradiance volume less the clusters its own
// maps hide from it (self-shadowing).
//
// Two paths: HDR, on the photograph's linear radiance, and LDR, on its 8-bit intensities
// with the intensity transfers of section 7.1 (intensity_transfer.h), so that a photograph
// whose radiance is unknown can still receive shadows.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "differential/cluster_shadow_maps.h"
#include "differential/irradiance_volume.h"
#include "differential/object_levels.h"
#include "differential/preprocess.h"
#include "differential/source_clusters.h"
#include "shadows/technique.h"

namespace shadowlab {

// The objects with what every frame of their paths shares: their two levels and their light.
struct PreparedObject {
    ObjectLevels levels;
    IrradianceVolume light;   // over the box of their whole paths
};

struct ObjectSettings {
    int shadowTriangles = 300;   // of the level the shadow maps draw
    double probeSpacingM = 0.15;
};

// Throws std::invalid_argument as objectLevels does, or for a spacing the irradiance volume
// refuses.
PreparedObject prepareObject(const DifferentialModel& model, std::span<const SyntheticObject> objects,
                             const ObjectSettings& settings = {});

struct CompositeSettings {
    int passes = 20;        // n, the shadow maps per frame; 0: one per occluded source ("all")
    int resolution = 256;   // texels per side of each map (the frustum holds only the object)
    bool ldr = false;       // composite 8-bit intensities (section 7.1) instead of radiance
    bool keepMasks = false; // keep each cluster's mask for the debug views
    raster::SimdLevel simd = raster::bestSimdLevel();
};

struct CompositeFrame {
    // HDR: linear radiance. LDR: 8-bit intensities (0 to 255, rounded) in every channel.
    std::vector<glm::vec3> image;
    std::vector<TechniqueStat> stats;
    // The intermediate buffers (docs/differential-rendering.md): per pixel, the object's
    // coverage, whether the traversal listed its receiver patch, and how many clusters' maps
    // shadow it; the traversal's sources and receivers, the clusters with their lights, and,
    // on request, each cluster's mask.
    std::vector<uint8_t> objectPixels, listedReceiverPixels;
    std::vector<uint8_t> shadowingClusters;
    ShaftHits hits;
    std::vector<SourceCluster> clusters;
    std::vector<glm::dvec3> lights;
    std::vector<std::vector<uint8_t>> clusterMasks;
};

// `placements` places object i (placementsAt gives a frame of their paths). The traversal
// runs once per object's box, so objects apart do not list the sources between them.
// Throws std::invalid_argument for passes < 0, a map size outside the depth map's range, a
// placement that is not finite, or a count of placements that is not the objects'.
CompositeFrame compositeFrame(const DifferentialModel& model, const PreparedObject& object,
                              std::span<const glm::mat4> placements, const CompositeSettings& settings = {});

// The model's triangles then the placed objects', as the camera draws them: a pixel on a
// triangle past the model's is an object's, whose material (its index) keeps its albedo.
WorldGeometry withObject(const DifferentialModel& model, const WorldGeometry& object);

// The box of a placed level's vertices (scenes/bounds.h's instanceBounds gives each object's).
Aabb boundsOf(const WorldGeometry& world);

}  // namespace shadowlab
