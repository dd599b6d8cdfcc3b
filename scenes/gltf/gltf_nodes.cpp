#include "scenes/gltf/gltf_nodes.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace shadowlab {
namespace {

std::string nodeField(size_t node) { return "nodes[" + std::to_string(node) + "]"; }

bool finiteNumbers(const std::vector<double>& values) {
    for (const double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

size_t checkedNode(const GltfDocument& document, int index, const std::string& field) {
    if (index < 0 || size_t(index) >= document.model.nodes.size())
        document.fail(field, "names node " + std::to_string(index) + ", but the file has " +
                                 std::to_string(document.model.nodes.size()));
    return size_t(index);
}

}  // namespace

glm::dmat4 localTransform(const GltfDocument& document, size_t index) {
    const tinygltf::Node& node = document.model.nodes[index];
    const std::string field = nodeField(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16 || !finiteNumbers(node.matrix))
            document.fail(field + ".matrix", "must be 16 finite numbers");
        if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
            document.fail(field + ".matrix", "cannot be combined with translation, rotation or scale");
        glm::dmat4 m;
        for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = node.matrix[size_t(k)];   // column-major, as glTF stores it
        if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
            document.fail(field + ".matrix", "must be affine (last row 0 0 0 1)");
        return m;
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3 || !finiteNumbers(node.translation))
            document.fail(field + ".translation", "must be 3 finite numbers");
        m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4 || !finiteNumbers(node.rotation))
            document.fail(field + ".rotation", "must be 4 finite numbers (a quaternion x, y, z, w)");
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(std::abs(length - 1.0) <= 1e-3)) document.fail(field + ".rotation", "must be a unit quaternion");
        m = m * glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3 || !finiteNumbers(node.scale)) document.fail(field + ".scale", "must be 3 finite numbers");
        m = m * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0), glm::dvec4(0, node.scale[1], 0, 0),
                           glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
    }
    return m;
}

std::vector<PlacedNode> placeNodes(const GltfDocument& document) {
    const tinygltf::Model& model = document.model;
    if (model.scenes.empty()) document.fail("scenes", "the file has no scene to draw");
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(sceneIndex) >= model.scenes.size())
        document.fail("scene", "names scene " + std::to_string(sceneIndex) + ", but the file has " +
                                   std::to_string(model.scenes.size()));
    const tinygltf::Scene& scene = model.scenes[size_t(sceneIndex)];
    const std::string sceneField = "scenes[" + std::to_string(sceneIndex) + "].nodes";
    // An explicit stack, so that a chain of many nodes cannot overflow the call stack.
    std::vector<bool> reached(model.nodes.size(), false);
    std::vector<PlacedNode> placed;
    std::vector<PlacedNode> stack;
    for (size_t k = scene.nodes.size(); k-- > 0;)
        stack.push_back({checkedNode(document, scene.nodes[k], sceneField + "[" + std::to_string(k) + "]"), glm::dmat4(1.0)});
    while (!stack.empty()) {
        PlacedNode next = stack.back();
        stack.pop_back();
        if (reached[next.node])
            document.fail(nodeField(next.node), "is reached twice: the nodes form a cycle or a node has two parents");
        reached[next.node] = true;
        next.worldFromNode = next.worldFromNode * localTransform(document, next.node);
        placed.push_back(next);
        const std::vector<int>& children = model.nodes[next.node].children;
        for (size_t k = children.size(); k-- > 0;) {
            const std::string field = nodeField(next.node) + ".children[" + std::to_string(k) + "]";
            stack.push_back({checkedNode(document, children[k], field), next.worldFromNode});
        }
    }
    return placed;
}

}  // namespace shadowlab
