#include "scenes/caster_lod.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <meshoptimizer.h>

namespace shadowlab {
namespace {

struct SimplifiedMesh {
    Mesh mesh;
    double errorObjectUnits = 0.0;   // meshoptimizer's estimate, in the mesh's own units
};

SimplifiedMesh simplifyMesh(const Mesh& mesh, double ratio) {
    // Never fewer than a tetrahedron's 4 triangles: below that a closed mesh would flatten
    // into a two-sided triangle and then vanish, and its shadow with it.
    const size_t targetTriangles = std::max(size_t(std::llround(ratio * double(mesh.triangles.size()))),
                                            std::min<size_t>(mesh.triangles.size(), 4));
    if (targetTriangles >= mesh.triangles.size()) return {mesh, 0.0};
    const size_t indexCount = 3 * mesh.triangles.size();
    const unsigned* indices = &mesh.triangles[0].x;
    const float* positions = &mesh.positions[0].x;
    const size_t vertexCount = mesh.positions.size();
    // One index per distinct position, so that split vertices (a box's 24) are one vertex
    // to the simplifier and their seams are not taken for borders.
    std::vector<unsigned> welded(indexCount);
    meshopt_generateShadowIndexBuffer(welded.data(), indices, indexCount, positions, vertexCount, sizeof(glm::vec3),
                                      sizeof(glm::vec3));
    std::vector<unsigned> kept(indexCount);   // the simplifier may write up to the input's size
    float relativeError = 0.0f;
    // No error bound: the ratio alone says where to stop.
    kept.resize(meshopt_simplify(kept.data(), welded.data(), indexCount, positions, vertexCount, sizeof(glm::vec3),
                                 3 * targetTriangles, std::numeric_limits<float>::max(), meshopt_SimplifyLockBorder,
                                 &relativeError));

    SimplifiedMesh out;
    out.mesh.source = mesh.source + " (simplified)";
    out.mesh.positions.resize(vertexCount);
    // Keeps the vertices the kept triangles use, in the order they are first used.
    const size_t used = meshopt_optimizeVertexFetch(out.mesh.positions.data(), kept.data(), kept.size(), positions,
                                                    vertexCount, sizeof(glm::vec3));
    out.mesh.positions.resize(used);
    for (size_t i = 0; i < kept.size(); i += 3) out.mesh.triangles.push_back({kept[i], kept[i + 1], kept[i + 2]});
    out.errorObjectUnits = double(relativeError) * double(meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3)));
    return out;
}

// The largest factor by which an instance stretches a length.
double largestScale(const MeshInstance& instance) {
    double scale = 0.0;
    for (int axis = 0; axis < 3; ++axis) scale = std::max(scale, double(glm::length(glm::vec3(instance.worldFromObject[axis]))));
    return scale;
}

struct CasterLevels {
    // Each level's copy holds the instances where they were when it was made.
    static constexpr DependsOn kDependsOn = DependsOn::WorldGeometry;
    struct Level {
        explicit Level(SimplifiedScene s) : casters(std::move(s.scene)), instanceErrorM(std::move(s.instanceErrorM)) {}
        PreparedScene casters;
        std::vector<float> instanceErrorM;
    };
    struct Levels {
        std::mutex building;   // held while a level is looked up or built
        std::map<double, std::unique_ptr<const Level>> byRatio;
    };
    std::unique_ptr<Levels> levels = std::make_unique<Levels>();
};

void requireRatio(double ratio) {
    if (!(ratio > 0.0 && ratio <= 1.0))
        throw std::invalid_argument((std::ostringstream() << "caster level of detail: the triangle ratio must be in (0, 1], got "
                                     << ratio).str());
}

double largest(std::span<const float> errors) {
    return errors.empty() ? 0.0 : double(*std::max_element(errors.begin(), errors.end()));
}

}  // namespace

double SimplifiedScene::errorM() const { return largest(instanceErrorM); }
double CasterLevel::errorM() const { return largest(instanceErrorM); }

SimplifiedScene simplifyMeshes(const Scene& scene, double ratio) {
    requireRatio(ratio);
    SimplifiedScene out{scene, {}};
    std::vector<double> meshError(scene.meshes.size(), 0.0);
    // A cut-out's mesh is kept whole: the simplifier keeps positions only, and a card's shape
    // is in its texture, read at the texture coordinates, not in its two triangles.
    std::vector<bool> cutOut(scene.meshes.size(), false);
    for (const MeshInstance& instance : scene.instances) {
        if (instance.material < scene.materials.size() && scene.materials[instance.material].cutOut())
            cutOut[instance.mesh] = true;
    }
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        if (cutOut[m]) continue;
        SimplifiedMesh s = simplifyMesh(scene.meshes[m], ratio);
        out.scene.meshes[m] = std::move(s.mesh);
        meshError[m] = s.errorObjectUnits;
    }
    for (const MeshInstance& instance : scene.instances)
        out.instanceErrorM.push_back(float(meshError[instance.mesh] * largestScale(instance)));
    return out;
}

CasterLevel casterLevel(const PreparedScene& prepared, double ratio, std::optional<double>* builtMs) {
    requireRatio(ratio);
    if (builtMs) builtMs->reset();
    if (ratio == 1.0) return {prepared, {}};
    CasterLevels::Levels& levels = *prepared.derived<CasterLevels>([] { return CasterLevels{}; }).levels;
    const std::lock_guard lock(levels.building);
    std::unique_ptr<const CasterLevels::Level>& level = levels.byRatio[ratio];
    if (!level) {
        const auto start = std::chrono::steady_clock::now();
        level = std::make_unique<const CasterLevels::Level>(simplifyMeshes(prepared.scene(), ratio));
        if (builtMs) *builtMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    return {level->casters, level->instanceErrorM};
}

}  // namespace shadowlab
