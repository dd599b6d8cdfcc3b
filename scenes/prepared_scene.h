// A scene made ready for a run of frames: flattened to world space once, and the data that
// some techniques need about its meshes (edge adjacency, for silhouettes) built once, on
// first use, as an engine builds them at load time. The caller owns it and passes it to
// every frame (frame/render.h); nothing about a scene is kept anywhere else, so two scenes,
// or an edited copy of one, can never share stale data. Between frames its instances may
// move (setInstanceTransforms): what derives from where they are is dropped and built
// again, what derives from the rest is kept.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <type_traits>
#include <typeindex>
#include <vector>

#include "scenes/edge_adjacency.h"
#include "scenes/scene.h"

namespace shadowlab {

// What a type kept by PreparedScene::derived is made from, which decides whether it
// outlives a move of instances (setInstanceTransforms).
enum class DependsOn {
    // Where the instances are: world positions or normals, bounds, a BVH, anything made
    // from world() or the instances' transforms. Dropped when an instance moves.
    WorldGeometry,
    // Only what moving leaves alone: meshes in object space, materials, textures, the
    // environment, which triangle is whose. Kept.
    FixedContent,
};

class PreparedScene {
public:
    explicit PreparedScene(Scene scene);
    PreparedScene(const PreparedScene&) = delete;
    PreparedScene& operator=(const PreparedScene&) = delete;

    const Scene& scene() const { return scene_; }
    const WorldGeometry& world() const { return world_; }

    // The camera and the lights may change from frame to frame (a fly-through, a moving
    // light): nothing prepared depends on them.
    void setCamera(const Camera& camera) { scene_.camera = camera; }
    void setLights(std::vector<Light> lights) { scene_.lights = std::move(lights); }

    // Moves instances between frames (a fly-through's moving object): each placement's
    // instance gets its worldFromObject, and the world positions and corner normals of those
    // whose transform changed are placed again in place, the same bits as flatten() of the
    // moved scene. If any changed, the geometry version goes up by one and every derived<T>
    // of DependsOn::WorldGeometry is dropped (references to it are left dangling, as
    // iterators are by a vector's growth), to be built again by its next call; placements
    // that change nothing change nothing. Meshes, materials and which instances exist stay
    // fixed: another of those is another PreparedScene. Not thread-safe: no frame may be
    // rendering. Throws std::invalid_argument, changing nothing, for an instance index out
    // of range or placed twice, a transform that is not affine (its last row 0 0 0 1) or a vertex that would
    // land outside the world (scene_limits.h). Returns how many instances moved.
    size_t setInstanceTransforms(std::span<const InstancePlacement> placements);
    // How many times instances have moved since the scene was prepared: a technique that
    // keeps state from frame to frame (a cache of shadow-map pages) compares it with the
    // version its state was made at to know that the geometry moved.
    uint64_t geometryVersion() const { return geometryVersion_; }

    // sceneEdgeAdjacency() of the scene, built on the first call (thread-safe). It is made
    // from the meshes in object space (edge_adjacency.h), so moving instances keeps it.
    const std::vector<EdgeAdjacency>& edgeAdjacency() const;
    // Builds the edge adjacency if no call has yet; returns its wall time (ms) to the one
    // call that built it, nothing to every other: the cost is reported once.
    std::optional<double> buildEdgeAdjacency() const;

    // What a family of techniques derives from the scene (its BVH, an environment map's
    // tables, say), made by `build()` on the first call for the type T and kept for every
    // later frame, as the edge adjacency is; so no family keeps a cache of its own. Every
    // such T says what it is made from, as `static constexpr DependsOn kDependsOn`: a type
    // that does not say is a compile error, so none outlives a move by omission. A type made
    // from another derived type depends on what that one does, at least. `builtMs`, if
    // given, gets the wall time of the build to the one call that made it, and nothing
    // otherwise. A build that throws keeps nothing, and the next call tries again.
    // Thread-safe: callers of one type wait for its one build; a build may derive other
    // types (a table from the map), never its own.
    template <class T, class Build>
    const T& derived(Build&& build, std::optional<double>* builtMs = nullptr) const {
        static_assert(std::is_same_v<std::remove_cv_t<decltype(T::kDependsOn)>, DependsOn>,
                      "a type kept by PreparedScene::derived says what it is made from: "
                      "static constexpr DependsOn kDependsOn = ...;");
        std::optional<double> ms;
        const void* data = derivedData(
            typeid(T), T::kDependsOn,
            [&]() -> std::shared_ptr<const void> { return std::make_shared<const T>(build()); }, ms);
        if (builtMs) *builtMs = ms;
        return *static_cast<const T*>(data);
    }

private:
    const void* derivedData(std::type_index type, DependsOn dependsOn,
                            const std::function<std::shared_ptr<const void>()>& build,
                            std::optional<double>& builtMs) const;

    Scene scene_;
    WorldGeometry world_;
    uint64_t geometryVersion_ = 0;
    mutable std::once_flag adjacencyBuilt_;
    mutable std::vector<EdgeAdjacency> adjacency_;
    struct Derived {
        DependsOn dependsOn = DependsOn::WorldGeometry;
        std::mutex building;   // held while this type's data is built
        std::shared_ptr<const void> data;
    };
    mutable std::mutex derivedMutex_;   // guards the map, never held during a build
    mutable std::map<std::type_index, std::shared_ptr<Derived>> derived_;
};

}  // namespace shadowlab
