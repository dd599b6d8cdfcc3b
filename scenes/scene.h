// The in-memory scene: what a scene file (docs/scene-format.md) or a built-in scene
// describes. Meshes are kept in object space with an instance transform; flatten()
// produces the world-space triangle list that the rasterizer, the G-buffer and the
// Embree reference all consume, so every technique sees exactly the same geometry.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

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
};

// Every model is a Lambert diffuse term plus, except for Lambert, a specular lobe
// (shading/shade.h, brdf()): Blinn-Phong and normalised Phong lobes of a shininess, or the
// GGX microfacet lobe of a roughness (Torrance-Sparrow).
enum class MaterialModel { Lambert, BlinnPhong, Phong, Ggx };

struct Material {
    std::string name;
    MaterialModel model = MaterialModel::Lambert;
    glm::vec3 albedo{0.8f};    // diffuse reflectance in [0,1]
    glm::vec3 specular{0.0f};  // specular reflectance in [0,1]; GGX: Schlick's F0
    float shininess = 32.0f;   // Blinn-Phong and Phong exponent, > 0
    float roughness = 0.5f;    // GGX alpha, in (0, 1]
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
struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};           // point, spot; centre of disk and rectangle
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot: axis it shines along; directional: towards the light;
                                        // disk: unit normal of the emitting side
    float coneAngleDeg = 30.0f;         // spot: half-angle of the cone
    float radius = 0.0f;                // disk
    glm::vec3 halfEdgeU{0.0f}, halfEdgeV{0.0f};  // rectangle
    glm::vec3 intensity{1.0f};
};

struct Camera {
    glm::vec3 eye{0.0f, 4.0f, 9.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovyDeg = 45.0f;
    int width = 1280, height = 800;
    float zNear = 0.1f, zFar = 100.0f;
};

struct Environment {
    glm::vec3 ambient{0.0f};            // constant ambient radiance added to every surface
    // A latitude-longitude map of distant radiance (conventions.md, "Lights"), read by
    // shading/environment/environment_file.h where it is used: its path, resolved against
    // the scene file's folder (empty: none), and its turn about +Y, right-handed.
    std::string map;
    float rotationDeg = 0.0f;
};

struct Scene {
    std::string name;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    Camera camera;
    Environment environment;
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
};

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

}  // namespace shadowlab
