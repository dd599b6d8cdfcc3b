// The glTF reader (scenes/gltf_scene.h): the Khronos sample models load with the counts
// their files declare, node transforms place meshes where a hand computation does, strips
// and fans keep their winding, MASK materials become cut-outs with the same alpha test,
// cameras and lights are read in our units, and every malformed file is refused naming
// the file and the field.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "scenes/albedo_texture.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_file.h"
#include "scenes/scene_limits.h"
#include "tests/scenes/gltf_test_files.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;
using nlohmann::json;
using test::GltfFile;

namespace {

// One triangle, in the z = 0 plane facing +Z, as a mesh of `file`.
int triangleMesh(GltfFile& file, const json& extra = json::object()) {
    json primitive = {{"attributes", {{"POSITION", file.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}};
    primitive.update(extra);
    return file.mesh(primitive);
}

glm::vec3 faceNormal(const WorldGeometry& world, size_t t) {
    const glm::uvec3 tri = world.triangles[t];
    return glm::normalize(glm::cross(world.positions[tri[1]] - world.positions[tri[0]],
                                     world.positions[tri[2]] - world.positions[tri[0]]));
}

Scene loadWritten(const test::TempDir& dir, const std::string& name, const std::string& bytes) {
    return loadGltfScene(dir.write(name, bytes));
}

std::string refusal(const GltfFile& file, const std::string& name = "bad.gltf") {
    test::TempDir dir;
    const std::string path = dir.write(name, name.ends_with(".glb") ? file.glb() : file.gltf());
    return test::sceneErrorOf([&] { loadGltfScene(path); });
}

}  // namespace

TEST_CASE("a glTF node hierarchy places a mesh where T R S of each node, parent first, puts it") {
    GltfFile file;
    const int mesh = triangleMesh(file);
    const int child = file.node({{"mesh", mesh}, {"translation", {1, 0, 0}}}, false);
    // Parent: translate (1, 2, 3), turn 90 degrees about +Y (quaternion (0, sin 45, 0, cos 45)), scale 2.
    const double h = std::sqrt(0.5);
    file.node({{"children", {child}}, {"translation", {1, 2, 3}}, {"rotation", {0, h, 0, h}}, {"scale", {2, 2, 2}}});
    test::TempDir dir;
    const WorldGeometry world = flatten(loadWritten(dir, "tree.gltf", file.gltf()));
    REQUIRE(world.triangles.size() == 1);
    // By hand: p -> (p + (1, 0, 0)) * 2, turned about +Y (x -> -z, z -> x), + (1, 2, 3).
    const glm::vec3 expected[3] = {{1, 2, 1}, {1, 2, -1}, {1, 4, 1}};
    for (int c = 0; c < 3; ++c) {
        const glm::vec3 p = world.positions[world.triangles[0][c]];
        INFO("corner ", c, ": ", p.x, " ", p.y, " ", p.z);
        CHECK(glm::length(p - expected[c]) < 1e-5f);
    }
}

TEST_CASE("a glTF matrix node and a mirroring node: placed by the matrix, the mirrored triangle and its normals still face its front") {
    GltfFile file;
    const int positions = file.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normals = file.vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int mesh = file.mesh({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}});
    // Column-major: translation (0, 0, 5) in elements 12..14.
    file.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}});
    file.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}});
    test::TempDir dir;
    const Scene scene = loadWritten(dir, "mirror.gltf", file.gltf());
    const WorldGeometry world = flatten(scene);
    REQUIRE(world.triangles.size() == 2);
    CHECK(world.positions[world.triangles[0][0]] == glm::vec3(0, 0, 5));
    // The mirror turns the triangle to x <= 0; glTF says its front is still +Z (section 3.7.4).
    CHECK(glm::length(faceNormal(world, 0) - glm::vec3(0, 0, 1)) < 1e-6f);
    CHECK(glm::length(faceNormal(world, 1) - glm::vec3(0, 0, 1)) < 1e-6f);
    CHECK(scene.meshes.size() == 2);   // the primitive, and its mirrored winding
    for (int c = 0; c < 6; ++c) CHECK(world.cornerNormals[size_t(c)] == glm::vec3(0, 0, 1));
}

