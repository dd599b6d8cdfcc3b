#include "differential/transfers.h"

#include <tbb/parallel_for.h>

#include "differential/patch_radiance.h"
#include "differential/source_set.h"
#include "shading/luminance.h"

namespace shadowlab {

size_t TransferTable::bytes() const {
    return L.size() * sizeof(glm::vec3) + total.size() * sizeof(glm::dvec3) +
           (sources.size() + receiverPatches.size() + vertices.size() + rowOfVertex.size()) * sizeof(uint32_t);
}

std::vector<uint32_t> sourceSet(const PatchModel& model, const std::vector<glm::dvec3>& radiance, double share) {
    const std::vector<uint32_t> radiant = radiantPatches(model, radiance);
    std::vector<EmittingPatch> emitting;
    for (const uint32_t p : radiant) emitting.push_back({luminance(radiance[p]), model.patches[p].area});
    std::vector<uint32_t> set = selectSources(emitting, share);
    for (uint32_t& s : set) s = radiant[s];
    return set;
}

std::vector<uint32_t> receiverPatches(const PatchModel& model, const PixelPatches& pixels) {
    std::vector<uint8_t> seen(model.patches.size(), 0);
    for (const uint32_t p : pixels.patch) {
        if (p != kNoPatch) seen[p] = 1;
    }
    std::vector<uint32_t> receivers;
    for (uint32_t p = 0; p < seen.size(); ++p) {
        if (seen[p]) receivers.push_back(p);
    }
    return receivers;
}

TransferTable computeTransfers(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                               std::vector<uint32_t> sources, std::vector<uint32_t> receivers,
                               const ReferenceVisibility& modelRays, const PatchSampling& sampling) {
    TransferTable table;
    table.sources = std::move(sources);
    table.receiverPatches = std::move(receivers);
    table.rowOfVertex.assign(model.vertices.size(), -1);
    for (const uint32_t p : table.receiverPatches) {
        for (const uint32_t v : model.patches[p].vertex) table.rowOfVertex[v] = 0;
    }
    for (uint32_t v = 0; v < model.vertices.size(); ++v) {
        if (table.rowOfVertex[v] < 0) continue;
        table.rowOfVertex[v] = int32_t(table.vertices.size());
        table.vertices.push_back(v);
    }
    const size_t S = table.sources.size();
    table.L.assign(table.vertices.size() * S, glm::vec3(0.0f));
    table.total.assign(table.vertices.size(), glm::dvec3(0.0));
    const std::vector<uint32_t> radiant = radiantPatches(model, radiance);
    std::vector<int32_t> slotOf(model.patches.size(), -1);   // patch -> its column
    for (size_t s = 0; s < S; ++s) slotOf[table.sources[s]] = int32_t(s);
    tbb::parallel_for(size_t(0), table.vertices.size(), [&](size_t r) {
        const uint32_t v = table.vertices[r];
        const glm::dvec3 x = model.vertexInside[v], n = model.vertexNormal[v];
        const glm::dvec3 rho = model.vertexReflectance[v];
        const auto seen = [&](const glm::dvec3& q) { return modelRays.pointVisible(glm::vec3(x), glm::vec3(n), q); };
        // The source set is a subset of the radiant patches: its transfers are computed once,
        // in the total and in the row.
        for (const uint32_t j : radiant) {
            const glm::dvec3 transfer = rho * patchTransfer(model, radiance[j], j, x, n, sampling, v, seen);
            table.total[r] += transfer;
            if (slotOf[j] >= 0) table.L[r * S + size_t(slotOf[j])] = glm::vec3(transfer);
        }
    });
    return table;
}

}  // namespace shadowlab
