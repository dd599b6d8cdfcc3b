// The G-buffer (conventions.md, "Buffers written to disk"): what the camera sees through
// each pixel centre. The rasterizer writes the visible triangle per pixel (a visibility
// buffer); buildGBuffer() then intersects the pixel-centre ray with that triangle's plane
// in double precision, so P is the exact surface point rather than an interpolation.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

inline constexpr uint32_t kNoTriangle = 0xffffffffu;

// Where each pixel's surface point was in the frame before of a sequence (a fly-through):
// the point carried back with its instance's move, then seen by the previous camera
// (shading/motion_vectors.h). Every array is empty in a frame without a frame before (a
// single render, a sequence's frame 0), else width * height long, 0 where hit = 0.
struct SurfaceMotion {
    // The motion vector (conventions.md, "motion.x, motion.y"): the point's position in the
    // previous image minus this pixel's centre, in pixels, x to the right and y down, so the
    // point was at (i + 0.5, j + 0.5) + offset; infinite where the point was behind the
    // previous camera.
    std::vector<glm::vec2> pixelOffset;
    std::vector<glm::vec3> previousPosition;   // the point where it was, world space
    std::vector<glm::vec3> previousNormal;     // its geometric normal there: N turned with its instance
};

struct GBuffer {
    int width = 0, height = 0;
    std::vector<uint8_t> hit;            // 1 where a surface covers the pixel centre
    std::vector<glm::vec3> position;     // world space, 0 where hit = 0
    std::vector<glm::vec3> normal;       // world-space geometric normal facing the camera, 0 where hit = 0
    std::vector<glm::vec3> shadingNormal;  // smooth normal for shading, on the side of `normal`
    std::vector<uint32_t> material;      // index into Scene::materials
    std::vector<uint32_t> triangle;      // index into WorldGeometry::triangles, or kNoTriangle
    // Texture coordinates at P, where the surface's textures are read (shading/surface_albedo.h);
    // empty when the world has none (WorldGeometry::cornerUvs), 0 where hit = 0.
    std::vector<glm::vec2> uv;
    std::vector<float> depth;            // window depth as in the depth buffer (1 = background)
    SurfaceMotion motion;                // empty without a frame before

    size_t pixelCount() const { return size_t(width) * size_t(height); }
    size_t index(int i, int j) const { return size_t(j) * size_t(width) + size_t(i); }
};

}  // namespace shadowlab
