// The rasterizer's public entry point: one draw call runs the whole pipeline,
//   vertex stage -> clipping -> setup -> binning   (front end, parallel over triangle chunks)
//   per-tile rasterization                          (back end, parallel over tiles)
// and returns when the framebuffer holds the result. Output is byte-identical for any
// thread count and any SIMD level (docs/determinism.md).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/bin.h"
#include "raster/framebuffer.h"
#include "raster/pipeline_state.h"
#include "raster/tile_kernels.h"
#include "raster/vertex_stage.h"

namespace shadowlab::raster {

// Vertex positions (either ordinary points or homogeneous ones), plus optional varyings
// stored vertex by vertex (varyingCount floats per vertex).
struct VertexStream {
    std::span<const glm::vec3> positions;
    std::span<const glm::vec4> homogeneousPositions;
    std::span<const float> varyings;
    int varyingCount = 0;
};

struct DrawCall {
    VertexStream vertices;
    glm::mat4 clipFromObject{1.0f};
    std::span<const glm::uvec3> triangles;
    uint32_t firstPrimitiveId = 0;       // triangle k writes firstPrimitiveId + k
    std::span<const uint32_t> primitiveIds;   // or, when given, primitiveIds[k]
    glm::vec4 constantColor{1.0f};       // FragmentOutput::ConstantColor
};

// A draw of triangles over plain positions, without varyings: what the depth, stencil and
// primitive-id passes over a scene's world geometry draw.
inline DrawCall positionsDraw(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                              const glm::mat4& clipFromObject) {
    DrawCall call;
    call.vertices.positions = positions;
    call.triangles = triangles;
    call.clipFromObject = clipFromObject;
    return call;
}

// Per-stage counters, summed over draws (integers, so independent of thread order).
struct RasterStats {
    uint64_t trianglesSubmitted = 0;
    uint64_t trianglesTriviallyRejected = 0;   // outside one viewport plane
    uint64_t trianglesClipped = 0;             // needed near/far/guard-band clipping
    uint64_t trianglesSetUp = 0;               // survived culling; their bounds hold a pixel centre
    uint64_t binEntries = 0;                   // (triangle, tile) pairs rasterized
    uint64_t fragments = 0;                    // covered pixels, before any test (the fill)
};

// How far a draw runs: every stage, or only up to the end of one, which the front end's
// benchmark (app/measure/bench_front_end.h) uses to time the stages on the draw's own chunks
// and threads. A draw that stops before the tiles leaves the framebuffer as it was.
enum class DrawStage { Vertices, Setup, Binning, Tiles };

class Rasterizer {
public:
    // Triangles per front-end chunk, and chunks per batch: a batch is set up, binned and
    // rasterized before the next, which bounds the memory a huge draw needs. Chunks run in
    // parallel (bin.h).
    static constexpr size_t kChunkTriangles = 4096;
    static constexpr size_t kChunksPerBatch = 64;
    // Bin entries (8 bytes each) held at once: a batch's chunks of triangles are binned and
    // rasterized in consecutive groups under this budget, so each tile still sees its
    // triangles in order. A group holds at least one chunk (4096 triangles), which bounds
    // the worst case: 4096 entries per tile.
    static constexpr size_t kDefaultBinEntryBudget = size_t(1) << 24;

    explicit Rasterizer(SimdLevel level = bestSimdLevel(), size_t binEntryBudget = kDefaultBinEntryBudget);

    SimdLevel simdLevel() const { return level_; }
    // Throws std::invalid_argument for an index out of range, too many varyings, primitive
    // ids past 2^32 - 1, or an output, stencil or colour state the framebuffer has no
    // buffer for.
    void draw(Framebuffer& framebuffer, const PipelineState& state, const DrawCall& call,
              DrawStage through = DrawStage::Tiles);

    const RasterStats& stats() const { return stats_; }
    void resetStats() { stats_ = {}; }

private:
    void validate(const Framebuffer& framebuffer, const PipelineState& state, const DrawCall& call) const;
    void runFrontEnd(const Framebuffer& framebuffer, const Viewport& viewport, const PipelineState& state,
                     const DrawCall& call, size_t firstTriangle, size_t triangleCount, size_t chunkCount, bool binning);
    uint64_t runBackEnd(Framebuffer& framebuffer, const DrawConstants& constants, TileKernel kernel);

    SimdLevel level_;
    const RasterKernels* kernels_;
    size_t binEntryBudget_;
    TransformedVertices vertices_;
    std::vector<SetupChunk> chunks_;
    std::vector<RasterStats> chunkStats_;
    TileBins bins_;
    std::vector<uint64_t> tileFragments_;   // per tile, each written by the tile's one task
    RasterStats stats_;
};

}  // namespace shadowlab::raster
