// A glTF scene renders to the same bytes as the same scene written as scene JSON with OBJ
// meshes and a PNG cut-out and albedo, and as scene JSON placing the glTF file as a model:
// the glTF reader maps nodes, UVs, MASK materials, base colour textures, the camera and a
// point light exactly as docs/scene-format.md ("glTF files") says. A base colour texture
// gives the albedo glTF 2.0's section 3.9.2 says.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shading/surface_albedo.h"
#include "tests/scenes/gltf_test_files.h"
#include "tests/scenes/scene_test_files.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using nlohmann::json;

namespace {

// A 20 m ground and, above it, a 2 m x 2 m card in the z = 0 plane cut out by a 4 x 4
// checker of alphas 0 and 255 with one texel at 128 (above the 0.5 cutoff), its colour a
// different grey-green per texel.
const std::vector<glm::vec3> kGround = {{-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}};
const std::vector<glm::vec3> kCard = {{-1, 0.5, 0}, {1, 0.5, 0}, {1, 2.5, 0}, {-1, 2.5, 0}};
const std::vector<glm::vec2> kCardUvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};   // glTF's: v down from the top
const std::vector<uint32_t> kQuad = {0, 1, 2, 0, 2, 3};
constexpr double kYfov = 0.8;

void writeLeaf(const test::TempDir& dir) {
    unsigned char rgba[64];
    for (int k = 0; k < 16; ++k) {
        rgba[4 * k] = uint8_t(40 + 12 * k), rgba[4 * k + 1] = 200, rgba[4 * k + 2] = uint8_t(220 - 9 * k);
        rgba[4 * k + 3] = ((k % 4 + k / 4) % 2) ? 255 : 0;
    }
    rgba[4 * 5 + 3] = 128;
    REQUIRE(stbi_write_png(dir.path("leaf.png").c_str(), 4, 4, 4, rgba, 16) != 0);
}

