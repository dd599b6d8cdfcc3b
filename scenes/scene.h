// The in-memory scene: what a scene file (docs/scene-format.md) or a built-in scene
// describes. Meshes are kept in object space with an instance transform; flatten()
// produces the world-space triangle list that the rasterizer, the G-buffer and the
// Embree reference all consume, so every technique sees exactly the same geometry.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/texture_wrap.h"

namespace shadowlab {

struct Mesh {
    std::string source;                 // file it came from, or "procedural:<kind>"
    std::vector<glm::vec3> positions;   // object space
    std::vector<glm::uvec3> triangles;  // counter-clockwise = front face
    // Shading normals given by the file, three per triangle in corner order (OBJ's "vn" are
    // per corner, PLY's nx, ny, nz per vertex), object space; empty when the file has none.
    // A zero vector marks a corner the file left without one. scenes/shading_normals.h
    // fills the gaps with angle-weighted vertex normals.
    std::vector<glm::vec3> cornerNormals;
    // Texture coordinates, three per triangle in corner order (OBJ's "vt"), for a material's
    // alpha and albedo textures; empty when the mesh has none. (0, 0) is the texture's
    // bottom-left corner, as in OBJ files.
    std::vector<glm::vec2> cornerUvs;
};

// An alpha texture (foliage cards): opacity per texel in [0, 1], row-major, row 0 at the
// top of the image, read from a PNG's alpha channel (scenes/alpha_texture.h).
struct AlphaTexture {
    std::string source;
    int width = 0, height = 0;
    std::vector<float> alpha;
    UvWrap wrap{};  // glTF's sampler; scene files' textures clamp
};

// An albedo texture (glTF's base colour texture): linear RGB reflectance per texel in
// [0, 1], row-major, row 0 at the top, decoded once at load from the file's sRGB 8-bit
// texels (scenes/albedo_texture.h).
struct AlbedoTexture {
    std::string source;
    int width = 0, height = 0;
    std::vector<glm::vec3> albedo;
    UvWrap wrap{};  // glTF's sampler; scene files' textures clamp
};

// Every model is a Lambert diffuse term plus, except for Lambert, a specular lobe
// (shading/shade.h, brdf()): Blinn-Phong and normalised Phong lobes of a shininess, or the
// GGX microfacet lobe of a roughness (Torrance-Sparrow).
enum class MaterialModel { Lambert, BlinnPhong, Phong, Ggx };

struct Material {
    std::string name;
    MaterialModel model = MaterialModel::Lambert;
    // Diffuse reflectance in [0,1]; with an albedo texture, the surface's albedo at a point is
    // this times the texture's texel there (glTF 2.0, section 3.9.2; shading/surface_albedo.h).
    glm::vec3 albedo{0.8f};
    glm::vec3 specular{0.0f};  // specular reflectance in [0,1]; GGX: Schlick's F0
    float shininess = 32.0f;   // Blinn-Phong and Phong exponent, > 0
    float roughness = 0.5f;    // GGX alpha, in (0, 1]
    // What passes through the surface (conventions.md, "Casters that are not opaque"): a
    // share `opacity` of the light is stopped and what is left is tinted by
    // `transmittance`, so the surface passes T = (1 - opacity) transmittance per channel.
    float opacity = 1.0f;
    glm::vec3 transmittance{1.0f};
    // A cut-out: the surface is a hole wherever the alpha texture at the mesh's UVs is
    // below alphaCutoff. Index into Scene::alphaTextures, -1 for none.
    int alphaTexture = -1;
    float alphaCutoff = 0.5f;
    // Index into Scene::albedoTextures, -1 for none.
    int albedoTexture = -1;

