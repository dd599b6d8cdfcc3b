// glTF files written by tests: a document built in JSON with its one buffer, written as a
// .gltf with the buffer as a data URI (or beside it as a .bin), or as a .glb.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace shadowlab::test {

inline std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t b0 = uint8_t(bytes[i]), b1 = i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0,
                       b2 = i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0;
        const uint32_t n = b0 << 16 | b1 << 8 | b2;
        out += digits[n >> 18 & 63];
        out += digits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

struct GltfFile {
    nlohmann::json json = {{"asset", {{"version", "2.0"}}}, {"scenes", {{{"nodes", nlohmann::json::array()}}}},
                           {"scene", 0}};
    std::string bin;

    // The bytes as a buffer view and an accessor of `count` elements; the accessor's index.
    int accessor(const void* data, size_t bytes, int componentType, const char* type, size_t count) {
        while (bin.size() % 4) bin += '\0';
        const size_t offset = bin.size();
        bin.append(static_cast<const char*>(data), bytes);
        json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        json["accessors"].push_back({{"bufferView", json["bufferViews"].size() - 1}, {"componentType", componentType},
                                     {"type", type}, {"count", count}});
        return int(json["accessors"].size()) - 1;
    }
    int vec3s(const std::vector<glm::vec3>& v) { return accessor(v.data(), v.size() * 12, 5126, "VEC3", v.size()); }
    int vec2s(const std::vector<glm::vec2>& v) { return accessor(v.data(), v.size() * 8, 5126, "VEC2", v.size()); }
    int indices(const std::vector<uint32_t>& v) { return accessor(v.data(), v.size() * 4, 5125, "SCALAR", v.size()); }

    // A mesh of one primitive; its index.
    int mesh(const nlohmann::json& primitive) {
        json["meshes"].push_back({{"primitives", {primitive}}});
        return int(json["meshes"].size()) - 1;
    }
    // A node; a root of the scene unless `root` is false. Its index.
    int node(const nlohmann::json& node, bool root = true) {
        json["nodes"].push_back(node);
        const int index = int(json["nodes"].size()) - 1;
        if (root) json["scenes"][0]["nodes"].push_back(index);
        return index;
    }

    // The .gltf text, its buffer a data URI.
    std::string gltf() const {
        nlohmann::json j = json;
        j["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
        return j.dump();
    }
    // The .gltf text naming its buffer `uri`, beside it.
    std::string gltfWithExternalBuffer(const std::string& uri) const {
        nlohmann::json j = json;
        j["buffers"] = {{{"byteLength", bin.size()}, {"uri", uri}}};
        return j.dump();
    }
    // The .glb bytes (glTF 2.0, section 4.4).
    std::string glb() const {
        nlohmann::json j = json;
        j["buffers"] = {{{"byteLength", bin.size()}}};
        std::string text = j.dump();
        while (text.size() % 4) text += ' ';
        std::string data = bin;
        while (data.size() % 4) data += '\0';
        const auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
        return "glTF" + u32(2) + u32(uint32_t(12 + 8 + text.size() + 8 + data.size())) + u32(uint32_t(text.size())) +
               "JSON" + text + u32(uint32_t(data.size())) + std::string("BIN\0", 4) + data;
    }
};

}  // namespace shadowlab::test
