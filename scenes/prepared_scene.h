// A scene made ready for a run of frames: flattened to world space once, and the data that
// some techniques need about its meshes (edge adjacency, for silhouettes) built once, on
// first use, as an engine builds them at load time. The caller owns it and passes it to
// every frame (frame/render.h); nothing about a scene is kept anywhere else, so two scenes,
// or an edited copy of one, can never share stale data.
#pragma once

#include <mutex>
#include <optional>
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

private:
    Scene scene_;
    WorldGeometry world_;
    mutable std::once_flag adjacencyBuilt_;
    mutable std::vector<EdgeAdjacency> adjacency_;
};

}  // namespace shadowlab