std::string gltfText() {
    test::GltfFile file;
    file.json["images"] = {{{"uri", "leaf.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    file.json["materials"] = {
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}}}},
        {{"alphaMode", "MASK"}, {"alphaCutoff", 0.5},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
    const int ground = file.mesh({{"material", 0}, {"indices", file.indices(kQuad)}, {"attributes", {{"POSITION", file.vec3s(kGround)}}}});
    const int card = file.mesh({{"material", 1}, {"indices", file.indices(kQuad)},
                                {"attributes", {{"POSITION", file.vec3s(kCard)}, {"TEXCOORD_0", file.vec2s(kCardUvs)}}}});
    file.node({{"mesh", ground}});
    file.node({{"mesh", card}});
    file.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", kYfov}, {"aspectRatio", 1.5}, {"znear", 0.1}, {"zfar", 100}}}}};
    file.node({{"camera", 0}, {"translation", {0, 2, 6}}});
    file.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 40}}};
    file.node({{"translation", {1, 5, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    return file.gltf();
}

// The scene JSON's camera and light, as the glTF file has them.
json cameraAndLights() {
    return {{"camera", {{"eye", {0, 2, 6}}, {"target", {0, 2, 5}}, {"fovy", kYfov * 180.0 / M_PI}, {"width", 1200},
                        {"height", 800}, {"near", 0.1}, {"far", 100}}},
            {"lights", {{{"type", "point"}, {"position", {1, 5, 3}}, {"power", 40}}}}};
}

std::string objText(const std::vector<glm::vec3>& positions, const std::vector<glm::vec2>& gltfUvs) {
    std::string text;
    for (const glm::vec3& p : positions) text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const glm::vec2& uv : gltfUvs) text += "vt " + std::to_string(uv.x) + " " + std::to_string(1.0f - uv.y) + "\n";
    const bool uvs = !gltfUvs.empty();
    for (size_t t = 0; t < kQuad.size(); t += 3) {
        text += "f";
        for (int c = 0; c < 3; ++c) {
            const std::string index = std::to_string(kQuad[t + size_t(c)] + 1);
            text += " " + index + (uvs ? "/" + index : "");
        }
        text += "\n";
    }
    return text;
}

std::string jsonWithObjText() {
    json scene = cameraAndLights();
    scene["meshes"] = {{{"name", "ground"}, {"file", "ground.obj"}}, {{"name", "card"}, {"file", "card.obj"}}};
    scene["materials"] = {{{"name", "ground"}, {"albedo", {0.8, 0.8, 0.8}}},
                          {{"name", "leaf"},
                           {"albedo", {0.8, 0.8, 0.8}},
                           {"albedo-texture", "leaf.png"},
                           {"alpha-texture", "leaf.png"},
                           {"alpha-cutoff", 0.5}}};
    scene["instances"] = {{{"mesh", "ground"}, {"material", "ground"}}, {{"mesh", "card"}, {"material", "leaf"}}};
    return scene.dump();
}

std::string jsonWithModelText() {
    json scene = cameraAndLights();
    scene["meshes"] = json::array();
    scene["materials"] = json::array();
    scene["instances"] = json::array();
    scene["models"] = {{{"name", "model"}, {"file", "scene.gltf"}}};
    return scene.dump();
}

Frame render(Scene scene) {
    SceneOverrides overrides;
    overrides.width = 96;
    overrides.height = 64;
    applyOverrides(scene, overrides);
    const PreparedScene prepared(std::move(scene));
    FrameSettings settings;
    return renderFrame(prepared, findTechnique("shadow-map"), settings);
}

}  // namespace

TEST_CASE("a glTF scene, the same scene as JSON with OBJ meshes, and JSON placing the glTF file render the same bytes") {
    test::TempDir dir;
    writeLeaf(dir);
    dir.write("ground.obj", objText(kGround, {}));
    dir.write("card.obj", objText(kCard, kCardUvs));
    const Frame gltf = render(loadScene(dir.write("scene.gltf", gltfText()), ""));
    const Frame objs = render(loadScene(dir.write("objs.json", jsonWithObjText()), ""));
    const Frame model = render(loadScene(dir.write("model.json", jsonWithModelText()), ""));
    // Something is cut out and shadowed: the card's holes let the ground be seen and lit.
    size_t shadowed = 0, lit = 0;
    for (size_t k = 0; k < gltf.shadow.visibility.size(); ++k)
        if (gltf.gbuffer.hit[k]) (gltf.shadow.visibility[k] == 0.0f ? shadowed : lit) += 1;
    CHECK(shadowed > 0);
    CHECK(lit > 0);
    CHECK(test::sameBytes(gltf.shadow.visibility, objs.shadow.visibility));
    CHECK(test::sameBytes(gltf.radiance, objs.radiance));
    CHECK(test::sameBytes(gltf.shadow.visibility, model.shadow.visibility));
    CHECK(test::sameBytes(gltf.radiance, model.radiance));
}

namespace {

// The sRGB decoding as IEC 61966-2-1 defines it, in double.
double srgbDecoded(int c) {
    const double x = c / 255.0;
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}

// A 2 m square facing +Z, its 2 x 2 texture's top row at y > 0 (glTF's v runs down the image).
std::string texturedPlaneText(const glm::dvec3& factor) {
    const std::vector<glm::vec3> plane = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const std::vector<glm::vec2> uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    test::GltfFile file;
    file.json["images"] = {{{"uri", "colours.png"}}};
    file.json["textures"] = {{{"source", 0}}};
    file.json["materials"] = {{{"pbrMetallicRoughness",
                                {{"baseColorFactor", {factor.x, factor.y, factor.z, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
    const int mesh = file.mesh({{"material", 0}, {"indices", file.indices(kQuad)},
                                {"attributes", {{"POSITION", file.vec3s(plane)}, {"TEXCOORD_0", file.vec2s(uvs)}}}});
    file.node({{"mesh", mesh}});
    file.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.0}, {"znear", 0.1}, {"zfar", 10}}}}};
    file.node({{"camera", 0}, {"translation", {0, 0, 3}}});
    // A directional light shines along its node's -Z: straight onto the plane.
    file.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}, {"intensity", 2}}};
    file.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    return file.gltf();
}

}  // namespace

