#include "shadows/world_draw.h"

namespace shadowlab {
namespace {

void addCutOutTriangle(const WorldGeometry& world, uint32_t t, WorldDraws::Batch& batch) {
    const uint32_t first = uint32_t(batch.corners.size());
    for (int c = 0; c < 3; ++c) {
        batch.corners.push_back(world.positions[world.triangles[t][c]]);
        const glm::vec2 uv = world.cornerUvs[3 * size_t(t) + size_t(c)];
        batch.uvs.insert(batch.uvs.end(), {uv.x, uv.y});
    }
    batch.triangles.emplace_back(first, first + 1, first + 2);
    batch.ids.push_back(t);
}

// The one kind of data a prepared scene keeps for drawWorld.
struct PreparedDraws {
    // Its cut-out batches hold copies of the world's corners.
    static constexpr DependsOn kDependsOn = DependsOn::WorldGeometry;
    WorldDraws draws;
};

}  // namespace

WorldDraws worldDraws(const WorldGeometry& world, std::span<const uint32_t> only) {
    WorldDraws draws;
    if (world.cutOuts.empty() && only.empty()) {
        draws.whole = true;
        return draws;
    }
    draws.cutOuts.resize(world.cutOuts.size());
    const auto add = [&](uint32_t t) {
        const int32_t cutOut = world.triangleCutOut.empty() ? -1 : world.triangleCutOut[t];
        if (cutOut < 0) {
            draws.solid.triangles.push_back(world.triangles[t]), draws.solid.ids.push_back(t);
        } else {
            addCutOutTriangle(world, t, draws.cutOuts[size_t(cutOut)]);
        }
    };
    if (only.empty()) {
        for (uint32_t t = 0; t < world.triangles.size(); ++t) add(t);
    } else {
        for (uint32_t t : only) add(t);
    }
    return draws;
}

const WorldDraws& preparedWorldDraws(const PreparedScene& prepared) {
    return prepared.derived<PreparedDraws>([&] { return PreparedDraws{worldDraws(prepared.world())}; }).draws;
}

void drawWorld(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const raster::PipelineState& state,
               const WorldGeometry& world, const WorldDraws& draws, const glm::mat4& clipFromWorld,
               const glm::vec4& constantColor) {
    if (draws.whole) {
        raster::DrawCall call = raster::positionsDraw(world.positions, world.triangles, clipFromWorld);
        call.constantColor = constantColor;
        rasterizer.draw(fb, state, call);
        return;
    }
    raster::DrawCall call = raster::positionsDraw(world.positions, draws.solid.triangles, clipFromWorld);
    call.primitiveIds = draws.solid.ids;
    call.constantColor = constantColor;
    rasterizer.draw(fb, state, call);
    for (size_t k = 0; k < draws.cutOuts.size(); ++k) {
        const WorldDraws::Batch& batch = draws.cutOuts[k];
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

void drawWorld(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const raster::PipelineState& state,
               const WorldGeometry& world, const glm::mat4& clipFromWorld, std::span<const uint32_t> only,
               const glm::vec4& constantColor) {
    drawWorld(rasterizer, fb, state, world, worldDraws(world, only), clipFromWorld, constantColor);
}

}  // namespace shadowlab
