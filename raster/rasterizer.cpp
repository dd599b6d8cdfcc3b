#include "raster/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "raster/clip.h"
#include "raster/setup.h"

namespace shadowlab::raster {
namespace {

const float* varyingsOf(const VertexStream& stream, uint32_t index) {
    return stream.varyingCount == 0 ? nullptr : stream.varyings.data() + size_t(index) * size_t(stream.varyingCount);
}

ClipVertex clipVertex(const TransformedVertices& v, const VertexStream& stream, uint32_t index) {
    ClipVertex c;
    c.position = v.clipPosition(index);
    const float* varyings = varyingsOf(stream, index);
    for (int k = 0; k < stream.varyingCount; ++k) c.varyings[k] = varyings[k];
    return c;
}

bool projectable(const glm::vec4& p) {
    return p.w > 0.0f && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// Starting from the vertex with the lexicographically smallest clip position (winding
// kept) makes the clipped polygon, and so the fan and its planes, depend only on the
// triangle's geometry: not on how its indices are rotated or numbered.
bool precedes(const glm::vec4& a, const glm::vec4& b) {
    for (int k = 0; k < 4; ++k) {
        if (a[k] != b[k]) return a[k] < b[k];
    }
    return false;
}

glm::uvec3 canonicalIndexOrder(const glm::uvec3& t, const TransformedVertices& v) {
    const glm::vec4 a = v.clipPosition(t.x), b = v.clipPosition(t.y), c = v.clipPosition(t.z);
    if (precedes(b, a) && !precedes(c, b)) return {t.y, t.z, t.x};
    if (precedes(c, a) && precedes(c, b)) return {t.z, t.x, t.y};
    return t;
}

// The slow path, for a triangle with a vertex outside the guard band, near or far plane,
// or one that cannot be projected: clip it, then set up the fan of triangles the clipped
// polygon forms, all with the polygon's largest depth for the polygon offset.
void clipAndSetup(SetupQueue& queue, const TransformedVertices& v, const VertexStream& stream, const glm::uvec3& triangle,
                  uint32_t id, const Viewport& viewport) {
    const glm::uvec3 t = canonicalIndexOrder(triangle, v);
    ClipVertex polygon[kMaxClippedVertices] = {clipVertex(v, stream, t.x), clipVertex(v, stream, t.y),
                                               clipVertex(v, stream, t.z)};
    const uint32_t codes = (v.clipCode[t.x] | v.clipCode[t.y] | v.clipCode[t.z]) & ~uint32_t(kNotProjectable);
    const int n = clipPolygon(polygon, 3, codes, viewport.volume, stream.varyingCount);
    SetupVertex window[kMaxClippedVertices];
    Primitive primitive = {id, 0.0};
    for (int k = 0; k < n; ++k) {
        // Clipping cannot repair a vertex at w <= 0 in front of the near plane (an unusual
        // projection) or a non-finite one: the primitive is dropped.
        if (!projectable(polygon[k].position)) return;
        window[k] = {toWindow(polygon[k].position, viewport.width, viewport.height), polygon[k].varyings};
        primitive.maxDepth = std::max(primitive.maxDepth, std::abs(window[k].window.z));
    }
    for (int k = 1; k + 1 < n; ++k) queue.push({window[0], window[k], window[k + 1]}, primitive);
}

// The largest vertex index of the draw, in parallel: a pass over every index that would
// otherwise be the draw's longest serial part.
uint32_t largestIndex(std::span<const glm::uvec3> triangles) {
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, triangles.size(), Rasterizer::kChunkTriangles), uint32_t(0),
        [&](const tbb::blocked_range<size_t>& range, uint32_t largest) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                largest = std::max({largest, triangles[i].x, triangles[i].y, triangles[i].z});
            }
            return largest;
        },
        [](uint32_t a, uint32_t b) { return std::max(a, b); });
}

// The viewport vertices are placed in: the framebuffer, or the one it is a window of.
Viewport viewportFor(const Framebuffer& fb, const PipelineState& state) {
    const ViewportWindow& w = state.window;
    const int width = w.viewportWidth ? w.viewportWidth : fb.width(), height = w.viewportWidth ? w.viewportHeight : fb.height();
    return {width, height, clipVolumeFor(width, height, state.clipFar)};
}

}  // namespace

Rasterizer::Rasterizer(SimdLevel level, size_t binEntryBudget)
    : level_(level), kernels_(&rasterKernels(level)), binEntryBudget_(binEntryBudget) {}

