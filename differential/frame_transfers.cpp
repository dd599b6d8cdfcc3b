#include "differential/frame_transfers.h"

#include <algorithm>
#include <span>

#include <tbb/parallel_for.h>

#include "differential/intensity_transfer.h"

namespace shadowlab {

std::vector<uint8_t> listedRows(const DifferentialModel& m, const std::vector<uint32_t>& listedReceivers) {
    std::vector<uint8_t> rows(m.transfers.vertices.size(), 0);
    for (const uint32_t slot : listedReceivers) {
        for (const uint32_t v : m.model.patches[m.transfers.receiverPatches[slot]].vertex) {
            rows[size_t(m.transfers.rowOfVertex[v])] = 1;
        }
    }
    return rows;
}

std::vector<glm::vec3> frameIntensityTransfers(const DifferentialModel& m, const std::vector<uint32_t>& listedSources,
                                               const std::vector<uint8_t>& rows) {
    const size_t S = m.transfers.sources.size();
    const SourceTree& tree = m.sourceTree;
    std::vector<uint32_t> order = listedSources;
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return tree.patchTransfer(a) > tree.patchTransfer(b) || (tree.patchTransfer(a) == tree.patchTransfer(b) && a < b);
    });
    std::vector<uint8_t> set(order.size());
    for (size_t k = 0; k < set.size(); ++k) set[k] = uint8_t(k % 2);
    std::vector<glm::vec3> table(m.transfers.L.size(), glm::vec3(0.0f));
    tbb::parallel_for(size_t(0), rows.size(), [&](size_t r) {
        if (!rows[r]) return;
        std::vector<glm::dvec3> L(order.size()), out(order.size());
        for (size_t k = 0; k < order.size(); ++k) L[k] = glm::dvec3(m.transfers.L[r * S + order[k]]);
        intensityTransfers(m.transfers.total[r], std::span<const glm::dvec3>(L), std::span<const uint8_t>(set),
                           m.response, std::span(out));
        for (size_t k = 0; k < order.size(); ++k) table[r * S + order[k]] = glm::vec3(out[k]);
    });
    return table;
}

std::vector<glm::vec3> clusterTransfers(const DifferentialModel& m, const std::vector<SourceCluster>& clusters,
                                        const std::vector<uint8_t>& rows, const std::vector<glm::vec3>& table) {
    const size_t R = rows.size(), S = m.transfers.sources.size();
    std::vector<glm::vec3> sums(clusters.size() * R, glm::vec3(0.0f));
    tbb::parallel_for(size_t(0), clusters.size(), [&](size_t c) {
        for (size_t r = 0; r < R; ++r) {
            if (!rows[r]) continue;
            glm::vec3 sum(0.0f);
            for (const uint32_t s : clusters[c].patches) sum += table[r * S + s];
            sums[c * R + r] = sum;
        }
    });
    return sums;
}

}  // namespace shadowlab