    bool translucent() const { return opacity < 1.0f; }
    bool cutOut() const { return alphaTexture >= 0; }
    bool textured() const { return albedoTexture >= 0; }
    glm::vec3 passed() const { return (1.0f - opacity) * transmittance; }
};

// A participating medium that only absorbs (a smoke puff): the extinction coefficient
// sigma (1/m) is constant inside each voxel of a grid over an axis-aligned box, so the
// optical depth along a ray is an exact sum over the voxels it crosses
// (shadows/volume_march.h), and the light passing through is exp(-optical depth).
struct DensityVolume {
    std::string name;
    glm::vec3 min{0.0f}, max{1.0f};     // world space, min < max
    glm::ivec3 resolution{1};           // voxels per axis
    std::vector<float> sigma;           // x fastest, then y, then z; >= 0
    float at(int x, int y, int z) const {
        return sigma[(size_t(z) * size_t(resolution.y) + size_t(y)) * size_t(resolution.x) + size_t(x)];
    }
};

struct MeshInstance {
    std::string name;
    uint32_t mesh = 0;                  // index into Scene::meshes
    uint32_t material = 0;              // index into Scene::materials
    glm::mat4 worldFromObject{1.0f};
};

enum class LightType { Point, Spot, Directional, Disk, Rectangle };

// conventions.md, "Lights". Intensity is radiant intensity (W/sr) for point and spot
// lights, irradiance (W/m^2) for directional lights and radiance (W/(m^2 sr)) for area
// lights; a colour times a scalar power in the scene file.
// A light cookie, or gobo map (RTR 4th ed., section 7.2, "light attenuation mask"): the
// fraction of a spot light's intensity sent through each texel, per channel in [0, 1],
// row-major, row 0 at the top, read from a grey or RGB PNG (scenes/light_cookie.h) and
// projected through the spot's cone (conventions.md, "Lights"; shading/lights.h).
struct LightCookie {
    std::string source;
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;
};

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};           // point, spot; centre of disk and rectangle
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot: axis it shines along; directional: towards the light;
                                        // disk: unit normal of the emitting side
    float coneAngleDeg = 30.0f;         // spot: half-angle of the cone
    // spot: where a smooth falloff towards the cone's edge begins (KHR_lights_punctual's
    // innerConeAngle, conventions.md "Lights"); none: a hard cone, full intensity to its edge.
    std::optional<float> innerConeAngleDeg = std::nullopt;
    // point, spot: the distance (m) beyond which no light arrives, with the extension's
    // smooth window towards it; 0: unbounded, the plain inverse square.
    float range = 0.0f;
    float radius = 0.0f;                // disk
    glm::vec3 halfEdgeU{0.0f}, halfEdgeV{0.0f};  // rectangle
    // directional: the sun seen as a disk of this angular diameter (degrees, in [0, 180);
    // UE5's "Source Angle", the real sun's about 0.53) around `direction`; 0: a point-like sun.
    // Only reference-soft reads it (conventions.md, "Lights"); every other technique and the
    // shading see the centre direction.
    float angularDiameterDeg = 0.0f;
    glm::vec3 intensity{1.0f};
    // spot: its cookie, null for none. Shared by the copies of the light, never changed.
    std::shared_ptr<const LightCookie> cookie = nullptr;
};