void Rasterizer::validate(const Framebuffer& framebuffer, const PipelineState& state, const DrawCall& call) const {
    const VertexStream& vs = call.vertices;
    const size_t vertexCount = vs.positions.empty() ? vs.homogeneousPositions.size() : vs.positions.size();
    if (!vs.positions.empty() && !vs.homogeneousPositions.empty()) {
        throw std::invalid_argument("draw: give either positions or homogeneous positions, not both");
    }
    if (vs.varyingCount < 0 || vs.varyingCount > kMaxVaryings) {
        throw std::invalid_argument("draw: varyingCount must be in 0.." + std::to_string(kMaxVaryings));
    }
    if (vs.varyings.size() != vertexCount * size_t(vs.varyingCount)) {
        throw std::invalid_argument("draw: varyings must hold varyingCount values per vertex");
    }
    if (!call.primitiveIds.empty() && call.primitiveIds.size() != call.triangles.size()) {
        throw std::invalid_argument("draw: primitiveIds must hold one id per triangle");
    }
    const AlphaTest& alpha = state.alphaTest;
    if (alpha.alpha && (alpha.width < 1 || alpha.height < 1 || int64_t(alpha.width) * alpha.height > INT32_MAX ||
                        vs.varyingCount < 2)) {
        throw std::invalid_argument("draw: the alpha test needs a texture of at least 1 x 1 texels and varyings u, v");
    }
    if (uint64_t(call.firstPrimitiveId) + call.triangles.size() > uint64_t(UINT32_MAX) + 1) {
        throw std::invalid_argument("draw: primitive ids would pass 2^32 - 1");
    }
    if (!call.triangles.empty() && largestIndex(call.triangles) >= vertexCount) {
        throw std::invalid_argument("draw: vertex index out of range (" + std::to_string(vertexCount) + " vertices)");
    }
    const ViewportWindow& w = state.window;
    if (w.viewportWidth == 0 ? (w.viewportHeight != 0 || w.x != 0 || w.y != 0)
                             : (w.viewportWidth < 1 || w.viewportWidth > kMaxViewport || w.viewportHeight < 1 ||
                                w.viewportHeight > kMaxViewport || w.x < 0 || w.y < 0 ||
                                w.x > w.viewportWidth - framebuffer.width() || w.y > w.viewportHeight - framebuffer.height())) {
        throw std::invalid_argument("draw: the framebuffer must be a window inside a viewport of at most " +
                                    std::to_string(kMaxViewport) + " pixels a side");
    }
    const Attachments& has = framebuffer.attachments();
    if (state.stencil.enabled && !has.stencil) throw std::invalid_argument("draw: stencil test on a framebuffer without stencil");
    if (state.output == FragmentOutput::PrimitiveId && !has.primitiveId) {
        throw std::invalid_argument("draw: primitive-id output on a framebuffer without a primitive-id buffer");
    }
    if (state.output == FragmentOutput::FragmentList && !has.fragments) {
        throw std::invalid_argument("draw: fragment-list output on a framebuffer without fragment lists");
    }
    const bool writesColor = state.output == FragmentOutput::ConstantColor || state.output == FragmentOutput::VaryingColor;
    if (writesColor && !has.color) throw std::invalid_argument("draw: colour output on a framebuffer without colour");
}

void Rasterizer::runFrontEnd(const Framebuffer& framebuffer, const Viewport& viewport, const PipelineState& state,
                             const DrawCall& call, size_t firstTriangle, size_t triangleCount, size_t chunkCount,
                             bool binning) {
    const SetupConstants constants = setupConstants(framebuffer.width(), framebuffer.height(), state, call.vertices.varyingCount);
    tbb::parallel_for(size_t(0), chunkCount, [&](size_t c) {
        SetupChunk& chunk = chunks_[c];
        RasterStats& stats = chunkStats_[c];
        chunk.triangles.clear(), chunk.planes.clear(), chunk.planeStart.clear();
        stats = {};
        SetupQueue queue(kernels_->setup, constants, chunk);
        const size_t begin = firstTriangle + c * kChunkTriangles;
        const size_t end = std::min(begin + kChunkTriangles, firstTriangle + triangleCount);
        const TransformedVertices& v = vertices_;
        for (size_t i = begin; i < end; ++i) {
            const glm::uvec3& t = call.triangles[i];
            const uint32_t id = call.primitiveIds.empty() ? call.firstPrimitiveId + uint32_t(i) : call.primitiveIds[i];
            if (v.viewportCode[t.x] & v.viewportCode[t.y] & v.viewportCode[t.z]) {
                ++stats.trianglesTriviallyRejected;   // wholly outside one side of the view volume
            } else if ((v.clipCode[t.x] | v.clipCode[t.y] | v.clipCode[t.z]) == 0) {
                const double maxDepth = std::max({std::abs(v.window[t.x].z), std::abs(v.window[t.y].z), std::abs(v.window[t.z].z)});
                queue.push({{v.window[t.x], varyingsOf(call.vertices, t.x)}, {v.window[t.y], varyingsOf(call.vertices, t.y)},
                            {v.window[t.z], varyingsOf(call.vertices, t.z)}}, {id, maxDepth});
            } else {
                ++stats.trianglesClipped;
                clipAndSetup(queue, v, call.vertices, t, id, viewport);
            }
        }
        queue.flush();
        if (binning) countTiles(chunk, framebuffer.tilesX(), framebuffer.tilesY());
    });
}