TEST_CASE("glTF triangle strips and fans become triangles with counter-clockwise fronts") {
    // A unit quad facing +Z: strip order 0 1 2 3 = (0,0) (1,0) (0,1) (1,1); fan around (0,0).
    for (const auto& modeAndOrder : {std::pair{5, std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}}},
                                     std::pair{6, std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}}}}) {
        const int mode = modeAndOrder.first;   // a plain variable: clang 14's INFO cannot capture a binding
        const std::vector<glm::vec3>& order = modeAndOrder.second;
        GltfFile file;
        file.node({{"mesh", file.mesh({{"mode", mode}, {"attributes", {{"POSITION", file.vec3s(order)}}}})}});
        test::TempDir dir;
        const WorldGeometry world = flatten(loadWritten(dir, "strip.gltf", file.gltf()));
        INFO("mode ", mode);
        REQUIRE(world.triangles.size() == 3);   // n - 2
        for (size_t t = 0; t < 3; ++t) CHECK(glm::length(faceNormal(world, t) - glm::vec3(0, 0, 1)) < 1e-6f);
    }
}

TEST_CASE("glTF POINTS and LINES primitives are left out and the triangles beside them kept") {
    GltfFile file;
    const int lines = file.vec3s({{0, 0, 0}, {1, 0, 0}});
    file.json["meshes"].push_back({{"primitives", {{{"mode", 1}, {"attributes", {{"POSITION", lines}}}},
                                                   {{"attributes", {{"POSITION", file.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}}}}});
    file.node({{"mesh", 0}});
    test::TempDir dir;
    CHECK(flatten(loadWritten(dir, "lines.gltf", file.gltf())).triangles.size() == 1);
}

TEST_CASE("a glTF MASK material is a cut-out: alpha = texel alpha x factor alpha, and a texel exactly at the cutoff stays") {
    // A 4 x 1 RGBA texture with alphas 127, 128, 129, 255; the cutoff is 128/255 as written.
    test::TempDir dir;
    const unsigned char rgba[16] = {9, 9, 9, 127, 9, 9, 9, 128, 9, 9, 9, 129, 9, 9, 9, 255};
    REQUIRE(stbi_write_png(dir.path("leaf.png").c_str(), 4, 1, 4, rgba, 16) != 0);
    GltfFile file;
    const double cutoff = 128.0 / 255.0;
    file.json["images"] = {{{"uri", "leaf.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    file.json["materials"] = {{{"alphaMode", "MASK"}, {"alphaCutoff", cutoff},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
    const int positions = file.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int uvs = file.vec2s({{0, 0}, {1, 0}, {0, 1}});
    file.node({{"mesh", file.mesh({{"material", 0}, {"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}})}});
    const Scene scene = loadWritten(dir, "leaf.gltf", file.gltf());
    REQUIRE(scene.materials.size() == 1);
    const Material& material = scene.materials[0];
    CHECK(material.albedo == glm::vec3(0.5f, 0.25f, 1.0f));
    REQUIRE(material.cutOut());
    CHECK(material.alphaCutoff == float(cutoff));
    const AlphaTexture& texture = scene.alphaTextures[size_t(material.alphaTexture)];
    REQUIRE(texture.alpha.size() == 4);
    for (int k = 0; k < 4; ++k) CHECK(texture.alpha[size_t(k)] == float(rgba[4 * k + 3]) / 255.0f * 1.0f);
    // Our test cuts where alpha < cutoff (scene.h), glTF's where alpha < alphaCutoff: the
    // texel at 128 stays, 127 is a hole, bit for bit the same decision.
    // Its colour is the albedo texture, each texel sRGB 9 decoded (9/255 / 12.92).
    REQUIRE(material.textured());
    CHECK(scene.albedoTextures[size_t(material.albedoTexture)].albedo == std::vector<glm::vec3>(4, glm::vec3(float(9.0 / 255.0 / 12.92))));
    CHECK(texture.alpha[0] < material.alphaCutoff);
    CHECK_FALSE(texture.alpha[1] < material.alphaCutoff);
    // glTF's v runs down from the image's top; ours up from its bottom.
    const WorldGeometry world = flatten(scene);
    CHECK(world.cornerUvs[0] == glm::vec2(0, 1));
    CHECK(world.cornerUvs[2] == glm::vec2(0, 0));
    // Without a sampler, both textures repeat (section 3.8.4); a sampler's modes are read per
    // axis, and a mode or a sampler index the file cannot mean is refused by name.
    CHECK(texture.wrap.u == TextureWrap::Repeat);
    CHECK(texture.wrap.v == TextureWrap::Repeat);
    file.json["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9729}}};
    file.json["textures"][0]["sampler"] = 0;
    const Scene sampled = loadWritten(dir, "sampled.gltf", file.gltf());
    for (const UvWrap wrap : {sampled.alphaTextures[0].wrap, sampled.albedoTextures[0].wrap}) {
        CHECK(wrap.u == TextureWrap::ClampToEdge);
        CHECK(wrap.v == TextureWrap::MirroredRepeat);
    }
    file.json["samplers"][0]["wrapT"] = 10496;
    test::checkMessage(test::sceneErrorOf([&] { loadWritten(dir, "bad.gltf", file.gltf()); }),
                       {"bad.gltf", "samplers[0].wrapT", "got 10496"});
    file.json["textures"][0]["sampler"] = 1;
    test::checkMessage(test::sceneErrorOf([&] { loadWritten(dir, "bad.gltf", file.gltf()); }),
                       {"bad.gltf", "textures[0].sampler", "names sampler 1"});
}

TEST_CASE("sRGB texels decode to linear albedo by IEC 61966-2-1's two pieces") {
    for (int c = 0; c < 256; ++c) {
        const double x = c / 255.0;
        const double expected = x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
        CHECK(double(srgbToLinear(uint8_t(c))) == doctest::Approx(expected).epsilon(1e-6));
    }
    CHECK(srgbToLinear(0) == 0.0f);
    CHECK(srgbToLinear(255) == 1.0f);
}

TEST_CASE("an OPAQUE glTF material's base colour texture is its albedo texture, and without TEXCOORD_0 it is refused") {
    test::TempDir dir;
    const unsigned char rgb[6] = {0, 128, 255, 64, 32, 16};
    REQUIRE(stbi_write_png(dir.path("colours.png").c_str(), 2, 1, 3, rgb, 6) != 0);
    GltfFile file;
    file.json["images"] = {{{"uri", "colours.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    file.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
    const int positions = file.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    GltfFile withUvs = file;
    const int uvs = withUvs.vec2s({{0, 0}, {1, 0}, {0, 1}});
    withUvs.node({{"mesh", withUvs.mesh({{"material", 0}, {"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}})}});
    const Scene scene = loadWritten(dir, "colours.gltf", withUvs.gltf());
    REQUIRE(scene.materials.size() == 1);
    const Material& material = scene.materials[0];
    CHECK(material.albedo == glm::vec3(0.5f, 0.25f, 1.0f));   // the factor; the texture multiplies it where it is read
    CHECK_FALSE(material.cutOut());
    REQUIRE(material.textured());
    const AlbedoTexture& texture = scene.albedoTextures[size_t(material.albedoTexture)];
    CHECK(texture.width == 2);
    CHECK(texture.height == 1);
    CHECK(texture.albedo == std::vector<glm::vec3>{{srgbToLinear(0), srgbToLinear(128), srgbToLinear(255)},
                                                   {srgbToLinear(64), srgbToLinear(32), srgbToLinear(16)}});
    file.node({{"mesh", file.mesh({{"material", 0}, {"attributes", {{"POSITION", positions}}}})}});
    const std::string path = dir.write("bare.gltf", file.gltf());
    test::checkMessage(test::sceneErrorOf([&] { loadScene(path, ""); }),
                       {"bare.gltf", "meshes[0].primitives[0].attributes", "its material's base colour texture needs TEXCOORD_0"});
}

TEST_CASE("glTF BLEND is translucency (opacity = the factor's alpha) and MASK without a texture is all or nothing") {
    GltfFile file;
    file.json["materials"] = {{{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.25}}}}},
                              {{"alphaMode", "MASK"}, {"alphaCutoff", 0.5}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.4}}}}},
                              {{"alphaMode", "MASK"}, {"alphaCutoff", 0.5}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.6}}}}}};
    for (int m = 0; m < 3; ++m) file.node({{"mesh", triangleMesh(file, {{"material", m}})}});
    test::TempDir dir;
    const Scene scene = loadWritten(dir, "blend.gltf", file.gltf());
    REQUIRE(scene.instances.size() == 2);   // the MASK below its cutoff draws nothing
    CHECK(scene.materials[scene.instances[0].material].opacity == 0.25f);
    CHECK(scene.materials[scene.instances[1].material].opacity == 1.0f);
    CHECK_FALSE(scene.materials[scene.instances[1].material].cutOut());
}

TEST_CASE("a glTF perspective camera: yfov, aspect, near, far and its node's place, and without one the scene is framed") {
    GltfFile file;
    file.node({{"mesh", triangleMesh(file)}});
    const double h = std::sqrt(0.5);
    // Turned 90 degrees about +Y: looks along -X.
    file.json["cameras"] = {{{"type", "perspective"},
                             {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.25}, {"zfar", 40}}}}};
    file.node({{"camera", 0}, {"translation", {3, 1, 0}}, {"rotation", {0, h, 0, h}}});
    test::TempDir dir;
    const Scene scene = loadWritten(dir, "camera.gltf", file.gltf());
    CHECK(scene.camera.fovyDeg == doctest::Approx(0.5 * 180.0 / M_PI));
    CHECK(scene.camera.width == 1200);
    CHECK(scene.camera.height == 800);
    CHECK(scene.camera.zNear == 0.25f);
    CHECK(scene.camera.zFar == 40.0f);
    CHECK(scene.camera.eye == glm::vec3(3, 1, 0));
    CHECK(glm::length(scene.camera.target - glm::vec3(2, 1, 0)) < 1e-6f);
    CHECK(scene.notes.size() == 1);   // the default sun
    file.json["nodes"].erase(1);
    file.json["scenes"][0]["nodes"] = {0};
    const Scene framed = loadWritten(dir, "framed.gltf", file.gltf());
    REQUIRE(framed.notes.size() == 2);
    test::checkMessage(framed.notes[0], {"framed.gltf", "has no camera"});
    // The triangle's box centre, (0.5, 0.5, 0), is what the default camera looks at.
    CHECK(framed.camera.target == glm::vec3(0.5f, 0.5f, 0.0f));
}

TEST_CASE("KHR_lights_punctual lights: type, node placement, direction along -Z, intensity 1:1, spot cone angles, range") {
    GltfFile file;
    file.node({{"mesh", triangleMesh(file)}});
    file.json["extensionsUsed"] = {"KHR_lights_punctual"};
    file.json["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "directional"}, {"intensity", 2}, {"color", {1, 0.5, 0.25}}},
        {{"type", "point"}, {"intensity", 30}, {"range", 12}},
        {{"type", "spot"}, {"intensity", 50}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}}};
    const double h = std::sqrt(0.5);
    // Turned -90 degrees about +X: -Z becomes -Y (pointing down).
    const json down = {0, 0, 0, 0};
    for (int k = 0; k < 3; ++k)
        file.node({{"translation", {k, 5, 0}}, {"rotation", {-h, 0, 0, h}},
                   {"extensions", {{"KHR_lights_punctual", {{"light", k}}}}}});
    test::TempDir dir;
    const Scene scene = loadWritten(dir, "lights.gltf", file.gltf());
    REQUIRE(scene.lights.size() == 3);
    CHECK(scene.notes.size() == 1);   // the camera only
    const Light& sun = scene.lights[0];
    CHECK(sun.type == LightType::Directional);
    CHECK(glm::length(sun.direction - glm::vec3(0, 1, 0)) < 1e-6f);   // ours points towards the light
    CHECK(sun.intensity == glm::vec3(2, 1, 0.5));
    const Light& point = scene.lights[1];
    CHECK(point.type == LightType::Point);
    CHECK(point.position == glm::vec3(1, 5, 0));
    CHECK(point.intensity == glm::vec3(30));
    CHECK(point.range == 12.0f);
    const Light& spot = scene.lights[2];
    CHECK(spot.type == LightType::Spot);
    CHECK(glm::length(spot.direction - glm::vec3(0, -1, 0)) < 1e-6f);
    CHECK(spot.coneAngleDeg == doctest::Approx(0.6 * 180.0 / M_PI));
    REQUIRE(spot.innerConeAngleDeg);
    CHECK(*spot.innerConeAngleDeg == doctest::Approx(0.2 * 180.0 / M_PI));
    CHECK(spot.range == 0.0f);
}

TEST_CASE("glTF files are scenes by extension: loadScene reads .gltf and .glb alike") {
    GltfFile file;
    file.node({{"mesh", triangleMesh(file)}});
    test::TempDir dir;
    const Scene text = loadScene(dir.write("a.gltf", file.gltf()), "");
    const Scene binary = loadScene(dir.write("a.glb", file.glb()), "");
    CHECK(flatten(text).positions == flatten(binary).positions);
    dir.write("external.bin", file.bin);
    CHECK(flatten(loadScene(dir.write("external.gltf", file.gltfWithExternalBuffer("external.bin")), "")).positions ==
          flatten(text).positions);
}

TEST_CASE("malformed glTF files are refused naming the file and the field") {
    const auto refused = [](const std::function<void(GltfFile&)>& breakIt, const std::vector<std::string>& pieces,
                            const std::string& name = "bad.gltf") {
        GltfFile file;
        file.node({{"mesh", triangleMesh(file)}});
        breakIt(file);
        test::checkMessage(refusal(file, name), pieces);
    };
    SUBCASE("an accessor past its buffer view") {
        refused([](GltfFile& f) { f.json["accessors"][0]["count"] = 4; }, {"bad.gltf", "accessors[0].count", "run past"});
    }
    SUBCASE("a buffer view past its buffer") {
        refused([](GltfFile& f) { f.json["bufferViews"][0]["byteLength"] = 400; }, {"bufferViews[0].byteLength", "runs past"});
    }
    SUBCASE("an index past the vertices") {
        refused([](GltfFile& f) { f.json["meshes"][0]["primitives"][0]["indices"] = f.indices({0, 1, 3}); },
                {"accessors[1]", "past the primitive's 3 vertices", "indices"});
    }
    SUBCASE("a huge count, bounded before anything is allocated") {
        refused([](GltfFile& f) { f.json["accessors"][0]["count"] = 4000000000ull; }, {"accessors[0].count", "more than a scene"});
    }
    SUBCASE("a node cycle") {
        refused([](GltfFile& f) { f.node({{"children", {2}}}, false), f.node({{"children", {1}}}); }, {"nodes[", "reached twice"});
    }
    SUBCASE("a node that is its own child") {
        refused([](GltfFile& f) { f.json["nodes"][0]["children"] = {0}; }, {"nodes[0]", "reached twice"});
    }
    SUBCASE("a required extension we do not read") {
        refused([](GltfFile& f) { f.json["extensionsRequired"] = {"KHR_draco_mesh_compression"}; },
                {"extensionsRequired[0]", "KHR_draco_mesh_compression", "not read"});
        refused([](GltfFile& f) { f.json["extensionsRequired"] = {"EXT_meshopt_compression"}; }, {"EXT_meshopt_compression"},
                "bad.glb");
    }
    SUBCASE("an orthographic camera") {
        refused([](GltfFile& f) {
            f.json["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}};
            f.node({{"camera", 0}});
        }, {"cameras[0].type", "orthographic", "only perspective"});
    }
    SUBCASE("a sparse accessor") {
        refused([](GltfFile& f) {
            f.json["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
                                                {"values", {{"bufferView", 0}}}};
        }, {"accessors[0].sparse", "not read"});
    }
    SUBCASE("a spot whose outer cone is a half-space") {
        refused([](GltfFile& f) {
            f.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "spot"}, {"spot", {{"outerConeAngle", 1.5707963267948966}}}}};
            f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        }, {"lights[0].spot.outerConeAngle"});
    }
    SUBCASE("more lights than a scene may hold (a frame keeps a V per light)") {
        refused([](GltfFile& f) {
            f.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}}};
            for (size_t k = 0; k <= kMaxSceneLights; ++k) f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        }, {"bad.gltf", "KHR_lights_punctual", "more lights than a scene may hold (16)"});
    }
    SUBCASE("normals that are not unit vectors; positions that are not finite") {
        refused([](GltfFile& f) { f.json["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = f.vec3s({{0, 0, 1}, {0, 0, 2}, {0, 0, 1}}); },
                {"attributes.NORMAL", "normal 1 has length 2"});
        refused([](GltfFile& f) { f.vec3s({{0, 0, 0}, {INFINITY, 0, 0}, {0, 1, 0}}), f.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 1; },
                {"accessors[1]", "element 1 is not finite", "POSITION"});
    }
}

TEST_CASE("glTF files' outside references are refused naming the file: URIs that leave the folder or name a folder, images we do not read") {
    test::TempDir dir;
    GltfFile file;
    file.node({{"mesh", triangleMesh(file)}});
    std::filesystem::create_directories(dir.path("sub"));
    for (const auto& [uri, pieces] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"../outside.bin", {"uri \"../outside.bin\"", "inside the glTF file's folder"}},
             {"/etc/passwd", {"uri \"/etc/passwd\"", "inside"}},
             {"sub", {"uri \"sub\"", "directory"}},
             {"missing.bin", {"uri \"missing.bin\"", "missing.bin"}}}) {
        const std::string path = dir.write("refers.gltf", file.gltfWithExternalBuffer(uri));
        test::checkMessage(test::sceneErrorOf([&] { loadGltfScene(path); }), {"refers.gltf", pieces[0], pieces[1]});
    }
    // A BMP named as a texture: refused by our image reader, naming the image.
    dir.write("leaf.bmp", "BM" + std::string(60, '\0'));
    file.json["images"] = {{{"uri", "leaf.bmp"}}};
    const std::string path = dir.write("bmp.gltf", file.gltf());
    test::checkMessage(test::sceneErrorOf([&] { loadGltfScene(path); }), {"bmp.gltf: images[0]", "BMP"});
}

TEST_CASE("a .glb whose chunk lengths lie is refused naming the length") {
    GltfFile file;
    file.node({{"mesh", triangleMesh(file)}});
    const std::string good = file.glb();
    test::TempDir dir;
    const auto refusedWith = [&](std::string bytes, size_t offset, uint32_t value, const std::string& field) {
        std::memcpy(bytes.data() + offset, &value, 4);
        const std::string path = dir.write("lie.glb", bytes);
        test::checkMessage(test::sceneErrorOf([&] { loadGltfScene(path); }), {"lie.glb", field});
    };
    uint32_t jsonLength;
    std::memcpy(&jsonLength, good.data() + 12, 4);
    refusedWith(good, 8, uint32_t(good.size() + 4), "header.length");
    refusedWith(good, 12, uint32_t(good.size()), "chunks[0].length");
    refusedWith(good, 20 + jsonLength, uint32_t(good.size()), "chunks[1].length");
    refusedWith(good, 4, 1, "header.version");
    test::checkMessage(test::sceneErrorOf([&] { loadGltfScene(dir.write("short.glb", good.substr(0, 16))); }), {"short.glb", "header"});
}

#ifdef SHADOWLAB_GLTF_SAMPLES
namespace {

const std::string kSamples = SHADOWLAB_GLTF_SAMPLES;

json documentOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!bytes.starts_with("glTF")) return json::parse(bytes);
    uint32_t length;
    std::memcpy(&length, bytes.data() + 12, 4);
    return json::parse(bytes.substr(20, length));
}

// What the file declares, counted from its JSON alone: per node of the scene that has a
// mesh, per primitive of a triangle mode, its triangles from the accessors' counts.
struct Declared {
    size_t instances = 0, triangles = 0, vertices = 0;
    std::set<int> materials;
};

void countNode(const json& doc, int node, Declared& declared) {
    const json& n = doc["nodes"][size_t(node)];
    if (n.contains("mesh")) {
        for (const json& p : doc["meshes"][size_t(n["mesh"].get<int>())]["primitives"]) {
            const int mode = p.value("mode", 4);
            const size_t positions = doc["accessors"][size_t(p["attributes"]["POSITION"].get<int>())]["count"];
            const size_t corners = p.contains("indices") ? doc["accessors"][size_t(p["indices"].get<int>())]["count"].get<size_t>() : positions;
            if (mode < 4) continue;
            declared.triangles += mode == 4 ? corners / 3 : corners - 2;
            declared.vertices += positions;
            declared.instances += 1;
            declared.materials.insert(p.value("material", -1));
        }
    }
    for (const json& child : n.value("children", json::array())) countNode(doc, child.get<int>(), declared);
}

}  // namespace

