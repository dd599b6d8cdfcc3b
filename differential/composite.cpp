#include "differential/composite.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "differential/frame_transfers.h"
#include "scenes/bounds.h"
#include "scenes/float_range.h"
#include "shadows/camera_pass.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

Aabb pathBounds(const ObjectLevels& levels, std::span<const SyntheticObject> objects) {
    Aabb box = boundsOf(placed(levels.whole, placementsAt(objects, 0)));
    for (size_t k = 1; k < objects[0].path.size(); ++k) {
        box = merged(box, boundsOf(placed(levels.whole, placementsAt(objects, k))));
    }
    return box;
}

// The traversal of each object's box, their lists merged (each source and receiver once).
ShaftHits traverseObjects(const DifferentialModel& m, const std::vector<Aabb>& boxes) {
    ShaftHits all;
    std::vector<uint8_t> source(m.transfers.sources.size(), 0), receiver(m.transfers.receiverPatches.size(), 0);
    std::vector<uint8_t> shaft(m.shafts.nodes.size(), 0);
    for (const Aabb& box : boxes) {
        const ShaftHits hits = traverseShafts(m.shafts, m.sourceTree, m.receiverOctree, box);
        for (const uint32_t s : hits.sourcePatches) if (!source[s]) source[s] = 1, all.sourcePatches.push_back(s);
        for (const uint32_t r : hits.receiverPatches) {
            if (!receiver[r]) receiver[r] = 1, all.receiverPatches.push_back(r);
        }
        for (const int32_t l : hits.leafShafts) {
            if (!shaft[size_t(l)]) shaft[size_t(l)] = 1, all.leafShafts.push_back(l);
        }
    }
    return all;
}

// The cluster's light: the centre of its patch with the largest transfer (section 8).
glm::dvec3 clusterLight(const DifferentialModel& m, const SourceCluster& cluster) {
    uint32_t best = cluster.patches.front();
    for (const uint32_t s : cluster.patches) {
        if (m.sourceTree.nodes[m.sourceTree.leafOfPatch[s]].transfer >
            m.sourceTree.nodes[m.sourceTree.leafOfPatch[best]].transfer)
            best = s;
    }
    return m.model.centre(m.transfers.sources[best]);
}

// What patch j sends a point of the object, B_j A_j cos cos / (pi r^2) (the form factor of a
// small patch seen from afar; section 7.2 approximates the object's transfers so): the light
// a self-shadowed point loses to a cluster, if the model lets it through (`open`).
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
    const std::vector<glm::vec3>& sums;       // clusterTransfers
    const std::vector<uint8_t>& listedPatch;
    // Per source slot, whether the model lets its light reach the object's centre: the
    // irradiance volume already left out what the model hides (the desk over the object),
    // so a self-shadow must not take it off again.
    const std::vector<uint8_t>& openToObject;
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
    size_t row[4];
    for (int corner = 0; corner < 4; ++corner) {
        row[corner] = size_t(f.m.transfers.rowOfVertex[f.m.model.patches[p].vertex[corner]]);
    }
    glm::vec3 taken(0.0f);
    uint8_t shadowing = 0;
    for (size_t c = 0; c < f.maps.size(); ++c) {
        if (!occluded(f.maps[c], P)) continue;
        ++shadowing;
        if (!out.clusterMasks.empty()) out.clusterMasks[c][k] = 1;
        for (int corner = 0; corner < 4; ++corner) taken += w[corner] * f.sums[c * rows + row[corner]];
    }
    out.listedReceiverPixels[k] = 1;
    out.shadowingClusters[k] = shadowing;
    const glm::vec3 result = glm::max(photo - taken, glm::vec3(0.0f));
    return f.ldr ? glm::round(result) : result;   // an 8-bit frame buffer keeps whole levels
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
        for (const uint32_t s : f.clusters[c].patches) {
            if (f.openToObject[s]) light -= pointTransfer(f.m, f.m.transfers.sources[s], x, n);
        }
    }
    out.objectPixels[k] = 1;
    out.shadowingClusters[k] = shadowing;
    const glm::dvec3 radiance =
        glm::dvec3(f.object.levels.whole.materials[g.material[k]].albedo) * glm::max(light, glm::dvec3(0.0));
    return f.ldr ? glm::vec3(glm::round(f.m.response(radiance))) : glm::vec3(radiance);
}

