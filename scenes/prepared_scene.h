// A scene made ready for a run of frames: flattened to world space once, and the data that
// some techniques need about its meshes (edge adjacency, for silhouettes) built once, on
// first use, as an engine builds them at load time. The caller owns it and passes it to
// every frame (frame/render.h); nothing about a scene is kept anywhere else, so two scenes,
// or an edited copy of one, can never share stale data.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <typeindex>
#include <vector>

#include "scenes/edge_adjacency.h"
#include "scenes/scene.h"

namespace shadowlab {

class PreparedScene {
public:
    explicit PreparedScene(Scene scene);
    PreparedScene(const PreparedScene&) = delete;
    PreparedScene& operator=(const PreparedScene&) = delete;

    const Scene& scene() const { return scene_; }
    const WorldGeometry& world() const { return world_; }

    // The camera and the lights may change from frame to frame (a fly-through, a moving
    // light): nothing prepared depends on them. Meshes and instances are fixed; another
    // geometry is another PreparedScene.
    void setCamera(const Camera& camera) { scene_.camera = camera; }
    void setLights(std::vector<Light> lights) { scene_.lights = std::move(lights); }

    // sceneEdgeAdjacency() of the scene, built on the first call (thread-safe).
    const std::vector<EdgeAdjacency>& edgeAdjacency() const;
    // Builds the edge adjacency if no call has yet; returns its wall time (ms) to the one
    // call that built it, nothing to every other: the cost is reported once.
    std::optional<double> buildEdgeAdjacency() const;

    // What a family of techniques derives from the fixed parts of the scene (its geometry,
    // materials, environment: an environment map's tables, say), made by `build()` on the
    // first call for the type T and kept for every later frame, as the edge adjacency is;
    // so no family keeps a cache of its own. `builtMs`, if given, gets the wall time of the
    // build to the one call that made it, and nothing otherwise. A build that throws keeps
    // nothing, and the next call tries again. Thread-safe: callers of one type wait for its
    // one build; a build may derive other types (a table from the map), never its own.
    template <class T, class Build>
    const T& derived(Build&& build, std::optional<double>* builtMs = nullptr) const {
        std::optional<double> ms;
        const void* data = derivedData(
            typeid(T), [&]() -> std::shared_ptr<const void> { return std::make_shared<const T>(build()); }, ms);
        if (builtMs) *builtMs = ms;
        return *static_cast<const T*>(data);
    }

private:
    const void* derivedData(std::type_index type, const std::function<std::shared_ptr<const void>()>& build,
                            std::optional<double>& builtMs) const;

    Scene scene_;
    WorldGeometry world_;
    mutable std::once_flag adjacencyBuilt_;
    mutable std::vector<EdgeAdjacency> adjacency_;
    struct Derived {
        std::mutex building;   // held while this type's data is built
        std::shared_ptr<const void> data;
    };
    mutable std::mutex derivedMutex_;   // guards the map, never held during a build
    mutable std::map<std::type_index, std::shared_ptr<Derived>> derived_;
};

}  // namespace shadowlab
