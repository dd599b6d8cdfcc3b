// The light's view for a depth map, fitted tightly to what matters (Real-Time Rendering,
// 4th ed., section 7.4, Figure 7.11): the sides bound the receivers the camera sees (the
// G-buffer points with hit = 1), the far plane is the farthest of them, and the near plane
// is the nearest geometry inside that frustum, since only geometry between the light and
// the visible receivers can shadow them.
//
// Point and spot lights get a perspective frustum with its apex at the light (asymmetric,
// so it hugs the receivers); directional lights an orthographic box. A point light whose
// receivers surround it cannot be covered by one frustum: fitLightView throws, and the
// technique uses six cube faces instead (fitCubeFace).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

struct LightView {
    glm::dmat4 viewFromWorld{1.0};   // OpenGL view space: the light looks down -z
    glm::dmat4 clipFromView{1.0};
    double zNear = 0.0, zFar = 1.0;  // view-space distances along -z
    bool orthographic = false;
    glm::dmat4 clipFromWorld() const { return clipFromView * viewFromWorld; }
};

// The memory a fit works in: every vertex's depth and side bits in the view (the nearest
// geometry inside it). A technique keeps it between frames (technique_history.h) and lends
// it through LightFitOptions::scratch, so that a steady state's fits allocate none of it.
struct LightViewScratch {
    std::vector<double> depth;
    std::vector<uint8_t> insideBits;
    GBuffer everyVertex;        // fitLightViewToWorld's receivers: every vertex of the world
    WorldGeometry worldBox;     // ... and the world's box, the geometry its near plane is fitted to
};

struct LightFitOptions {
    int resolution = 2048;       // texels per side of the map the view is for
    double marginTexels = 2.0;   // receivers stay this far inside the sides (filter footprints)
    // The near plane is never closer than this fraction of the far distance, which bounds
    // the depth precision a perspective map can lose (window depth resolves ~ z^2 / near).
    double minNearFraction = 1e-4;
    // Point and spot lights: the direction the view looks along. Zero (the default): towards
    // the centre of the receivers' bounding box. A disk light's normal makes the depth planes
    // parallel to the light's plane (what shadow fins measure distances from).
    glm::dvec3 axis{0.0};
    // The receivers' bounds kernel (receiver_bounds.h); every level gives the same view.
    raster::SimdLevel simd = raster::bestSimdLevel();
    // Cube faces (fitCubeFace): true culls a face whose pyramid holds no visible receiver;
    // false fits it anyway, to the geometry around the light (a comparison for tests and
    // measurements: no receiver looks such a face up, so V is the same, bit for bit).
    bool cullCubeFaces = true;
    // The memory to fit in (kept between frames); null: the fit's own, freed after it.
    LightViewScratch* scratch = nullptr;
};

// Throws std::invalid_argument when there are no receivers, the light is an area light
// (pass pointLightFor(light)), or a point light's receivers span more than a hemisphere.
LightView fitLightView(const Light& light, const GBuffer& receivers, const WorldGeometry& world,
                       const LightFitOptions& options = {});

// The same view fitted to the whole world instead of the visible receivers: its sides hold
// every vertex and its near plane is the nearest point of the world's bounding box inside
// them. It does not follow the camera, and stays while the outermost vertices and the box
// do (a caster moving inside the world leaves it), which is what a map kept across frames
// needs (cache=static, maps/static_map_cache.h); its depth range is wider than a fit to
// the receivers. Throws as fitLightView does (a point light among the world's vertices).
LightView fitLightViewToWorld(const Light& light, const WorldGeometry& world, const LightFitOptions& options = {});

// Face k (0..5: +x, -x, +y, -y, +z, -z) of a cube around a point light: a 90-degree
// square frustum, with near and far fitted to the receivers and geometry inside it.
// Returns false when no receiver lies in the face (culled: its map could shadow no pixel
// the camera sees, since a receiver looks up only the face whose pyramid holds it), unless
// options.cullCubeFaces is false: such a face then reaches the farthest vertex of `world`.
bool fitCubeFace(const Light& light, int face, const GBuffer& receivers, const WorldGeometry& world,
                 const LightFitOptions& options, LightView& view);

// Face k's view from a light at `apex`: looking along the face's axis with its fixed up
// vector, the frame fitCubeFace fits in (and a virtual map's faces are drawn in).
glm::dmat4 cubeFaceViewFromWorld(const glm::dvec3& apex, int face);

// The faces' names, as debug buffers suffix them ("-face-px").
inline constexpr const char* kCubeFaceNames[6] = {"px", "nx", "py", "ny", "pz", "nz"};

// Whether P lies in the 90-degree pyramid of a cube face's view: the test fitCubeFace fits
// a face's receivers by, and the one a receiver's face is chosen by.
bool insideCubeFace(const LightView& face, const glm::dvec3& P);

// The views a light needs for the visible receivers: the one frustum fitLightView fits, or,
// for a point light they surround (where it throws), the faces fitCubeFace keeps.
struct LightViews {
    std::vector<LightView> views;
    std::vector<int> faces;   // each view's cube face (0..5, kCubeFaceNames); empty for one frustum

    size_t size() const { return views.size(); }
    // What ends view v's debug buffers' names: "" for one frustum, "-face-px" for a face.
    std::string suffix(size_t v) const;
};
// Throws as fitLightView does, but for a point light's receivers all around it.
LightViews fitLightViews(const Light& light, const GBuffer& receivers, const WorldGeometry& world,
                         const LightFitOptions& options);

}  // namespace shadowlab