// One shadow map per cluster, from its light, of the simplified object (section 7.2); the
// lights go to `out`.
std::vector<ClusterMap> clusterMaps(const DifferentialModel& m, const PreparedObject& object,
                                    std::span<const glm::mat4> placements, const Aabb& box,
                                    const CompositeSettings& settings, CompositeFrame& out) {
    const WorldGeometry casters = placed(object.levels.simplified.scene, placements);
    const Sphere bound = boundingSphere(box);
    std::vector<ClusterMap> maps;
    for (const SourceCluster& cluster : out.clusters) {
        out.lights.push_back(clusterLight(m, cluster));
        maps.push_back(clusterShadowMap(out.lights.back(), bound.centre, bound.radius, casters, settings.resolution, settings.simd));
    }
    return maps;
}

// Per source slot: 1 if it is in a cluster and the model lets its patch's centre be seen
// from the object's centre (one ray per clustered source and frame).
std::vector<uint8_t> openToObject(const DifferentialModel& m, const std::vector<SourceCluster>& clusters,
                                  const glm::dvec3& centre) {
    std::vector<uint8_t> open(m.transfers.sources.size(), 0);
    for (const SourceCluster& cluster : clusters) {
        for (const uint32_t s : cluster.patches) {
            const glm::dvec3 target = m.model.centre(m.transfers.sources[s]);
            const glm::dvec3 d = target - centre;
            open[s] = glm::dot(d, d) > 0.0 && m.modelRays->pointVisible(glm::vec3(centre),
                                                                        glm::vec3(glm::normalize(d)), target);
        }
    }
    return open;
}

void appendFrameStats(CompositeFrame& out, size_t objectTriangles, const Scene& shadowLevel) {
    size_t shadowed = 0, shadowTriangles = 0;
    for (size_t k = 0; k < out.shadowingClusters.size(); ++k) {
        shadowed += out.shadowingClusters[k] > 0 && !out.objectPixels[k];
    }
    for (const Mesh& mesh : shadowLevel.meshes) shadowTriangles += mesh.triangles.size();
    out.stats.push_back({"object_triangles", double(objectTriangles)});
    out.stats.push_back({"shadow_map_triangles", double(shadowTriangles)});
    out.stats.push_back({"listed_sources_count", double(out.hits.sourcePatches.size())});
    out.stats.push_back({"listed_receivers_count", double(out.hits.receiverPatches.size())});
    out.stats.push_back({"clusters_count", double(out.clusters.size())});
    out.stats.push_back({"shadowed_pixels", double(shadowed)});
}

}  // namespace

WorldGeometry withObject(const DifferentialModel& m, const WorldGeometry& object) {
    WorldGeometry world = m.geometry;
    const uint32_t base = uint32_t(world.positions.size());
    world.positions.insert(world.positions.end(), object.positions.begin(), object.positions.end());
    for (const glm::uvec3& t : object.triangles) world.triangles.push_back(t + base);
    world.triangleMaterial.insert(world.triangleMaterial.end(), object.triangleMaterial.begin(),
                                  object.triangleMaterial.end());
    world.triangleInstance.insert(world.triangleInstance.end(), object.triangleInstance.begin(),
                                  object.triangleInstance.end());
    world.cornerNormals.insert(world.cornerNormals.end(), object.cornerNormals.begin(), object.cornerNormals.end());
    return world;
}

Aabb boundsOf(const WorldGeometry& world) {
    Aabb box{glm::dvec3(0.0), glm::dvec3(0.0)};
    if (world.positions.empty()) return box;
    box.min = box.max = glm::dvec3(world.positions.front());
    for (const glm::vec3& p : world.positions) {
        box.min = glm::min(box.min, glm::dvec3(p)), box.max = glm::max(box.max, glm::dvec3(p));
    }
    return box;
}

