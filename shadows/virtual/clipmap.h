// The virtual shadow map of a directional light as a clipmap (docs/virtual-shadow-maps.md):
// square levels of `resolution` texels a side, each twice the size of the one before, all
// centred on the camera and cut into pages of `pageTexels` texels a side. This is the
// adaptive shadow map's idea (Fernando et al. 2001: resolution where the view needs it)
// laid out as Unreal Engine 5's virtual shadow maps lay out a sun (Epic's public
// documentation, "Virtual Shadow Maps": a 16k x 16k virtual map in 128 x 128 pages, clipmap
// levels for directional lights).
//
// Levels are named by an absolute exponent: level l covers 2^(l+1) m a side, so its texel
// is 2^(l+1) / resolution m, a power of two, and a page's corners lie on a grid fixed in
// the light's frame. A level's window is centred on the camera snapped to whole pages, so a
// camera that moves keeps every page still inside the window: the same page of the same
// level holds the same texels in every frame (page coordinates are global, not window-
// relative), and only the pages that enter the window are new.
//
// Coordinates: the light's frame (LightFrame) is orthonormal, in double; its x and y span
// the map's plane and its z points towards the light. A level's texel coordinate is the
// frame's (x, y) divided by its texel size, with the texel's row growing downwards (-y), as
// every image (conventions.md): texel (u, v) covers [u, u+1) x [v, v+1).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shadows/texel_index.h"

namespace shadowlab::vsm {

// The light's orthonormal frame, in double: z towards the light (Light::direction), x and y
// across its beam: the rows of the rotation every shadow map of a sun is drawn with
// (light_view.h), so the same direction always gives the same frame.
struct LightFrame {
    glm::dvec3 x{1.0, 0.0, 0.0}, y{0.0, 1.0, 0.0}, z{0.0, 0.0, 1.0};

    static LightFrame towards(const glm::dvec3& direction);
    // A world point in the frame: (across, across, height towards the light).
    glm::dvec3 local(const glm::dvec3& P) const { return {glm::dot(P, x), glm::dot(P, y), glm::dot(P, z)}; }
};

struct ClipmapSettings {
    int resolution = 16384;   // texels a side of every level
    int pageTexels = 128;     // texels a side of a page; divides resolution
    int firstLevel = -2;      // the finest level: 2^(l+1) m a side (0.5 m, a 30 um texel)
    int lastLevel = 10;       // the coarsest (2 km)

    int pagesPerSide() const { return resolution / pageTexels; }
    int levelCount() const { return lastLevel - firstLevel + 1; }
    // Level l's texel and page sides, m: powers of two, so texel coordinates of a frame point
    // are exact scalings of it.
    double texelM(int level) const;
    double pageM(int level) const { return texelM(level) * pageTexels; }
};

// A page of a level: its level and its global page coordinates (page (px, py) holds texels
// [px, px+1) * pageTexels x [py, py+1) * pageTexels of the level).
struct PageKey {
    int level = 0;
    int32_t x = 0, y = 0;
    bool operator==(const PageKey&) const = default;
};

// Where a level's window lies this frame: its first page in each axis (global coordinates);
// it spans pagesPerSide() pages from there.
struct LevelWindow {
    int level = 0;
    int32_t firstX = 0, firstY = 0;
    bool holds(int32_t px, int32_t py, int pagesPerSide) const {
        return px >= firstX && py >= firstY && px - firstX < pagesPerSide && py - firstY < pagesPerSide;
    }
};

// The page holding texel coordinate c (floor(c / pageTexels)), saturated to +-2^30 pages,
// so that any coordinate, however far, gives a page no window holds instead of overflowing.
// c / pageTexels is exact (a power of two), as its product with the inverse; texelIndexOf
// floors and saturates without a library call. Inline: marking and the lookup call it per
// pixel.
inline int32_t pageOf(double c, int pageTexels) { return texelIndexOf(c * (1.0 / double(pageTexels))); }

// Level l's texel coordinate of a point of the frame (the row grows downwards).
glm::dvec2 texelOf(const ClipmapSettings& settings, int level, const glm::dvec3& local);

// The window of a level centred on the camera's eye, snapped to whole pages.
LevelWindow placeLevel(const ClipmapSettings& settings, int level, const glm::dvec3& eyeLocal);

// Whether the settings make a clipmap: resolution and page a power of two, 16 <= pageTexels
// <= resolution <= 2^20, at least 2 pages a side, levels in [-kMaxLevel, kMaxLevel] and
// first <= last. Throws std::invalid_argument naming the setting otherwise.
inline constexpr int kMaxLevel = 40;
inline constexpr int kMaxLevelCount = 2 * kMaxLevel + 1;
void checkClipmapSettings(const ClipmapSettings& settings);

}  // namespace shadowlab::vsm
