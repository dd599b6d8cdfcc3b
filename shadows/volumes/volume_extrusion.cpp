#include "shadows/volumes/volume_extrusion.h"

#include <limits>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

constexpr uint32_t kUnmapped = std::numeric_limits<uint32_t>::max();

// Vertices of one instance's volume: each world vertex used gets one finite copy (w = 1)
// and one copy at infinity (w = 0), numbered locally in order of first use.
//
// With caps, every finite vertex is numbered first, in world order. The rasterizer clips a
// triangle starting from its smallest vertex index (rasterizer.cpp, canonicalIndexOrder),
// so a light cap that crosses the near plane gets the depth bits of the depth prepass only
// if its indices are ordered as the world's are.
class VolumeVertices {
public:
    VolumeVertices(const WorldGeometry& world, const InstanceRange& range, const glm::dvec4& light,
                   uint32_t vertexCount, bool worldOrder)
        : world_(world), firstVertex_(range.firstVertex), light_(light),
          finite_(vertexCount, kUnmapped), infinite_(vertexCount, kUnmapped) {
        for (uint32_t v = 0; worldOrder && v < vertexCount; ++v) finite(firstVertex_ + v);
    }

    uint32_t finite(uint32_t worldVertex) {
        return map(finite_, worldVertex, glm::vec4(world_.positions[worldVertex], 1.0f));
    }
    uint32_t infinite(uint32_t worldVertex) {
        const glm::dvec3 away = -towardsLight(light_, glm::dvec3(world_.positions[worldVertex]));
        return map(infinite_, worldVertex, glm::vec4(glm::vec3(away), 0.0f));
    }
    std::vector<glm::vec4> vertices;

private:
    uint32_t map(std::vector<uint32_t>& local, uint32_t worldVertex, const glm::vec4& position) {
        uint32_t& index = local[worldVertex - firstVertex_];
        if (index == kUnmapped) index = uint32_t(vertices.size()), vertices.push_back(position);
        return index;
    }
    const WorldGeometry& world_;
    uint32_t firstVertex_;
    glm::dvec4 light_;
    std::vector<uint32_t> finite_, infinite_;
};

struct InstanceVolume {
    std::vector<glm::vec4> vertices;
    std::vector<glm::uvec3> sides, lightCaps, darkCaps;
    std::vector<SilhouetteEdge> silhouette;
};

// A triangle as it is (sign +1) or reversed (sign -1).
glm::uvec3 oriented(glm::uvec3 t, int sign) { return sign > 0 ? t : glm::uvec3(t.x, t.z, t.y); }

InstanceVolume extrudeInstance(const WorldGeometry& world, const Mesh& mesh, const InstanceRange& range,
                               const EdgeAdjacency& adjacency, const glm::dvec4& light, bool withCaps) {
    const std::vector<CasterSigns> signs = instanceCasterSigns(world, range, light, adjacency.closed);
    InstanceVolume out;
    out.silhouette = silhouetteEdges(adjacency, lightSigns(signs), range.firstVertex);
    VolumeVertices v(world, range, light, uint32_t(mesh.positions.size()), withCaps);
    for (const SilhouetteEdge& e : out.silhouette) {
        const uint32_t a = v.finite(e.from), b = v.finite(e.to);
        const uint32_t aInf = v.infinite(e.from), bInf = v.infinite(e.to);
        out.sides.push_back({b, a, aInf});
        out.sides.push_back({b, aInf, bInf});
    }
    for (uint32_t t = 0; withCaps && t < range.triangleCount; ++t) {
        const glm::uvec3& tri = world.triangles[range.firstTriangle + t];
        if (signs[t].light != 0) {
            out.lightCaps.push_back(oriented({v.finite(tri.x), v.finite(tri.y), v.finite(tri.z)}, signs[t].light));
        }
        if (signs[t].dark != 0) {
            out.darkCaps.push_back(oriented({v.infinite(tri.x), v.infinite(tri.y), v.infinite(tri.z)}, signs[t].dark));
        }
    }
    out.vertices = std::move(v.vertices);
    return out;
}

// Instance volumes concatenated in instance order (so the result does not depend on how
// the instances were spread over threads): every side, then every light cap, then every
// dark cap, so that z-pass can draw a prefix.
ShadowVolume concatenate(std::vector<InstanceVolume>& parts) {
    ShadowVolume volume;
    std::vector<uint32_t> vertexBase;
    for (InstanceVolume& part : parts) {
        vertexBase.push_back(uint32_t(volume.vertices.size()));
        volume.vertices.insert(volume.vertices.end(), part.vertices.begin(), part.vertices.end());
        volume.silhouette.insert(volume.silhouette.end(), part.silhouette.begin(), part.silhouette.end());
    }
    auto append = [&](std::vector<glm::uvec3> InstanceVolume::*list) {
        size_t count = 0;
        for (size_t i = 0; i < parts.size(); ++i) {
            for (const glm::uvec3& t : parts[i].*list) volume.triangles.push_back(t + vertexBase[i]);
            count += (parts[i].*list).size();
        }
        return count;
    };
    volume.sideCount = append(&InstanceVolume::sides);
    volume.lightCapCount = append(&InstanceVolume::lightCaps);
    volume.darkCapCount = append(&InstanceVolume::darkCaps);
    return volume;
}

}  // namespace

ShadowVolume extrudeShadowVolume(const Scene& scene, const WorldGeometry& world,
                                 const std::vector<EdgeAdjacency>& adjacency, const glm::dvec4& light,
                                 bool withCaps, const std::vector<uint8_t>& cutOutCasts) {
    const std::vector<InstanceRange> ranges = instanceRanges(scene);
    if (!ranges.empty() &&
        ranges.back().firstTriangle + ranges.back().triangleCount != world.triangles.size()) {
        throw std::invalid_argument("extrudeShadowVolume: world geometry is not flatten(scene)");
    }
    std::vector<InstanceVolume> parts(ranges.size());
    tbb::parallel_for(size_t(0), ranges.size(), [&](size_t i) {
        const InstanceRange& r = ranges[i];
        // An instance has one material, so its first triangle says whether it is a cut-out.
        const int32_t cutOut = r.triangleCount == 0 || world.triangleCutOut.empty() ? -1 : world.triangleCutOut[r.firstTriangle];
        if (cutOut >= 0 && !cutOutCasts.empty() && !cutOutCasts[size_t(cutOut)]) return;
        parts[i] = extrudeInstance(world, scene.meshes[r.mesh], r, adjacency[r.mesh], light, withCaps);
    });
    return concatenate(parts);
}

}  // namespace shadowlab
