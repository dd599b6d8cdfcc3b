// Stage 4 of the glTF reader: the node hierarchy of the file's scene (glTF 2.0, section
// 3.5): each node's local transform (its matrix, or T * R * S from translation, rotation
// and scale) composed with its parents' into a world transform, in double, rounded once.
// The nodes must form trees (section 3.5.1: a node has at most one parent, no cycles):
// a node reached twice is refused, naming it, before any transform is composed.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scenes/gltf/gltf_document.h"

namespace shadowlab {

struct PlacedNode {
    size_t node = 0;              // index into the file's nodes
    glm::dmat4 worldFromNode{1.0};
};

// Every node of the file's scene (`scene`, or the first when it names none) in depth-first
// order, parents before children and children in the order listed.
std::vector<PlacedNode> placeNodes(const GltfDocument& document);

// A node's own transform (section 3.5.2).
glm::dmat4 localTransform(const GltfDocument& document, size_t node);

}  // namespace shadowlab
