#include "scenes/obj_reader.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>
#include <vector>

#include <tiny_obj_loader.h>

#include "scenes/float_range.h"
#include "scenes/read_file.h"
#include "scenes/scene_error.h"

namespace shadowlab {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// True for a statement "<keyword> ..." the way tinyobjloader recognises it.
bool isStatement(std::string_view line, std::string_view keyword) {
    return line.size() > keyword.size() && line.starts_with(keyword) && isBlank(line[keyword.size()]);
}

bool isFiniteFloat(std::string_view token) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && end == token.data() + token.size() && roundsToFiniteFloat(value);
}

// A "v" or "vn" line (what names it in errors) must hold three finite numbers, a "vt"
// line two (u, v; a w after them is not read).
void checkVectorLine(std::string_view line, std::string_view keyword, const char* what, size_t lineNumber,
                     const std::string& file) {
    std::istringstream words{std::string(line.substr(keyword.size()))};
    std::string token;
    const std::vector<const char*> axes = keyword == "vt" ? std::vector<const char*>{"u", "v"}
                                                           : std::vector<const char*>{"x", "y", "z"};
    for (const char* axis : axes) {
        if (!(words >> token))
            throw SceneError(file + ": line " + std::to_string(lineNumber) + ": " + what + " has no " + axis);
        if (!isFiniteFloat(token))
            throw SceneError(file + ": line " + std::to_string(lineNumber) + ": " + what + " " + axis + " \"" +
                             token + "\" is not a finite float");
    }
}

// tinyobjloader reads a coordinate it cannot parse ("nan", "1,5", a missing z) as 0
// without a word, and drops faces with fewer than 3 vertices with only a warning. Such a
// file would render plausibly and wrongly, so the text is checked first: every "v" and
// "vn" line must hold three finite numbers. Returns the number of "f" lines, so that any face
// tinyobjloader dropped can be noticed.
size_t checkObjText(const std::string& text, const std::string& file) {
    size_t faceLines = 0, lineNumber = 0;
    for (size_t pos = 0; pos < text.size(); ++lineNumber) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line = std::string_view(text).substr(pos, end - pos);
        pos = end + 1;
        while (!line.empty() && isBlank(line.front())) line.remove_prefix(1);
        if (isStatement(line, "v")) checkVectorLine(line, "v", "vertex", lineNumber + 1, file);
        if (isStatement(line, "vn")) checkVectorLine(line, "vn", "normal", lineNumber + 1, file);
        if (isStatement(line, "vt")) checkVectorLine(line, "vt", "texture coordinate", lineNumber + 1, file);
        faceLines += isStatement(line, "f");
    }
    return faceLines;
}

std::string trimmed(std::string text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    return text;
}

std::string faceProblem(size_t face, const char* what, int index, size_t count, const char* plural) {
    return "face " + std::to_string(face) + ": " + what + " index " + std::to_string(int64_t(index) + 1) +
           " (1-based) is out of range (the file has " + std::to_string(count) + " " + plural + ")";
}

// The file's "vn" normals and "vt" texture coordinates, empty where it has none.
struct CornerData {
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
};

// Fan-triangulates every face, checking its indices; faces are counted from 0 in file order.
// Each triangle's corners get their "v//vn" normal and "v/vt" texture coordinate where the
// file has any, 0 where the corner names none.
void addFaces(const tinyobj::shape_t& shape, size_t vertexCount, const CornerData& data, size_t& face, Mesh& mesh,
              const std::string& file) {
    const std::vector<glm::vec3>& normals = data.normals;
    size_t next = 0;
    for (const unsigned char cornerCount : shape.mesh.num_face_vertices) {
        const tinyobj::index_t* corners = &shape.mesh.indices[next];
        next += cornerCount;
        for (size_t c = 0; c < cornerCount; ++c) {
            const int index = corners[c].vertex_index;
            if (index < 0 || size_t(index) >= vertexCount)
                throw SceneError(file + ": " + faceProblem(face, "vertex", index, vertexCount, "vertices"));
            const int normal = corners[c].normal_index;
            if (normal >= 0 && size_t(normal) >= normals.size())
                throw SceneError(file + ": " + faceProblem(face, "normal", normal, normals.size(), "normals"));
            const int uv = corners[c].texcoord_index;
            if (uv >= 0 && size_t(uv) >= data.uvs.size())
                throw SceneError(file + ": " + faceProblem(face, "texture coordinate", uv, data.uvs.size(),
                                                           "texture coordinates"));
        }
        auto uvOf = [&](size_t c) {
            return corners[c].texcoord_index < 0 ? glm::vec2(0.0f) : data.uvs[size_t(corners[c].texcoord_index)];
        };
        auto normalOf = [&](size_t c) { return corners[c].normal_index < 0 ? glm::vec3(0.0f) : normals[corners[c].normal_index]; };
        for (size_t c = 1; c + 1 < cornerCount; ++c) {
            mesh.triangles.emplace_back(corners[0].vertex_index, corners[c].vertex_index, corners[c + 1].vertex_index);
            if (!normals.empty()) mesh.cornerNormals.insert(mesh.cornerNormals.end(), {normalOf(0), normalOf(c), normalOf(c + 1)});
            if (!data.uvs.empty()) mesh.cornerUvs.insert(mesh.cornerUvs.end(), {uvOf(0), uvOf(c), uvOf(c + 1)});
        }
        ++face;
    }
    // tinyobjloader stores corner counts as unsigned char, so a larger face leaves
    // indices over.
    if (next != shape.mesh.indices.size())
        throw SceneError(file + ": a face has more than 255 vertices, which tinyobjloader cannot represent");
}

}  // namespace

Mesh parseObj(const std::string& text, const std::string& path) {
    const size_t faceLines = checkObjText(text, path);

    // Parsing from a string skips "mtllib": materials come from the scene file.
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;   // fans below, the same rule as for PLY
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config)) throw SceneError(path + ": " + trimmed(reader.Error()));

    Mesh mesh;
    mesh.source = path;
    const std::vector<tinyobj::real_t>& xyz = reader.GetAttrib().vertices;
    for (size_t i = 0; i + 2 < xyz.size(); i += 3) mesh.positions.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    CornerData data;
    const std::vector<tinyobj::real_t>& nxyz = reader.GetAttrib().normals;
    for (size_t i = 0; i + 2 < nxyz.size(); i += 3) data.normals.emplace_back(nxyz[i], nxyz[i + 1], nxyz[i + 2]);
    const std::vector<tinyobj::real_t>& uv = reader.GetAttrib().texcoords;
    for (size_t i = 0; i + 1 < uv.size(); i += 2) data.uvs.emplace_back(uv[i], uv[i + 1]);
    size_t face = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) addFaces(shape, mesh.positions.size(), data, face, mesh, path);
    if (face != faceLines)
        throw SceneError(path + ": " + std::to_string(faceLines - face) + " face(s) with fewer than 3 vertices");
    // OBJ readers skip lines they do not know, so any file parses: one with nothing in it is
    // named here rather than reported later as a scene without triangles.
    if (mesh.positions.empty() && faceLines == 0) throw SceneError(path + ": holds no vertices and no faces (not an OBJ file?)");
    return mesh;
}

Mesh readObj(const std::string& path) { return parseObj(readWholeFile(path), path); }

}  // namespace shadowlab
