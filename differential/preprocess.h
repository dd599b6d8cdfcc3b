// Everything Gibson et al. 2003 compute once per photograph (sections 4 to 6 and 9's
// preprocessing): the model's patches and their radiance, which patch each pixel sees, the
// photograph (rendered for the built-in cases), the source set and the receivers, the
// transfers, the two hierarchies with the source tree's summed transfers, and the shaft
// hierarchy between them pruned by the 2% rule. Each frame then only traverses, clusters,
// renders shadow maps and subtracts (composite.h).
#pragma once

#include <memory>
#include <vector>

#include "differential/background.h"
#include "differential/patch_light.h"
#include "differential/receiver_octree.h"
#include "differential/scene/compositing_scene.h"
#include "differential/shaft_hierarchy.h"
#include "differential/source_tree.h"
#include "differential/transfers.h"
#include "raster/tile_kernels.h"
#include "shadows/reference/reference.h"
#include "shadows/technique.h"

namespace shadowlab {

struct PreprocessSettings {
    double sourceShare = 0.7;       // of all radiant power (section 4)
    double significance = 0.02;     // the most of a vertex's light the shafts leave out (section 6)
    uint32_t receiverLeafSize = 8;  // patches per receiver octree leaf (section 6)
    PatchSampling sampling;
    raster::SimdLevel simd = raster::bestSimdLevel();
};

struct DifferentialModel {
    Camera camera;
    CameraResponse response;
    PatchModel model;
    WorldGeometry geometry;                  // patchGeometry(model)
    std::unique_ptr<ReferenceVisibility> modelRays;
    std::vector<glm::dvec3> radiance;        // per patch
    PixelPatches pixels;
    std::vector<glm::vec3> background;       // the photograph, linear radiance
    TransferTable transfers;
    // The photograph as the 8-bit path starts from it: round(T(background)) per channel.
    std::vector<glm::vec3> photographIntensities;
    SourceTree sourceTree;                   // over source slots (columns of the transfers)
    ReceiverOctree receiverOctree;           // over receiver slots (TransferTable::receiverPatches)
    // Per source-tree node and receiver row, the luminance of the node's summed transfers.
    std::vector<float> nodeTransfer;
    ShaftHierarchy shafts;
    PreprocessSettings settings;
    // Each stage's wall time (radiance_ms, background_ms, transfers_ms, hierarchy_ms), the
    // sizes (source_patches_count, receiver_patches_count, shaft_nodes_count,
    // shaft_leaves_count) and the memory (transfers_bytes, shafts_bytes): section 9's figures.
    std::vector<TechniqueStat> stats;
};

// Throws std::invalid_argument for a scene whose model is invalid (flattenPatches), whose
// background is neither empty nor one finite value per pixel, whose camera response has an
// exposure or gamma that is not positive and finite, or a share or significance outside
// (0, 1].
DifferentialModel preprocess(const CompositingScene& scene, const PreprocessSettings& settings = {});

// The box of patch p's corners.
Aabb patchBounds(const PatchModel& model, uint32_t p);

}  // namespace shadowlab
