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

const void* PreparedScene::derivedData(std::type_index type, const std::function<std::shared_ptr<const void>()>& build,
                                       std::optional<double>& builtMs) const {
    std::shared_ptr<Derived> entry;
    {
        const std::lock_guard lock(derivedMutex_);
        std::shared_ptr<Derived>& slot = derived_[type];
        if (!slot) slot = std::make_shared<Derived>();
        entry = slot;
    }
    const std::lock_guard building(entry->building);
    if (!entry->data) {
        // Isolated for the reason buildEdgeAdjacency() gives: a build may run in parallel.
        builtMs = millisecondsOf([&] { tbb::this_task_arena::isolate([&] { entry->data = build(); }); });
    }
    return entry->data.get();
}

const std::vector<EdgeAdjacency>& PreparedScene::edgeAdjacency() const {
    buildEdgeAdjacency();
    return adjacency_;
}

}  // namespace shadowlab
