#include "compositing/differential/composite.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "shadows/camera_pass.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

Aabb pathBounds(const ObjectLevels& levels, const std::vector<glm::mat4>& path) {
    Aabb box = boundsOf(placed(levels.whole, path.front()));
    for (const glm::mat4& placement : path) {
        const Aabb b = boundsOf(placed(levels.whole, placement));
        box.min = glm::min(box.min, b.min), box.max = glm::max(box.max, b.max);
    }
    return box;
}

// Per cluster and receiver row, the sum of the cluster's transfers (radiance or intensity)
// at the rows of the listed receivers; other rows stay 0.
std::vector<glm::vec3> clusterSums(const DifferentialModel& m, const std::vector<SourceCluster>& clusters,
                                   const std::vector<uint32_t>& listedReceivers, const std::vector<glm::vec3>& table) {
    const size_t rows = m.transfers.vertices.size(), S = m.transfers.sources.size();
    std::vector<glm::vec3> sums(clusters.size() * rows, glm::vec3(0.0f));
    std::vector<uint8_t> listedRow(rows, 0);
    for (const uint32_t slot : listedReceivers) {
        for (const uint32_t v : m.model.patches[m.transfers.receiverPatches[slot]].vertex) {
            listedRow[size_t(m.transfers.rowOfVertex[v])] = 1;
        }
    }
    tbb::parallel_for(size_t(0), clusters.size(), [&](size_t c) {
        for (size_t r = 0; r < rows; ++r) {
            if (!listedRow[r]) continue;
            glm::vec3 sum(0.0f);
            for (const uint32_t s : clusters[c].patches) sum += table[r * S + s];
            sums[c * rows + r] = sum;
        }
    });
    return sums;
}

// The cluster's light: the centre of its patch with the largest transfer (section 8).
glm::dvec3 clusterLight(const DifferentialModel& m, const SourceCluster& cluster) {
    uint32_t best = cluster.patches.front();
    for (const uint32_t s : cluster.patches) {
        if (m.sourceTree.nodes[m.sourceTree.leafOfPatch[s]].transfer > m.sourceTree.nodes[m.sourceTree.leafOfPatch[best]].transfer) best = s;
    }
    return m.model.centre(m.transfers.sources[best]);
}

// What patch j sends a point of the object, B_j A_j cos cos / (pi r^2) (the form factor of a
// small patch seen from afar): the light a self-shadowed point loses to a cluster.
glm::dvec3 pointTransfer(const DifferentialModel& m, uint32_t patch, const glm::dvec3& x, const glm::dvec3& n) {
    const Patch& p = m.model.patches[patch];
    const glm::dvec3 d = m.model.centre(patch) - x;
    const double r2 = glm::dot(d, d);
    const double cosX = glm::dot(n, d), cosP = -glm::dot(p.normal, d);
    if (cosX <= 0.0 || cosP <= 0.0 || r2 == 0.0) return glm::dvec3(0.0);
    return m.radiance[patch] * (p.area * cosX * cosP / (std::numbers::pi * r2 * r2));
}

struct FrameContext {
    const DifferentialModel& m;
    const PreparedObject& object;
    const std::vector<ClusterMap>& maps;
    const std::vector<SourceCluster>& clusters;
    const std::vector<glm::vec3>& sums;
    const std::vector<uint8_t>& listedPatch;
    double lift;   // m, object points move out along their normal before their own maps
    bool ldr;
};

