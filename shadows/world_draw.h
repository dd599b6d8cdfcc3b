// Drawing a world's triangles so that cut-outs have holes in every pass: the solid
// triangles in one draw, each cut-out's (WorldGeometry::cutOuts) in a draw of its own with
// the rasterizer's alpha test, its corners carrying their texture coordinates. The camera's
// G-buffer and every depth map of a world draw through it, so a foliage card casts and
// shows the shape of its leaves in every shadow-map technique.
// Primitive ids are world triangle indices.
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"
#include "scenes/scene.h"

namespace shadowlab {

// The world's triangles, or only those listed (indices into world.triangles, ascending);
// `constantColor` for FragmentOutput::ConstantColor.
void drawWorld(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const raster::PipelineState& state,
               const WorldGeometry& world, const glm::mat4& clipFromWorld, std::span<const uint32_t> only = {},
               const glm::vec4& constantColor = glm::vec4(1.0f));

}  // namespace shadowlab