PreparedObject prepareObject(const DifferentialModel& model, std::span<const SyntheticObject> objects,
                             const ObjectSettings& settings) {
    PreparedObject prepared{objectLevels(objects, settings.shadowTriangles), {}};
    prepared.light = buildIrradianceVolume(model.model, model.radiance, *model.modelRays,
                                           pathBounds(prepared.levels, objects), settings.probeSpacingM,
                                           model.settings.sampling);
    return prepared;
}

CompositeFrame compositeFrame(const DifferentialModel& m, const PreparedObject& object,
                              std::span<const glm::mat4> placements, const CompositeSettings& settings) {
    if (settings.passes < 0) throw std::invalid_argument("differential composite: passes must be 0 (all) or more");
    if (settings.resolution < kMinMapResolution || settings.resolution > kMaxMapResolution) {
        throw std::invalid_argument("differential composite: the maps' resolution is out of range");
    }
    requireFinitePlacements(placements, "differential composite");
    StageTimer timer;
    CompositeFrame out;
    const WorldGeometry whole = placed(object.levels.whole, placements);
    const std::vector<Aabb> boxes = instanceBounds(object.levels.whole, whole);   // one per object
    const Aabb box = std::accumulate(boxes.begin() + 1, boxes.end(), boxes.front(),
                                     [](const Aabb& a, const Aabb& b) { return merged(a, b); });
    timer.lap("object");
    out.hits = traverseObjects(m, boxes);
    timer.lap("traversal");
    const int n = settings.passes > 0 ? settings.passes : std::max<int>(1, int(out.hits.sourcePatches.size()));
    if (!out.hits.sourcePatches.empty()) out.clusters = representativeSources(m.sourceTree, out.hits.sourcePatches, n);
    timer.lap("clusters");
    const std::vector<ClusterMap> maps = clusterMaps(m, object, placements, box, settings, out);
    timer.lap("shadow_maps");
    const std::vector<uint8_t> rows = listedRows(m, out.hits.receiverPatches);
    const std::vector<glm::vec3> sums = clusterTransfers(
        m, out.clusters, rows, settings.ldr ? frameIntensityTransfers(m, out.hits.sourcePatches, rows) : m.transfers.L);
    std::vector<uint8_t> listedPatch(m.model.patches.size(), 0);
    for (const uint32_t slot : out.hits.receiverPatches) listedPatch[m.transfers.receiverPatches[slot]] = 1;
    const std::vector<uint8_t> open = openToObject(m, out.clusters, centre(box));
    timer.lap("transfer_sums");
    // The model's pixels are the photograph's (m.pixels): only the object's are built.
    const GBuffer g = renderGBuffer(withObject(m, whole), m.camera, settings.simd,
                                    uint32_t(m.geometry.triangles.size()));
    timer.lap("camera");
    out.image = settings.ldr ? m.photographIntensities : m.background;
    out.objectPixels.assign(g.pixelCount(), 0);
    out.listedReceiverPixels.assign(g.pixelCount(), 0);
    out.shadowingClusters.assign(g.pixelCount(), 0);
    if (settings.keepMasks) out.clusterMasks.assign(maps.size(), std::vector<uint8_t>(g.pixelCount(), 0));
    // Object points are lifted past the simplified level's error and 1% of the largest object's size.
    double size = 0.0;
    for (const Aabb& b : boxes) size = std::max(size, glm::length(b.max - b.min));
    const double lift = object.levels.simplified.errorM() * largestScale(placements) + 0.005 * size;
    const FrameContext f{m, object, maps, out.clusters, sums, listedPatch, open, lift, settings.ldr};
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            out.image[k] = g.hit[k] ? objectPixel(f, g, k, out) : receiverPixel(f, k, out.image[k], out);
        }
    });
    timer.lap("composite");
    timer.appendTo(out.stats);
    appendFrameStats(out, whole.triangles.size(), object.levels.simplified.scene);
    return out;
}

}  // namespace shadowlab
