#include "differential/preprocess.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "differential/patch_radiance.h"
#include "scenes/float_range.h"
#include "shading/luminance.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

void requireValid(const CompositingScene& scene, const PreprocessSettings& settings) {
    if (!(settings.sourceShare > 0.0 && settings.sourceShare <= 1.0)) {
        throw std::invalid_argument("differential preprocessing: the source share must be in (0, 1]");
    }
    if (!(settings.significance > 0.0 && settings.significance <= 1.0)) {
        throw std::invalid_argument("differential preprocessing: the significance must be in (0, 1]");
    }
    const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
    if (!scene.background.empty() && scene.background.size() != pixels) {
        throw std::invalid_argument("differential preprocessing: the background needs one value per pixel");
    }
    for (const glm::vec3& L : scene.background) {
        if (!allFinite(L))
            throw std::invalid_argument("differential preprocessing: the background has a non-finite value");
    }
    const CameraResponse& T = scene.response;
    if (!(T.exposure > 0.0 && T.gamma > 0.0) || !std::isfinite(T.exposure) || !std::isfinite(T.gamma)) {
        throw std::invalid_argument(
            "differential preprocessing: the camera response needs a positive, finite exposure and gamma");
    }
}

// Per source-tree node and receiver row, the luminance of the node's summed transfers:
// the leaves' from the table, each inner node the sum of its children (children come
// after their parent in the tree, so a backward sweep meets them first).
std::vector<float> nodeTransfers(const SourceTree& tree, const TransferTable& table) {
    const size_t rows = table.vertices.size(), S = table.sources.size();
    std::vector<float> sums(tree.nodes.size() * rows, 0.0f);
    for (size_t n = tree.nodes.size(); n-- > 0;) {
        const SourceNode& node = tree.nodes[n];
        float* out = sums.data() + n * rows;
        if (node.leaf()) {
            for (size_t r = 0; r < rows; ++r) out[r] = luminance(table.L[r * S + node.patch]);
            continue;
        }
        const float* a = sums.data() + size_t(node.children[0]) * rows;
        const float* b = sums.data() + size_t(node.children[1]) * rows;
        for (size_t r = 0; r < rows; ++r) out[r] = a[r] + b[r];
    }
    return sums;
}

// Per receiver-octree node, the rows of its patches' vertices, each once.
std::vector<std::vector<int32_t>> receiverRows(const DifferentialModel& m) {
    std::vector<std::vector<int32_t>> rows(m.receiverOctree.nodes.size());
    for (size_t n = 0; n < rows.size(); ++n) {
        const ReceiverNode& r = m.receiverOctree.nodes[n];
        for (uint32_t k = r.firstPatch; k < r.firstPatch + r.patchCount; ++k) {
            const Patch& patch = m.model.patches[m.transfers.receiverPatches[m.receiverOctree.patches[k]]];
            for (const uint32_t v : patch.vertex) rows[n].push_back(m.transfers.rowOfVertex[v]);
        }
        std::sort(rows[n].begin(), rows[n].end());
        rows[n].erase(std::unique(rows[n].begin(), rows[n].end()), rows[n].end());
    }
    return rows;
}

// Section 6's rule, kept per vertex. The paper keeps a shaft if some vertex of its receivers
// gets `significance` (2%) of its light through it, and leaves it out otherwise; but a vertex
// loses the light of every shaft left out, and a light cut into n patches is n shafts, each
// of which may fall under the rule. So a shaft is left out only if at every vertex of its
// receivers the light left out so far and its own stay under that share (the paper's test is
// the case of nothing left out yet), and is charged to them: however finely the sources are
// cut, no vertex loses more than the share of its light, which the paper takes for less
// than the eye tells apart (its reference 17, Hecht).
ShaftHierarchy prunedShafts(const DifferentialModel& m) {
    const std::vector<std::vector<int32_t>> rowsOf = receiverRows(m);
    const size_t rows = m.transfers.vertices.size();
    std::vector<double> share(rows), leftOut(rows, 0.0);
    for (size_t r = 0; r < rows; ++r) share[r] = m.settings.significance * luminance(m.transfers.total[r]);
    // Called in the order the shafts are built, which fixes what is charged first.
    const auto keep = [&](int32_t sourceNode, int32_t receiverNode) {
        const float* through = m.nodeTransfer.data() + size_t(sourceNode) * rows;
        for (const int32_t r : rowsOf[size_t(receiverNode)]) {
            if (share[r] > 0.0 && leftOut[r] + through[r] >= share[r]) return true;
        }
        for (const int32_t r : rowsOf[size_t(receiverNode)]) leftOut[r] += through[r];
        return false;
    };
    return buildShaftHierarchy(m.sourceTree, m.receiverOctree, keep);
}

