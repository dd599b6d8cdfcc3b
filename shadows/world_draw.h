// Drawing a world's triangles so that cut-outs have holes in every pass: the solid
// triangles in one draw, each cut-out's (WorldGeometry::cutOuts) in a draw of its own with
// the rasterizer's alpha test, its corners carrying their texture coordinates. The camera's
// G-buffer and every depth map of a world draw through it, so a foliage card casts and
// shows the shape of its leaves in every shadow-map technique.
// Primitive ids are world triangle indices.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene.h"

namespace shadowlab {

// A world's triangles, or some of them, grouped into the draws above: the solid ones by
// index, each cut-out's as corners of their own (a corner's texture coordinate belongs to
// the triangle, not to the shared vertex). Grouping is a pass over the triangles, so a
// world's are grouped once per prepared scene (preparedWorldDraws) and drawn by every pass
// of every frame, as a renderer keeps its vertex buffers.
struct WorldDraws {
    struct Batch {
        std::vector<glm::uvec3> triangles;
        std::vector<uint32_t> ids;
        std::vector<glm::vec3> corners;   // a cut-out's: three per triangle
        std::vector<float> uvs;
    };
    bool whole = false;   // every triangle and no cut-out: the world's own arrays, as they are
    Batch solid;
    std::vector<Batch> cutOuts;   // indexed like WorldGeometry::cutOuts
};

// The world's triangles, or only those listed (indices into world.triangles, ascending).
WorldDraws worldDraws(const WorldGeometry& world, std::span<const uint32_t> only = {});
// The whole world's, grouped on first use and kept with the prepared scene.
const WorldDraws& preparedWorldDraws(const PreparedScene& prepared);

// `constantColor` for FragmentOutput::ConstantColor.
void drawWorld(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const raster::PipelineState& state,
               const WorldGeometry& world, const WorldDraws& draws, const glm::mat4& clipFromWorld,
               const glm::vec4& constantColor = glm::vec4(1.0f));
// The same, grouping the world's triangles (or those listed) for this one draw.
void drawWorld(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const raster::PipelineState& state,
               const WorldGeometry& world, const glm::mat4& clipFromWorld, std::span<const uint32_t> only = {},
               const glm::vec4& constantColor = glm::vec4(1.0f));

}  // namespace shadowlab
