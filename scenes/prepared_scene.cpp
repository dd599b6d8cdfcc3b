#include "scenes/prepared_scene.h"

#include <chrono>

namespace shadowlab {
namespace {

template <class F>
double millisecondsOf(F&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PreparedScene::PreparedScene(Scene scene) : scene_(std::move(scene)) {
    flattenMs_ = millisecondsOf([&] { world_ = flatten(scene_); });
}

const std::vector<EdgeAdjacency>& PreparedScene::edgeAdjacency() const {
    std::call_once(adjacencyBuilt_, [&] { adjacencyMs_ = millisecondsOf([&] { adjacency_ = sceneEdgeAdjacency(scene_); }); });
    return adjacency_;
}

std::vector<std::pair<std::string, double>> PreparedScene::preparationTimes() const {
    std::vector<std::pair<std::string, double>> times = {{"flatten_ms", flattenMs_}};
    if (adjacencyMs_ >= 0.0) times.emplace_back("edge_adjacency_ms", adjacencyMs_);
    return times;
}

}  // namespace shadowlab
