// What a frame takes off the photograph at each receiver vertex (Gibson et al. 2003,
// sections 7 and 8): per cluster, the sum of its sources' transfers at every vertex of the
// listed receivers, in radiance (L_ij, equation 2) or, on the 8-bit path, in intensity
// (S_ij, equation 3). Figure 4 makes the intensity transfers before each frame, over the
// frame's own sources: ordered by their average transfer to the receivers, largest first,
// alternately in the two sets, each taken off its set's running radiance at the vertex.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "differential/preprocess.h"
#include "differential/source_clusters.h"

namespace shadowlab {

// Per receiver row, whether it is a vertex of a listed receiver (slots of
// TransferTable::receiverPatches).
std::vector<uint8_t> listedRows(const DifferentialModel& model, const std::vector<uint32_t>& listedReceivers);

// S_ij laid out like TransferTable::L, filled at the listed rows and sources (source slots),
// 0 elsewhere.
std::vector<glm::vec3> frameIntensityTransfers(const DifferentialModel& model,
                                               const std::vector<uint32_t>& listedSources,
                                               const std::vector<uint8_t>& rows);

// Per cluster c and row r at c * rows + r: the sum over the cluster's sources of `table`
// (TransferTable::L or frameIntensityTransfers) at the listed rows, 0 elsewhere.
std::vector<glm::vec3> clusterTransfers(const DifferentialModel& model, const std::vector<SourceCluster>& clusters,
                                        const std::vector<uint8_t>& rows, const std::vector<glm::vec3>& table);

}  // namespace shadowlab