// Returns the fragments rasterized: each tile's count, summed.
uint64_t Rasterizer::runBackEnd(Framebuffer& framebuffer, const DrawConstants& constants, TileKernel kernel) {
    const FramebufferView view = framebuffer.unresolvedView();
    const int tileCount = framebuffer.tilesX() * framebuffer.tilesY();
    tileFragments_.assign(size_t(tileCount), 0);
    // One task owns one tile and runs its triangles in submission order. A tile no
    // triangle touches keeps a pending clear (framebuffer.h) and costs nothing.
    tbb::parallel_for(0, tileCount, [&](int tile) {
        if (bins_.start[size_t(tile)] == bins_.start[size_t(tile) + 1]) return;
        framebuffer.fillPendingTile(tile);
        const Tile at = tileAt(tile, framebuffer.tilesX());
        uint64_t fragments = 0;
        for (size_t e = bins_.start[size_t(tile)]; e < bins_.start[size_t(tile) + 1]; ++e) {
            kernel(*bins_.entries[e], at, constants, view, fragments);
        }
        tileFragments_[size_t(tile)] = fragments;
    });
    return std::accumulate(tileFragments_.begin(), tileFragments_.end(), uint64_t(0));
}

void Rasterizer::draw(Framebuffer& framebuffer, const PipelineState& state, const DrawCall& call, DrawStage through) {
    validate(framebuffer, state, call);
    const Viewport viewport = viewportFor(framebuffer, state);
    if (call.vertices.positions.empty()) {
        transformVertices(call.vertices.homogeneousPositions, call.clipFromObject, viewport, vertices_);
    } else {
        transformVertices(call.vertices.positions, call.clipFromObject, viewport, vertices_);
    }
    if (through == DrawStage::Vertices) return;
    DrawConstants constants = {state, {call.constantColor.r, call.constantColor.g, call.constantColor.b, call.constantColor.a},
                               call.vertices.varyingCount};
    const TileKernel kernel =
        kernels_->kernel[int(state.output)][state.stencil.enabled ? 1 : 0][state.alphaTest.alpha ? 1 : 0];

    const size_t batchTriangles = kChunkTriangles * kChunksPerBatch;
    chunks_.resize(kChunksPerBatch);
    chunkStats_.resize(kChunksPerBatch);
    for (size_t first = 0; first < call.triangles.size(); first += batchTriangles) {
        const size_t count = std::min(batchTriangles, call.triangles.size() - first);
        const size_t chunkCount = (count + kChunkTriangles - 1) / kChunkTriangles;
        runFrontEnd(framebuffer, viewport, state, call, first, count, chunkCount, through >= DrawStage::Binning);
        for (size_t group = 0; group < chunkCount && through >= DrawStage::Binning;) {
            size_t end = group + 1, entries = chunks_[group].entryCount;
            while (end < chunkCount && entries + chunks_[end].entryCount <= binEntryBudget_) entries += chunks_[end++].entryCount;
            fillBins(chunks_, group, end, framebuffer.tilesX(), framebuffer.tilesY(), bins_);
            if (through == DrawStage::Tiles) stats_.fragments += runBackEnd(framebuffer, constants, kernel);
            stats_.binEntries += entries;
            group = end;
        }
        for (size_t c = 0; c < chunkCount; ++c) {
            stats_.trianglesTriviallyRejected += chunkStats_[c].trianglesTriviallyRejected;
            stats_.trianglesClipped += chunkStats_[c].trianglesClipped;
            stats_.trianglesSetUp += chunks_[c].triangles.size();
        }
    }
    stats_.trianglesSubmitted += call.triangles.size();
}

}  // namespace shadowlab::raster