// A receiver pixel: the photograph less the transfers of every cluster whose map shadows it.
glm::vec3 receiverPixel(const FrameContext& f, size_t k, const glm::vec3& photo, CompositeFrame& out) {
    const uint32_t p = f.m.pixels.patch[k];
    if (p == kNoPatch || !f.listedPatch[p]) return photo;
    const glm::dvec3 P(f.m.pixels.gbuffer.position[k]);
    const glm::vec2 uv = f.m.pixels.uv[k];
    const float w[4] = {(1 - uv.x) * (1 - uv.y), uv.x * (1 - uv.y), uv.x * uv.y, (1 - uv.x) * uv.y};
    const size_t rows = f.m.transfers.vertices.size();
    glm::vec3 taken(0.0f);
    uint8_t shadowing = 0;
    for (size_t c = 0; c < f.maps.size(); ++c) {
        if (!occluded(f.maps[c], P)) continue;
        ++shadowing;
        if (!out.clusterMasks.empty()) out.clusterMasks[c][k] = 1;
        for (int corner = 0; corner < 4; ++corner) {
            const size_t row = size_t(f.m.transfers.rowOfVertex[f.m.model.patches[p].vertex[corner]]);
            taken += w[corner] * f.sums[c * rows + row];
        }
    }
    out.listedReceiverPixels[k] = 1;
    out.shadowingClusters[k] = shadowing;
    return glm::max(photo - taken, glm::vec3(0.0f));
}

// An object pixel: its albedo times the irradiance volume's light, less what its own maps
// hide from it.
glm::vec3 objectPixel(const FrameContext& f, const GBuffer& g, size_t k, CompositeFrame& out) {
    const glm::dvec3 x(g.position[k]), n(g.shadingNormal[k]);
    glm::dvec3 light = f.object.light.at(x, n);
    uint8_t shadowing = 0;
    for (size_t c = 0; c < f.maps.size(); ++c) {
        if (!occluded(f.maps[c], x + f.lift * glm::dvec3(g.normal[k]))) continue;
        ++shadowing;
        for (const uint32_t s : f.clusters[c].patches) light -= pointTransfer(f.m, f.m.transfers.sources[s], x, n);
    }
    out.objectPixels[k] = 1;
    out.shadowingClusters[k] = shadowing;
    const glm::dvec3 radiance = glm::dvec3(f.object.levels.whole.materials[0].albedo) * glm::max(light, glm::dvec3(0.0));
    return f.ldr ? glm::vec3(glm::round(f.m.response(radiance))) : glm::vec3(radiance);
}

}  // namespace

WorldGeometry withObject(const DifferentialModel& m, const WorldGeometry& object) {
    WorldGeometry world = m.geometry;
    world.cornerNormals.clear();
    for (const Patch& p : m.model.patches) world.cornerNormals.insert(world.cornerNormals.end(), 6, glm::vec3(p.normal));
    const uint32_t base = uint32_t(world.positions.size());
    world.positions.insert(world.positions.end(), object.positions.begin(), object.positions.end());
    for (const glm::uvec3& t : object.triangles) world.triangles.push_back(t + base);
    world.triangleMaterial.insert(world.triangleMaterial.end(), object.triangles.size(), 0u);
    world.triangleInstance.insert(world.triangleInstance.end(), object.triangles.size(), 0u);
    world.cornerNormals.insert(world.cornerNormals.end(), object.cornerNormals.begin(), object.cornerNormals.end());
    return world;
}

Aabb boundsOf(const WorldGeometry& world) {
    Aabb box{glm::dvec3(0.0), glm::dvec3(0.0)};
    if (world.positions.empty()) return box;
    box.min = box.max = glm::dvec3(world.positions.front());
    for (const glm::vec3& p : world.positions) box.min = glm::min(box.min, glm::dvec3(p)), box.max = glm::max(box.max, glm::dvec3(p));
    return box;
}

PreparedObject prepareObject(const DifferentialModel& model, const SyntheticObject& object, const ObjectSettings& settings) {
    if (object.path.empty()) throw std::invalid_argument("synthetic object: its path has no frame");
    PreparedObject prepared{objectLevels(object, settings.shadowTriangles), {}, object.path};
    prepared.light = buildIrradianceVolume(model.model, model.radiance, *model.modelRays, pathBounds(prepared.levels, object.path),
                                           settings.probeSpacingM, model.settings.sampling);
    return prepared;
}

std::vector<glm::vec3> photographIntensities(const DifferentialModel& model) {
    std::vector<glm::vec3> intensities(model.background.size());
    for (size_t k = 0; k < intensities.size(); ++k) {
        intensities[k] = glm::vec3(glm::round(model.response(glm::dvec3(model.background[k]))));
    }
    return intensities;
}

