// A scene for compositing synthetic objects into a photograph (Gibson et al. 2003, section 3):
// the photograph, the camera that took it, an approximate model of the real scene as planar
// patches, each with a diffuse reflectance and the radiance it sends (every patch with
// radiance is a potential light source), and the synthetic objects to place in it.
//
// The model is a list of surfaces, each a parallelogram cut into a grid of patches. A
// receiver's transfers live at the grid's vertices and are interpolated bilinearly across
// each patch (Gouraud shading of the paper's hardware passes), so a vertex belongs to one
// surface and carries that surface's reflectance.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct PatchSurface {
    std::string name;
    // Corners origin, origin + edgeU, origin + edgeU + edgeV, origin + edgeV: counter-
    // clockwise seen from the front, whose normal is unit(edgeU x edgeV); only the front
    // reflects or emits.
    glm::dvec3 origin{0.0}, edgeU{1.0, 0.0, 0.0}, edgeV{0.0, 0.0, -1.0};
    int cellsU = 1, cellsV = 1;
    glm::dvec3 reflectance{0.5};   // diffuse, in [0, 1)
    // Radiance it emits, W/(m^2 sr): one value for every patch, or cellsU * cellsV values
    // (cell (a, b) at b * cellsU + a) for a surface whose patches differ (a sky dome).
    std::vector<glm::dvec3> emitted;
};

// The model flattened: patch p is a quad of four grid vertices.
struct Patch {
    uint32_t vertex[4];   // counter-clockwise from the front
    uint32_t surface;
    glm::dvec3 reflectance, emitted;
    glm::dvec3 normal;    // unit, the front
    double area;          // m^2
};

struct PatchModel {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::dvec3> vertexNormal;     // its surface's front
    std::vector<uint32_t> vertexSurface;
    std::vector<glm::dvec3> vertexReflectance;   // its surface's
    // Where a vertex's light is evaluated: 1e-4 of the way towards its surface's centre, so
    // that a ray from a vertex on an edge its surface shares with another (the floor's
    // along a wall) does not start on the other surface and find it in the way.
    std::vector<glm::dvec3> vertexInside;
    std::vector<Patch> patches;
    // The corners of patch p, counter-clockwise from the front.
    std::array<glm::dvec3, 4> corners(uint32_t p) const;
    // Patch p's point at (u, v) in [0, 1]^2 of its own grid cell.
    glm::dvec3 pointAt(uint32_t p, double u, double v) const;
    glm::dvec3 centre(uint32_t p) const { return pointAt(p, 0.5, 0.5); }
};

// The most patches a model may have: differential rendering's preprocessing grows with
// their square (every receiver vertex gathers from every radiant patch), and a model of
// this many already takes minutes.
inline constexpr size_t kMaxCompositingPatches = size_t(1) << 16;

// Throws std::invalid_argument for more than kMaxCompositingPatches patches in all (before
// anything is allocated), a surface with a non-finite origin, no area, fewer than one cell per side,
// more than 4096 cells per side, a reflectance outside [0, 1), a negative or non-finite
// emitted radiance, or an emitted list of neither 1 nor cellsU * cellsV values.
PatchModel flattenPatches(const std::vector<PatchSurface>& surfaces);

// The model as triangles for the rasterizer and Embree: patch p is triangles 2p and 2p + 1,
// (v0, v1, v2) and (v0, v2, v3), one instance and material per surface, every corner
// normal the patch's.
WorldGeometry patchGeometry(const PatchModel& model);

// A synthetic object: a mesh with a diffuse albedo, placed by one transform per frame of its
// path (at least one). A scene's objects move together frame by frame, so their paths have
// the same length.
struct SyntheticObject {
    Mesh mesh;
    glm::dvec3 albedo{0.7};
    std::vector<glm::mat4> path;
};

// How a photograph's 8-bit values relate to radiance: I = 255 clamp((exposure L)^(1/gamma))
// per channel, the camera response T of Gibson et al. section 7.1 (a gamma curve; measured
// curves are monotone like it).
struct CameraResponse {
    double exposure = 1.0, gamma = 2.2;
    double operator()(double radiance) const;       // to 8-bit intensity in [0, 255], unrounded
    glm::dvec3 operator()(const glm::dvec3& radiance) const;
    double inverse(double intensity) const;         // the radiance of an intensity below 255
};

struct CompositingScene {
    std::string name;
    Camera camera;
    std::vector<PatchSurface> surfaces;
    std::vector<SyntheticObject> objects;   // one or more
    CameraResponse response;
    // The photograph as linear radiance, camera.width * camera.height, row 0 at the top; empty
    // when it is to be rendered from the model (differential/background.h).
    std::vector<glm::vec3> background;
};

}  // namespace shadowlab
