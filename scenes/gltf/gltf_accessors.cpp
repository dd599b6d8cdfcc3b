#include "scenes/gltf/gltf_accessors.h"

#include <cmath>
#include <cstring>

#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

std::string accessorField(int index) { return "accessors[" + std::to_string(index) + "]"; }

const tinygltf::Accessor& findAccessor(const GltfDocument& document, int index, const std::string& field) {
    if (index < 0 || size_t(index) >= document.model.accessors.size())
        document.fail(field, "names accessor " + std::to_string(index) + ", but the file has " +
                                 std::to_string(document.model.accessors.size()));
    return document.model.accessors[size_t(index)];
}

// Where an accessor's elements are: a base pointer and a stride, after checking that the
// last element ends inside its buffer view and the view inside its buffer. An accessor
// without a buffer view is all zeros (section 3.6.2.3): `bytes` is then null.
struct ElementBytes {
    const unsigned char* bytes = nullptr;
    uint64_t stride = 0;
};

ElementBytes locate(const GltfDocument& document, int index, int expectedType,
                    std::initializer_list<int> componentTypes) {
    const tinygltf::Accessor& accessor = document.model.accessors[size_t(index)];
    const std::string field = accessorField(index);
    if (accessor.sparse.isSparse) document.fail(field + ".sparse", "sparse accessors are not read here");
    if (accessor.type != expectedType)
        document.fail(field + ".type", "must be " + std::string(expectedType == TINYGLTF_TYPE_SCALAR ? "SCALAR"
                                                                : expectedType == TINYGLTF_TYPE_VEC2 ? "VEC2"
                                                                                                     : "VEC3") +
                                           " here");
    bool known = false;
    for (const int type : componentTypes) known = known || accessor.componentType == type;
    if (!known) document.fail(field + ".componentType", std::to_string(accessor.componentType) + " is not allowed here");
    // The largest accessor a scene can use: the indices of its most triangles.
    if (uint64_t(accessor.count) > 3 * kMaxSceneTriangles)
        document.fail(field + ".count", std::to_string(accessor.count) + " is more than a scene may hold");
    if (accessor.bufferView < 0) return {};
    const auto& views = document.model.bufferViews;
    if (size_t(accessor.bufferView) >= views.size())
        document.fail(field + ".bufferView", "names buffer view " + std::to_string(accessor.bufferView) +
                                                 ", but the file has " + std::to_string(views.size()));
    const tinygltf::BufferView& view = views[size_t(accessor.bufferView)];
    const std::string viewField = "bufferViews[" + std::to_string(accessor.bufferView) + "]";
    if (view.buffer < 0 || size_t(view.buffer) >= document.model.buffers.size())
        document.fail(viewField + ".buffer", "names buffer " + std::to_string(view.buffer) + ", but the file has " +
                                                 std::to_string(document.model.buffers.size()));
    const std::vector<unsigned char>& buffer = document.model.buffers[size_t(view.buffer)].data;
    if (uint64_t(view.byteOffset) + uint64_t(view.byteLength) > buffer.size())
        document.fail(viewField + ".byteLength", "offset " + std::to_string(view.byteOffset) + " + length " +
                                                     std::to_string(view.byteLength) + " runs past its buffer's " +
                                                     std::to_string(buffer.size()) + " bytes");
    const uint64_t elementSize = uint64_t(tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType))) *
                                 uint64_t(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)));
    const uint64_t stride = view.byteStride == 0 ? elementSize : uint64_t(view.byteStride);
    if (stride < elementSize)
        document.fail(viewField + ".byteStride", std::to_string(stride) + " is less than the element's " +
                                                     std::to_string(elementSize) + " bytes");
    if (accessor.count > 0 &&
        uint64_t(accessor.byteOffset) + stride * (uint64_t(accessor.count) - 1) + elementSize > uint64_t(view.byteLength))
        document.fail(field + ".count", std::to_string(accessor.count) + " elements from offset " +
                                            std::to_string(accessor.byteOffset) + " run past " + viewField + "'s " +
                                            std::to_string(view.byteLength) + " bytes");
    return {buffer.data() + view.byteOffset + accessor.byteOffset, stride};
}

template <typename T>
T loadComponent(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));   // glTF data is little-endian, as this machine
    return value;
}

// Component c of element k as float, integers normalised as section 3.11 says.
float floatComponent(const tinygltf::Accessor& accessor, const ElementBytes& at, size_t k, int c) {
    if (!at.bytes) return 0.0f;
    const unsigned char* p = at.bytes + k * at.stride;
    switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return float(p[c]) / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return float(loadComponent<uint16_t>(p + 2 * c)) / 65535.0f;
        default: return loadComponent<float>(p + 4 * c);
    }
}

}  // namespace

uint64_t accessorCount(const GltfDocument& document, int accessor, const std::string& field) {
    return uint64_t(findAccessor(document, accessor, field).count);
}

std::vector<glm::vec3> readVec3Accessor(const GltfDocument& document, int index, const std::string& field) {
    const tinygltf::Accessor& accessor = findAccessor(document, index, field);
    const ElementBytes at = locate(document, index, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    std::vector<glm::vec3> values(accessor.count);
    for (size_t k = 0; k < values.size(); ++k) {
        for (int c = 0; c < 3; ++c) values[k][c] = floatComponent(accessor, at, k, c);
        if (!std::isfinite(values[k].x) || !std::isfinite(values[k].y) || !std::isfinite(values[k].z))
            document.fail(accessorField(index), "element " + std::to_string(k) + " is not finite (" + field + ")");
    }
    return values;
}

std::vector<glm::vec2> readTexcoordAccessor(const GltfDocument& document, int index, const std::string& field) {
    const tinygltf::Accessor& accessor = findAccessor(document, index, field);
    const ElementBytes at = locate(document, index, TINYGLTF_TYPE_VEC2,
                                   {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
    if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized)
        document.fail(accessorField(index) + ".normalized", "integer texture coordinates must be normalized");
    std::vector<glm::vec2> values(accessor.count);
    for (size_t k = 0; k < values.size(); ++k) {
        for (int c = 0; c < 2; ++c) values[k][c] = floatComponent(accessor, at, k, c);
        if (!std::isfinite(values[k].x) || !std::isfinite(values[k].y))
            document.fail(accessorField(index), "element " + std::to_string(k) + " is not finite (" + field + ")");
    }
    return values;
}

std::vector<uint32_t> readIndexAccessor(const GltfDocument& document, int index, uint64_t vertexCount,
                                        const std::string& field) {
    const tinygltf::Accessor& accessor = findAccessor(document, index, field);
    const ElementBytes at = locate(document, index, TINYGLTF_TYPE_SCALAR,
                                   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
    std::vector<uint32_t> indices(accessor.count, 0u);
    for (size_t k = 0; at.bytes && k < indices.size(); ++k) {
        const unsigned char* p = at.bytes + k * at.stride;
        switch (accessor.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: indices[k] = p[0]; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: indices[k] = loadComponent<uint16_t>(p); break;
            default: indices[k] = loadComponent<uint32_t>(p); break;
        }
    }
    for (size_t k = 0; k < indices.size(); ++k) {
        if (indices[k] >= vertexCount)
            document.fail(accessorField(index), "index " + std::to_string(k) + " is " + std::to_string(indices[k]) +
                                                    ", past the primitive's " + std::to_string(vertexCount) +
                                                    " vertices (" + field + ")");
    }
    return indices;
}

}  // namespace shadowlab