CompositeFrame compositeFrame(const DifferentialModel& m, const PreparedObject& object, const glm::mat4& placement,
                              const CompositeSettings& settings) {
    if (settings.passes < 0) throw std::invalid_argument("differential composite: passes must be 0 (all) or more");
    if (settings.mapSize < kMinMapResolution || settings.mapSize > kMaxMapResolution) {
        throw std::invalid_argument("differential composite: the map size is out of range");
    }
    StageTimer timer;
    CompositeFrame out;
    const WorldGeometry whole = placed(object.levels.whole, placement);
    const WorldGeometry casters = placed(object.levels.simplified.scene, placement);
    const Aabb box = boundsOf(whole);
    timer.lap("object");
    out.hits = traverseShafts(m.shafts, m.sourceTree, m.receiverOctree, box);
    timer.lap("traversal");
    const int n = settings.passes > 0 ? settings.passes : std::max<int>(1, int(out.hits.sourcePatches.size()));
    if (!out.hits.sourcePatches.empty()) out.clusters = representativeSources(m.sourceTree, out.hits.sourcePatches, n);
    timer.lap("clusters");
    const glm::dvec3 centre = 0.5 * (box.min + box.max);
    const double radius = 0.5 * glm::length(box.max - box.min);
    std::vector<ClusterMap> maps;
    for (const SourceCluster& cluster : out.clusters) {
        out.lights.push_back(clusterLight(m, cluster));
        maps.push_back(clusterShadowMap(out.lights.back(), centre, radius, casters, settings.mapSize, settings.simd));
    }
    timer.lap("shadow_maps");
    const std::vector<glm::vec3> sums =
        clusterSums(m, out.clusters, out.hits.receiverPatches, settings.ldr ? m.intensityTransfers : m.transfers.L);
    std::vector<uint8_t> listedPatch(m.model.patches.size(), 0);
    for (const uint32_t slot : out.hits.receiverPatches) listedPatch[m.transfers.receiverPatches[slot]] = 1;
    timer.lap("transfer_sums");
    const uint32_t modelTriangles = uint32_t(m.geometry.triangles.size());
    // The model's pixels are the photograph's (m.pixels): only the object's are built.
    const GBuffer g = renderGBuffer(withObject(m, whole), m.camera, settings.simd, modelTriangles);
    timer.lap("camera");
    const size_t pixels = g.pixelCount();
    out.image = settings.ldr ? photographIntensities(m) : m.background;
    out.objectPixels.assign(pixels, 0);
    out.listedReceiverPixels.assign(pixels, 0);
    out.shadowingClusters.assign(pixels, 0);
    if (settings.keepMasks) out.clusterMasks.assign(maps.size(), std::vector<uint8_t>(pixels, 0));
    const double lift = object.levels.simplified.errorM() * largestScale(placement) + 0.005;
    const FrameContext f{m, object, maps, out.clusters, sums, listedPatch, lift, settings.ldr};
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            out.image[k] = g.hit[k] ? objectPixel(f, g, k, out) : receiverPixel(f, k, out.image[k], out);
        }
    });
    timer.lap("composite");
    timer.appendTo(out.stats);
    size_t shadowed = 0;
    for (size_t k = 0; k < pixels; ++k) shadowed += out.shadowingClusters[k] > 0 && !out.objectPixels[k];
    out.stats.push_back({"object_triangles", double(whole.triangles.size())});
    out.stats.push_back({"shadow_map_triangles", double(casters.triangles.size())});
    out.stats.push_back({"listed_sources_count", double(out.hits.sourcePatches.size())});
    out.stats.push_back({"listed_receivers_count", double(out.hits.receiverPatches.size())});
    out.stats.push_back({"clusters_count", double(out.clusters.size())});
    out.stats.push_back({"shadowed_pixels", double(shadowed)});
    return out;
}

}  // namespace shadowlab