TEST_CASE("the Khronos sample models load with the triangles, vertices, instances and materials their files declare") {
    for (const std::string name :
         {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "BoxTextured-glTF/BoxTextured.gltf",
          "BoxTextured-glTF-Embedded/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb", "cameras/Cameras.gltf",
          "simple_skin/simple_skin.gltf", "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf",
          "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_12.gltf"}) {
        INFO(name);
        const std::string path = kSamples + "/" + name;
        const json doc = documentOf(path);
        Declared declared;
        for (const json& root : doc["scenes"][size_t(doc.value("scene", 0))]["nodes"]) countNode(doc, root.get<int>(), declared);
        const Scene scene = loadScene(path, "");
        const WorldGeometry world = flatten(scene);
        CHECK(world.triangles.size() == declared.triangles);
        CHECK(world.positions.size() == declared.vertices);
        CHECK(scene.instances.size() == declared.instances);
        CHECK(scene.materials.size() == declared.materials.size());
    }
}

// What a file holds and we do not read is told by name and count (Scene::notes, which
// `render` prints): a skinned character stands in its static pose, a morphed cube in its
// base shape, and the user is told so.
TEST_CASE("glTF skins, animations and morph targets are ignored by name: the scene loads and its notes say what was not read") {
    const auto notRead = [](const Scene& scene) {
        std::string found;
        for (const std::string& note : scene.notes) {
            if (note.find("not read") != std::string::npos) found += note;
        }
        return found;
    };
    const Scene skinned = loadScene(kSamples + "/simple_skin/simple_skin.gltf", "");
    test::checkMessage(notRead(skinned), {"simple_skin.gltf: not read:", "1 skin(s)", "static pose", "1 animation(s)"});
    const Scene morphed = loadScene(kSamples + "/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", "");
    test::checkMessage(notRead(morphed), {"AnimatedMorphCube.gltf: not read:", "1 primitive(s) with morph targets", "1 animation(s)"});
    CHECK(notRead(morphed).find("skin") == std::string::npos);
    CHECK(notRead(loadScene(kSamples + "/BoxTextured-glTF-Binary/BoxTextured.glb", "")).empty());
}

