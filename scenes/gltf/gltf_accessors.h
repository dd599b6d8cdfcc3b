// Stage 2 of the glTF reader: an accessor's elements (glTF 2.0, section 3.6), each read
// only after its accessor, buffer view and buffer are found to hold them: every byte range
// is checked in 64-bit arithmetic before a value is read, and every count against the
// scene's limits (scenes/scene_limits.h) before anything of that size is allocated.
// tinygltf 2.7.0 parses these fields but checks none of the ranges.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/gltf/gltf_document.h"

namespace shadowlab {

// A vertex attribute of float vectors (POSITION, NORMAL): `field` names it in errors
// ("meshes[0].primitives[1].attributes.NORMAL"). Every value must be finite.
std::vector<glm::vec3> readVec3Accessor(const GltfDocument& document, int accessor, const std::string& field);

// TEXCOORD_0: float, or unsigned byte or short normalised to [0, 1] (section 3.7.2.1).
std::vector<glm::vec2> readTexcoordAccessor(const GltfDocument& document, int accessor, const std::string& field);

// Indices: unsigned byte, short or int scalars, each less than vertexCount.
std::vector<uint32_t> readIndexAccessor(const GltfDocument& document, int accessor, uint64_t vertexCount,
                                        const std::string& field);

// The element count an accessor declares, after the index is checked.
uint64_t accessorCount(const GltfDocument& document, int accessor, const std::string& field);

}  // namespace shadowlab
