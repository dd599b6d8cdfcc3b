#include "scenes/prepared_scene.h"

#include <chrono>

#include <tbb/task_arena.h>

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

const std::vector<EdgeAdjacency>& PreparedScene::edgeAdjacency() const {
    buildEdgeAdjacency();
    return adjacency_;
}

}  // namespace shadowlab