size_t shaftBytes(const ShaftHierarchy& shafts) {
    size_t bytes = shafts.nodes.size() * sizeof(ShaftNode);
    for (const ShaftNode& n : shafts.nodes) bytes += n.shaft.planes.size() * sizeof(ShaftPlane);
    return bytes;
}

}  // namespace

Aabb patchBounds(const PatchModel& model, uint32_t p) {
    const std::array<glm::dvec3, 4> c = model.corners(p);
    Aabb box{c[0], c[0]};
    for (const glm::dvec3& q : c) box.min = glm::min(box.min, q), box.max = glm::max(box.max, q);
    return box;
}

DifferentialModel preprocess(const CompositingScene& scene, const PreprocessSettings& settings) {
    requireValid(scene, settings);
    DifferentialModel m;
    m.camera = scene.camera;
    m.response = scene.response;
    m.settings = settings;
    StageTimer timer;
    m.model = flattenPatches(scene.surfaces);
    m.geometry = patchGeometry(m.model);
    m.modelRays = std::make_unique<ReferenceVisibility>(m.geometry, nullptr);   // patches: opaque
    m.radiance = patchRadiance(m.model, *m.modelRays, settings.sampling);
    timer.lap("radiance");
    m.pixels = pixelPatches(m.model, m.geometry, m.camera, settings.simd);
    m.background = scene.background.empty()
                       ? renderBackground(m.model, m.radiance, m.pixels, *m.modelRays, settings.sampling)
                       : scene.background;
    m.photographIntensities.resize(m.background.size());
    for (size_t k = 0; k < m.background.size(); ++k) {
        m.photographIntensities[k] = glm::vec3(glm::round(m.response(glm::dvec3(m.background[k]))));
    }
    timer.lap("background");
    m.transfers = computeTransfers(m.model, m.radiance, sourceSet(m.model, m.radiance, settings.sourceShare),
                                   receiverPatches(m.model, m.pixels), *m.modelRays, settings.sampling);
    timer.lap("transfers");
    const TransferTable& t = m.transfers;
    std::vector<Aabb> sourceBounds;
    std::vector<double> meanTransfer(t.sources.size(), 0.0);
    for (size_t s = 0; s < t.sources.size(); ++s) {
        sourceBounds.push_back(patchBounds(m.model, t.sources[s]));
        for (size_t r = 0; r < t.vertices.size(); ++r) meanTransfer[s] += luminance(t.L[r * t.sources.size() + s]);
        if (!t.vertices.empty()) meanTransfer[s] /= double(t.vertices.size());
    }
    m.sourceTree = buildSourceTree(sourceBounds, meanTransfer);
    std::vector<Aabb> receiverBounds;
    for (const uint32_t p : t.receiverPatches) receiverBounds.push_back(patchBounds(m.model, p));
    m.receiverOctree = buildReceiverOctree(receiverBounds, settings.receiverLeafSize);
    m.nodeTransfer = nodeTransfers(m.sourceTree, t);
    m.shafts = prunedShafts(m);
    timer.lap("hierarchy");
    timer.appendTo(m.stats);
    m.stats.push_back({"source_patches_count", double(t.sources.size())});
    m.stats.push_back({"receiver_patches_count", double(t.receiverPatches.size())});
    m.stats.push_back({"shaft_nodes_count", double(m.shafts.nodes.size())});
    m.stats.push_back({"shaft_leaves_count", double(m.shafts.leafCount())});
    m.stats.push_back({"transfers_bytes", double(t.bytes())});
    m.stats.push_back({"shafts_bytes", double(shaftBytes(m.shafts) + m.nodeTransfer.size() * sizeof(float))});
    return m;
}

}  // namespace shadowlab
