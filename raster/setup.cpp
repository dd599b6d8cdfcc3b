#include "raster/setup.h"

namespace shadowlab::raster {

SetupConstants setupConstants(int width, int height, const PipelineState& state, int varyingCount) {
    const bool interpolates = state.output == FragmentOutput::VaryingColor || state.alphaTest.alpha;
    const int planeCount = interpolates ? 1 + varyingCount : 0;
    const ViewportWindow& w = state.window;
    return {width,
            height,
            w.x,
            w.y,
            w.viewportWidth ? w.viewportWidth : width,
            w.viewportWidth ? w.viewportHeight : height,
            state.cull,
            state.conservative,
            state.offset,
            planeCount};
}

SetupQueue::SetupQueue(SetupKernel kernel, const SetupConstants& constants, SetupChunk& chunk)
    : kernel_(kernel), constants_(constants), chunk_(chunk) {}

void SetupQueue::push(const SetupVertex (&corners)[3], const Primitive& primitive) {
    const int t = batch_.count;
    for (int k = 0; k < 3; ++k) {
        const WindowVertex& w = corners[k].window;
        batch_.x[k][t] = w.x, batch_.y[k][t] = w.y, batch_.z[k][t] = w.z, batch_.inverseW[k][t] = w.inverseW;
        for (int v = 0; v + 1 < constants_.planeCount; ++v) batch_.varyings[v][k][t] = corners[k].varyings[v];
    }
    batch_.maxDepth[t] = primitive.maxDepth;
    batch_.primitiveId[t] = primitive.id;
    if (++batch_.count == kSetupBatchSize) flush();
}

void SetupQueue::flush() {
    if (batch_.count == 0) return;
    kernel_(batch_, constants_, output_);
    batch_.count = 0;
    chunk_.triangles.insert(chunk_.triangles.end(), output_.triangles, output_.triangles + output_.count);
    if (constants_.planeCount == 0) return;
    for (int k = 0; k < output_.count; ++k) {
        chunk_.planeStart.push_back(uint32_t(chunk_.planes.size()));
        chunk_.planes.insert(chunk_.planes.end(), output_.planes[k], output_.planes[k] + constants_.planeCount);
    }
}

}  // namespace shadowlab::raster
