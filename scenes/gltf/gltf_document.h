// Stage 1 of the glTF reader (docs/scene-format.md, "glTF files"): the file read with
// tinygltf (Debian's libtinygltf-dev) into its document model, with the checks tinygltf
// 2.7.0 does not make: a .glb's chunk lengths, URIs kept inside the file's folder, images
// read by the project's own reader (scenes/image_file.h), required extensions we do not
// read refused. Every later stage reads the document through GltfDocument, whose fail()
// names the file and the field ("car.glb: accessors[3].count: ...").
#pragma once

#include <string>

#include <tiny_gltf.h>

namespace shadowlab {

struct GltfDocument {
    std::string path;
    tinygltf::Model model;

    [[noreturn]] void fail(const std::string& field, const std::string& problem) const;
};

// Reads `path` (.gltf or .glb, told by the file's first bytes). Throws SceneError naming
// the file and the field for anything it cannot read.
GltfDocument readGltfDocument(const std::string& path);

// The same for bytes already in memory (the fuzzer); `path` names the document in errors
// and its folder holds the external files.
GltfDocument parseGltfDocument(const std::string& bytes, const std::string& path);

}  // namespace shadowlab
