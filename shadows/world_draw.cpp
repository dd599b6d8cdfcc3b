#include "shadows/world_draw.h"

#include <vector>

namespace shadowlab {
namespace {

// One draw's triangles: the solid ones by index, a cut-out's as corners of their own (a
// corner's texture coordinate belongs to the triangle, not to the shared vertex).
struct Batch {
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> ids;
    std::vector<glm::vec3> corners;
    std::vector<float> uvs;
};

void addCutOutTriangle(const WorldGeometry& world, uint32_t t, Batch& batch) {
    const uint32_t first = uint32_t(batch.corners.size());
    for (int c = 0; c < 3; ++c) {
        batch.corners.push_back(world.positions[world.triangles[t][c]]);
        const glm::vec2 uv = world.cornerUvs[3 * size_t(t) + size_t(c)];
        batch.uvs.insert(batch.uvs.end(), {uv.x, uv.y});
    }
    batch.triangles.emplace_back(first, first + 1, first + 2);
    batch.ids.push_back(t);
}

}  // namespace

void drawWorld(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const raster::PipelineState& state,
               const WorldGeometry& world, const glm::mat4& clipFromWorld, std::span<const uint32_t> only,
               const glm::vec4& constantColor) {
    if (world.cutOuts.empty() && only.empty()) {
        raster::DrawCall call = raster::positionsDraw(world.positions, world.triangles, clipFromWorld);
        call.constantColor = constantColor;
        rasterizer.draw(fb, state, call);
        return;
    }
    Batch solid;
    std::vector<Batch> cutOuts(world.cutOuts.size());
    const auto add = [&](uint32_t t) {
        const int32_t cutOut = world.triangleCutOut.empty() ? -1 : world.triangleCutOut[t];
        if (cutOut < 0) {
            solid.triangles.push_back(world.triangles[t]), solid.ids.push_back(t);
        } else {
            addCutOutTriangle(world, t, cutOuts[size_t(cutOut)]);
        }
    };
    if (only.empty()) {
        for (uint32_t t = 0; t < world.triangles.size(); ++t) add(t);
    } else {
        for (uint32_t t : only) add(t);
    }
    raster::DrawCall call = raster::positionsDraw(world.positions, solid.triangles, clipFromWorld);
    call.primitiveIds = solid.ids;
    call.constantColor = constantColor;
    rasterizer.draw(fb, state, call);
    for (size_t k = 0; k < cutOuts.size(); ++k) {
        const Batch& batch = cutOuts[k];
        if (batch.triangles.empty()) continue;
        const WorldGeometry::CutOut& cutOut = world.cutOuts[k];
        raster::PipelineState tested = state;
        tested.alphaTest = {cutOut.alpha.data(), cutOut.width, cutOut.height, cutOut.cutoff, cutOut.wrap};
        raster::DrawCall cutOutCall = raster::positionsDraw(batch.corners, batch.triangles, clipFromWorld);
        cutOutCall.vertices.varyings = batch.uvs;
        cutOutCall.vertices.varyingCount = 2;
        cutOutCall.primitiveIds = batch.ids;
        cutOutCall.constantColor = constantColor;
        rasterizer.draw(fb, tested, cutOutCall);
    }
}

}  // namespace shadowlab