TEST_CASE("the malformed Khronos samples are refused naming the file and the field") {
    for (const auto& [sample, pieces] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", {"accessors[", "not finite", "POSITION"}},
             {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", {"attributes.NORMAL", "not 1"}},
             {"IncorrectVertexArrays/Cube.gltf", {"meshes[1].primitives[0].attributes.POSITION", "whole triangles"}},
             {"IndexOutOfRange/IndexOutOfRange.gltf", {"accessors[0]", "past the primitive's 24 vertices"}},
             {"IndexOutOfRange/AllIndicesOutOfRange.gltf", {"accessors[0]", "past the primitive's"}},
             {"MissingBin/BoxTextured.gltf", {"uri \"BoxTextured0.bin\"", "No such file"}},
             {"RecursiveNodes/RecursiveNodes.gltf", {"nodes[0]", "reached twice"}},
             {"draco/2CylinderEngine.gltf", {"extensionsRequired[0]", "KHR_draco_mesh_compression"}},
             {"TestNoRootNode/NoScene.gltf", {"scenes", "no scene"}}}) {
        const std::string name = sample;   // a plain variable: clang 14's INFO cannot capture a binding
        INFO(name);
        const std::string path = kSamples + "/" + name;
        test::checkMessage(test::sceneErrorOf([&] { loadScene(path, ""); }), pieces);
        test::checkMessage(test::sceneErrorOf([&] { loadScene(path, ""); }), {name});
    }
}
#endif
