// The receivers and their radiance transfers (Gibson et al. 2003, sections 4 and 5): the
// source set, the receiver patches (those the camera sees) and, at every vertex of a
// receiver, L_ij = rho_i B_j F_ij V_ij from each source j (patch_light.h), precomputed once
// with Embree rays against the model. Per frame the composite takes the occluded ones off
// the photograph, interpolated across each patch (equation 2).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "differential/background.h"
#include "differential/patch_light.h"

namespace shadowlab {

struct TransferTable {
    std::vector<uint32_t> sources;           // the source set, brightest first
    std::vector<uint32_t> receiverPatches;   // in patch order
    std::vector<uint32_t> vertices;          // the receivers' vertices (rows), in vertex order
    std::vector<int32_t> rowOfVertex;        // model vertex -> its row, -1 for none
    std::vector<glm::vec3> L;                // row r, source s at r * sources.size() + s
    // Per row the vertex's radiance L_i from every radiant patch, not only the source set:
    // what the photograph holds there (the LDR path's starting point, section 7.1).
    std::vector<glm::dvec3> total;

    size_t bytes() const;
};

// The source set of section 4: the brightest radiant patches (by luminance) whose power
// pi B A reaches `share` of all of it, brightest first.
std::vector<uint32_t> sourceSet(const PatchModel& model, const std::vector<glm::dvec3>& radiance, double share);

// The patches that cover at least one pixel.
std::vector<uint32_t> receiverPatches(const PatchModel& model, const PixelPatches& pixels);

TransferTable computeTransfers(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                               std::vector<uint32_t> sources, std::vector<uint32_t> receivers,
                               const ReferenceVisibility& modelRays, const PatchSampling& sampling);

}  // namespace shadowlab
