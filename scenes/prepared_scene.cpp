#include "scenes/prepared_scene.h"

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_access.hpp>
#include <tbb/task_arena.h>

#include "scenes/scene_file_parts.h"   // withinWorld
#include "scenes/shading_normals.h"

namespace shadowlab {
namespace {

template <class F>
double millisecondsOf(F&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PreparedScene::PreparedScene(Scene scene) : scene_(std::move(scene)), world_(flatten(scene_)) {}

std::optional<double> PreparedScene::buildEdgeAdjacency() const {
    std::optional<double> builtHere;
    std::call_once(adjacencyBuilt_, [&] {
        // Isolated: while this thread waits inside the parallel build, TBB must not hand it
        // another task that could ask this scene for its adjacency and wait on the same flag.
        builtHere = millisecondsOf([&] { tbb::this_task_arena::isolate([&] { adjacency_ = sceneEdgeAdjacency(scene_); }); });
    });
    return builtHere;
}

const void* PreparedScene::derivedData(std::type_index type, DependsOn dependsOn,
                                       const std::function<std::shared_ptr<const void>()>& build,
                                       std::optional<double>& builtMs) const {
    std::shared_ptr<Derived> entry;
    {
        const std::lock_guard lock(derivedMutex_);
        std::shared_ptr<Derived>& slot = derived_[type];
        if (!slot) {
            slot = std::make_shared<Derived>();
            slot->dependsOn = dependsOn;
        }
        entry = slot;
    }
    const std::lock_guard building(entry->building);
    if (!entry->data) {
        // Isolated for the reason buildEdgeAdjacency() gives: a build may run in parallel.
        builtMs = millisecondsOf([&] { tbb::this_task_arena::isolate([&] { entry->data = build(); }); });
    }
    return entry->data.get();
}

size_t PreparedScene::setInstanceTransforms(std::span<const InstancePlacement> placements) {
    // Every placement checked before anything changes.
    std::vector<const InstancePlacement*> moved;
    std::vector<bool> placed(scene_.instances.size(), false);
    for (const InstancePlacement& placement : placements) {
        if (placement.instance >= scene_.instances.size())
            throw std::invalid_argument("setInstanceTransforms: instance " + std::to_string(placement.instance) +
                                        " does not exist (the scene has " + std::to_string(scene_.instances.size()) +
                                        ")");
        if (placed[placement.instance])
            throw std::invalid_argument("setInstanceTransforms: instance " + std::to_string(placement.instance) +
                                        " is placed twice");
        placed[placement.instance] = true;
        if (glm::row(placement.worldFromObject, 3) != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f))
            throw std::invalid_argument("setInstanceTransforms: instance " + std::to_string(placement.instance) +
                                        "'s transform is not affine (its last row must be 0 0 0 1)");
        MeshInstance instance = scene_.instances[placement.instance];
        // Bit for bit: a -0 for a +0 is a move too, as flatten() would keep its sign.
        if (std::memcmp(&instance.worldFromObject, &placement.worldFromObject, sizeof(glm::mat4)) == 0) continue;
        instance.worldFromObject = placement.worldFromObject;
        for (const glm::vec3& p : scene_.meshes[instance.mesh].positions)
            if (!withinWorld(worldPosition(instance, p)))
                throw std::invalid_argument("setInstanceTransforms: instance " + std::to_string(placement.instance) +
                                            " would put a vertex outside the world");
        moved.push_back(&placement);
    }
    if (moved.empty()) return 0;
    const std::vector<InstanceRange> ranges = instanceRanges(scene_);
    std::map<uint32_t, std::vector<glm::vec3>> meshNormals;   // each moved mesh's once
    for (const InstancePlacement* placement : moved) {
        MeshInstance& instance = scene_.instances[placement->instance];
        instance.worldFromObject = placement->worldFromObject;
        const Mesh& mesh = scene_.meshes[instance.mesh];
        auto [normals, fresh] = meshNormals.try_emplace(instance.mesh);
        if (fresh) normals->second = cornerShadingNormals(mesh);
        placeInstance(instance, mesh, normals->second, ranges[placement->instance], world_);
    }
    ++geometryVersion_;
    const std::lock_guard lock(derivedMutex_);
    for (auto& [type, entry] : derived_)
        if (entry->dependsOn == DependsOn::WorldGeometry) entry->data.reset();
    return moved.size();
}

const std::vector<EdgeAdjacency>& PreparedScene::edgeAdjacency() const {
    buildEdgeAdjacency();
    return adjacency_;
}

}  // namespace shadowlab
