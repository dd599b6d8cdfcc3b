// The virtual shadow map of a spot or point light as mip chains (docs/virtual-shadow-maps.md):
// one perspective face for a spot light, six cube faces for a point light (an area light:
// from its centre, as `shadow-map` treats it), each face `resolution` texels a side at mip 0,
// mip m having resolution >> m, every mip cut into pages of `pageTexels` (Unreal Engine 5's
// local lights, Epic's "Virtual Shadow Maps": a mip chain per face, the mip chosen per pixel).
// Resolution-matched shadow maps (Lefohn et al. 2007) use the same idea: the view's samples
// decide which mip, so which pages, a receiver needs.
//
// The faces are fixed in the light's frame, not fitted to the view, so that a page holds
// the same texels in every frame while the light stays still: a point light's faces are
// fitCubeFace's (light_view.h), a spot's one face looks along the spot's axis (the up vector
// shadow-map's perspective views use) and holds its cone. Depth is OpenGL window depth of
// the face's frustum between a near and a far plane that hold every caster (DepthRange, as
// distances along the face's axis), as every perspective shadow map stores it, so the
// shadow maps' receiver mapping and bias apply unchanged.
//
// In the page table (page_table.h) the level of face f at mip m is m * faceCount + f:
// coarse mips of every face come last, so allocation, which serves levels from the last,
// gives memory to the coarse mips first. A mip's window is the whole mip, fixed.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/bounds.h"
#include "scenes/scene.h"
#include "shadows/light_view.h"
#include "shadows/virtual/clipmap.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// A spot light of at most this half-angle gets one face; a wider one six, as a point light.
inline constexpr double kMaxSpotFaceDeg = 60.0;

struct MipChain {
    int resolution = 16384;             // texels a side of a face's mip 0
    int pageTexels = 128;
    int mipCount = 1;                   // mips 0 .. mipCount - 1, the last one page a side
    glm::dvec3 apex{0.0};
    double tanHalf = 1.0;               // the faces' half-angle's tangent (1: a cube face)
    std::vector<glm::dmat4> faces;      // each face's view (OpenGL: it looks down -z)
    DepthRange range;                   // near and far, along a face's axis

    int faceCount() const { return int(faces.size()); }
    int levelCount() const { return mipCount * faceCount(); }
    int levelOf(int face, int mip) const { return mip * faceCount() + face; }
    int faceOfLevel(int level) const { return level % faceCount(); }
    int mipOfLevel(int level) const { return level / faceCount(); }
    int mipTexels(int mip) const { return resolution >> mip; }
    int pagesPerSide(int mip) const { return mipTexels(mip) / pageTexels; }

    PageLayout layout() const;
    std::vector<LevelWindow> windows() const;   // every mip whole, from page (0, 0)
    // The face's frustum from the light, and a mip's texels as one map: world -> (texel x,
    // texel y, window depth, w), a DepthMap's texelFromWorld (depth_map.h).
    glm::dmat4 clipFromView() const;
    glm::dmat4 texelFromWorld(int level) const;
    // A mip's cells: squares of min(mip texels, the rasterizer's largest viewport) texels
    // from the mip's corner, each a whole number of pages (page_rendering.h's cells).
    int cellTexels(int mip) const;
    // How a page is drawn: as a window of its cell's map, whose view is the off-centre part
    // of its face's frustum that holds exactly the cell's texels; so a page's texels are
    // the bits of an ordinary perspective map of its cell (of the whole mip, for a mip that
    // fits the viewport), drawn whole.
    PageView pageView(const PageKey& key) const;
    // The first face whose pyramid holds P (insideCubeFace's test for a cube face), or -1.
    int faceHolding(const glm::dvec3& P) const;
    // Whether a face's pyramid holds q, a point in that face's view space.
    bool pyramidHolds(const glm::dvec3& q) const {
        return -q.z > 0.0 && std::abs(q.x) <= -q.z * tanHalf && std::abs(q.y) <= -q.z * tanHalf;
    }
};

// Each level as the one map a receiver is mapped into (only its size and matrices set), by
// level index (mip * faces + face).
std::vector<DepthMap> levelMaps(const MipChain& chain);

// The faces of `light` (spot or point; an area light's centre as a point, pointLightFor),
// their mips, and a depth range holding `boxes`, the casters' instances' boxes (depthRangeAround).
MipChain mipChainFor(const Light& light, const ClipmapSettings& settings, const std::vector<Aabb>& boxes);

// The depth range along the faces' axes that holds every box, widened by 10 % (and 1 cm) at
// its far end and to half its distance at its near end, and at least 1e-4 of the far
// distance (which bounds the depth precision a perspective map loses, as light_view.h's
// minNearFraction); `tight` false returns it widened, true the range the boxes need, to test
// whether a kept range still holds them (DepthRange::holds).
DepthRange depthRangeAround(const std::vector<Aabb>& boxes, const glm::dvec3& apex, double tanHalf, bool tight);

// A box's texel rectangle in one level (its corners' projections' bounds, texel units), or
// none when the box crosses the plane of the light facing the level's face: a beam through
// the apex could then meet it on either side, so the whole face is under it. `behind` is
// set when every corner lies behind the light's plane: the box is in no texel of the face.
struct TexelRect {
    glm::dvec2 lo, hi;
};
std::optional<TexelRect> texelRectOf(const Aabb& box, const glm::dmat4& texelFromWorld, bool& behind);

}  // namespace shadowlab::vsm