struct Camera {
    glm::vec3 eye{0.0f, 4.0f, 9.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovyDeg = 45.0f;
    int width = 1280, height = 800;
    float zNear = 0.1f, zFar = 100.0f;
    bool operator==(const Camera&) const = default;
};

struct Environment {
    glm::vec3 ambient{0.0f};            // constant ambient radiance added to every surface
    // A latitude-longitude map of distant radiance (conventions.md, "Lights"), read by
    // shading/environment/environment_file.h where it is used: its path, resolved against
    // the scene file's folder (empty: none), and its turn about +Y, right-handed.
    std::string map;
    float rotationDeg = 0.0f;
};

// A fly-through (docs/flythrough.md): the camera's eye and target, optionally the first
// light's position (or a directional light's direction towards it), and optionally the
// transforms of some instances, at keyframe times.
// An instance's transform at a keyframe: the translate, rotate (degrees about x, then y,
// then z) and scale of the scene file's instance entries (scenes/instance_transform.h).
struct InstancePose {
    glm::vec3 translate{0.0f}, rotateDeg{0.0f}, scale{1.0f};
};
struct PathKeyframe {
    double time = 0.0;
    glm::vec3 eye{0.0f}, target{0.0f};
    std::optional<glm::vec3> light;
    std::vector<InstancePose> poses;       // one per CameraPath::instances, in its order
};
// An instance a path moves. Its worldFromObject at a pose is
//   shift * translateRotateScale(pose) * fit
// as the scene file composes it (scenes/scene_instances.cpp): the pose replaces the
// transform the file gave, and the instance keeps its fit and its shift in a lattice.
struct PathInstance {
    uint32_t instance = 0;                 // index into Scene::instances
    std::optional<glm::vec3> shift;        // a "repeat" copy's offset in its lattice
    glm::mat4 fit{1.0f};
};
struct CameraPath {
    std::vector<PathKeyframe> keyframes;   // times strictly increasing; none: the scene has no path
    std::vector<PathInstance> instances;   // the instances every keyframe places; none: no instance moves
    int frames = 0;                        // frames to sample it at; 0: the command's default
};

// Where an instance goes (PreparedScene::setInstanceTransforms): a new worldFromObject,
// affine.
struct InstancePlacement {
    uint32_t instance = 0;                 // index into Scene::instances
    glm::mat4 worldFromObject{1.0f};
};

struct Scene {
    std::string name;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<MeshInstance> instances;
    std::vector<AlphaTexture> alphaTextures;
    std::vector<AlbedoTexture> albedoTextures;
    std::vector<DensityVolume> volumes;
    std::vector<Light> lights;
    Camera camera;
    Environment environment;
    CameraPath flythrough;
    // What the loader supplied that the file did not say (a glTF file's default camera or
    // sun) and what a glTF file holds that is not read (its skins, animations...), one line
    // each, for the program to tell the user.
    std::vector<std::string> notes;
};

// Every triangle of every instance in world space, in instance order, then mesh order.
struct WorldGeometry {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> triangleMaterial;   // per triangle, index into Scene::materials
    std::vector<uint32_t> triangleInstance;   // per triangle, index into Scene::instances
    // Smooth shading normals, three per triangle (corner c of triangle t at 3 t + c), world
    // space and unit length, or 0 at a corner of a degenerate triangle with no smooth
    // neighbour (scenes/shading_normals.h). Only shading reads them: shadow bias and the
    // references use the geometric normal of the triangle's plane.
    std::vector<glm::vec3> cornerNormals;
    // Texture coordinates, three per triangle like cornerNormals; empty when no material
    // reads a texture (cut-out or albedo), (0, 0) at the corners of a mesh without them.
    std::vector<glm::vec2> cornerUvs;
    // Cut-outs: per triangle the index into cutOuts of its material's alpha test, or -1;
    // empty when the scene has none. Each keeps a copy of its texture, so that whatever draws
    // the geometry (the camera pass, every depth map) tests alpha without the scene.
    struct CutOut {
        std::vector<float> alpha;   // row-major, row 0 at the top
        int width = 0, height = 0;
        float cutoff = 0.5f;
        UvWrap wrap{};
    };
    std::vector<int32_t> triangleCutOut;
    std::vector<CutOut> cutOuts;
};

// Whether anything in the scene lets light through: a translucent or cut-out material, or a
// density volume. Every technique but the references treats the scene's surfaces as opaque
// unless it says otherwise.
bool hasNonOpaqueCasters(const Scene& scene);

WorldGeometry flatten(const Scene& scene);

// Where an instance puts a vertex of its mesh, as flatten() computes it: plain float mat4 *
// vec4, so that anyone can reproduce the positions bit for bit; instance transforms are
// affine (the loader checks), so w stays 1.
inline glm::vec3 worldPosition(const MeshInstance& instance, const glm::vec3& p) {
    return glm::vec3(instance.worldFromObject * glm::vec4(p, 1.0f));
}

// Where one instance's vertices and triangles are in the WorldGeometry flatten() makes.
struct InstanceRange {
    uint32_t mesh;
    uint32_t firstVertex, firstTriangle, triangleCount;
};
std::vector<InstanceRange> instanceRanges(const Scene& scene);

// Writes an instance's world positions and corner normals over its range of `world`, as
// flatten() places them (the same bits): flatten() fills each instance's part with it, and a
// moved instance is placed again in place (PreparedScene::setInstanceTransforms).
// `objectNormals`: cornerShadingNormals() of its mesh, three per triangle.
void placeInstance(const MeshInstance& instance, const Mesh& mesh, std::span<const glm::vec3> objectNormals,
                   const InstanceRange& range, WorldGeometry& world);

}  // namespace shadowlab