TEST_CASE("a glTF base colour texture times its factor is the albedo each texel's part of a plane reflects") {
    test::TempDir dir;
    const unsigned char rgb[12] = {255, 0, 0, 30, 140, 250,    // top row: left, right
                                   128, 128, 128, 10, 200, 60};   // bottom row
    REQUIRE(stbi_write_png(dir.path("colours.png").c_str(), 2, 2, 3, rgb, 6) != 0);
    const glm::dvec3 factor(0.5, 0.75, 1.0);
    Scene scene = loadScene(dir.write("plane.gltf", texturedPlaneText(factor)), "");
    REQUIRE(scene.lights.size() == 1);
    REQUIRE(scene.lights[0].type == LightType::Directional);
    REQUIRE(scene.lights[0].direction == glm::vec3(0, 0, 1));   // towards the light: along the plane's normal
    REQUIRE(scene.environment.ambient == glm::vec3(0.0f));
    const glm::dvec3 E(scene.lights[0].intensity);
    SceneOverrides overrides;
    overrides.width = overrides.height = 48;
    applyOverrides(scene, overrides);
    const PreparedScene prepared(std::move(scene));
    const Frame frame = renderFrame(prepared, findTechnique("none"), FrameSettings{});
    // L = albedo / pi * E * cos, cos = 1, albedo = factor * decoded texel (glTF 2.0, 3.9.2),
    // at pixels inside each texel's quarter (clear of the seams, where either texel is right).
    int checked[4] = {0, 0, 0, 0};
    for (size_t k = 0; k < frame.gbuffer.pixelCount(); ++k) {
        if (!frame.gbuffer.hit[k]) continue;
        const glm::vec3 P = frame.gbuffer.position[k];
        if (std::abs(P.x) < 0.05f || std::abs(P.y) < 0.05f) continue;
        const int texel = (P.y > 0.0f ? 0 : 2) + (P.x > 0.0f ? 1 : 0);
        for (int c = 0; c < 3; ++c) {
            const double expected = factor[c] * srgbDecoded(rgb[3 * texel + c]) * E[c] / M_PI;
            CHECK(double(frame.radiance[k][c]) == doctest::Approx(expected).epsilon(1e-5));
        }
        ++checked[texel];
    }
    for (int texel = 0; texel < 4; ++texel) CHECK(checked[texel] > 100);
}

#ifdef SHADOWLAB_GLTF_SAMPLES
// Khronos' BoxTextured: u runs over [0, 6] on its faces with MIRRORED_REPEAT along s and
// CLAMP_TO_EDGE along t, so the Cesium logo shows forward and mirrored. Each pixel's albedo
// is its material's factor times the texel a hand computation in double finds (s mirrored,
// t clamped, glTF's t down from the image's top), clear of the texels' edges; and the logo
// is there: sky blue, grass green and white pixels all appear.
TEST_CASE("Khronos' BoxTextured shows its logo: every pixel's albedo is the texel its mirrored coordinates name") {
    Scene scene = loadScene(std::string(SHADOWLAB_GLTF_SAMPLES) + "/BoxTextured-glTF/BoxTextured.gltf", "");
    SceneOverrides overrides;
    overrides.width = overrides.height = 96;
    applyOverrides(scene, overrides);
    const PreparedScene prepared(std::move(scene));
    const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
    REQUIRE(prepared.scene().albedoTextures.size() == 1);
    const AlbedoTexture& texture = prepared.scene().albedoTextures[0];
    CHECK(texture.wrap.u == TextureWrap::MirroredRepeat);
    CHECK(texture.wrap.v == TextureWrap::ClampToEdge);
    const auto edgeClear = [](double c) { return std::abs(c - std::round(c)) > 1e-3; };
    int checked = 0, sky = 0, grass = 0, white = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const Material& material = prepared.scene().materials[g.material[k]];
        const double s = g.uv[k].x, t = 1.0 - double(g.uv[k].y);
        const double folded = std::fmod(s, 2.0) <= 1.0 ? std::fmod(s, 2.0) : 2.0 - std::fmod(s, 2.0);
        const double column = folded * texture.width, row = std::clamp(t, 0.0, 1.0) * texture.height;
        if (!edgeClear(column) || !edgeClear(row) || s < 0.0 || s > 6.0) continue;
        const size_t texel = size_t(std::min(int(row), texture.height - 1)) * size_t(texture.width) +
                             size_t(std::min(int(column), texture.width - 1));
        const glm::vec3 albedo = surfaceAlbedo(material, prepared.scene().albedoTextures, g, k);
        INFO("pixel " << k << " at s, t = " << s << ", " << t);
        CHECK(albedo == material.albedo * texture.albedo[texel]);
        ++checked;
        sky += albedo.b > 1.5f * albedo.r && albedo.b > albedo.g;
        grass += albedo.g > 1.5f * albedo.r && albedo.g > 1.5f * albedo.b;
        white += albedo.r > 0.5f && albedo.g > 0.5f && albedo.b > 0.5f;
    }
    CHECK(checked > 1000);
    CHECK(sky > 100);
    CHECK(grass > 100);
    CHECK(white > 20);
}
#endif
