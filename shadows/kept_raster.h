// What a stage keeps of the rasterizer between the frames of a sequence (technique_history.h),
// so that a frame in a steady state allocates no framebuffer and no front-end buffers:
//
//   KeptFramebuffer  a framebuffer made in the memory the stage's last frame left
//                    (raster::FramebufferStorage), handing its memory back when it goes;
//   KeptRasterizer   the rasterizer itself, whose vertices, set-up chunks and bins keep
//                    their memory from draw to draw.
//
// The stage keeps them as states of its own types, so no two stages of a technique share one:
//
//   struct StencilBuffers { raster::FramebufferStorage memory; KeptRasterizer rasterizer; };
//   StencilBuffers& kept = in.kept().state<StencilBuffers>();
//   KeptFramebuffer fb(kept.memory, width, height, attachments);
//   kept.rasterizer.at(in.simd).draw(*fb, ...);
//
// The framebuffer is cleared as a new one would be, whatever the memory held, and the
// rasterizer's buffers are rewritten by every draw, so the bytes drawn never depend on the
// frames before; a size other than last frame's resizes the memory.
#pragma once

#include <optional>
#include <utility>

#include "raster/framebuffer.h"
#include "raster/rasterizer.h"

namespace shadowlab {

class KeptFramebuffer {
public:
    KeptFramebuffer(raster::FramebufferStorage& memory, int width, int height, raster::Attachments attachments = {})
        : memory_(memory), framebuffer_(width, height, attachments, std::move(memory)) {}
    ~KeptFramebuffer() { memory_ = std::move(framebuffer_).release(); }
    KeptFramebuffer(const KeptFramebuffer&) = delete;
    KeptFramebuffer& operator=(const KeptFramebuffer&) = delete;

    raster::Framebuffer& operator*() { return framebuffer_; }
    raster::Framebuffer* operator->() { return &framebuffer_; }

private:
    raster::FramebufferStorage& memory_;
    raster::Framebuffer framebuffer_;
};

struct KeptRasterizer {
    // The rasterizer at `simd`, its stats reset as a new one's; made anew only when the
    // level differs from the kept one's.
    raster::Rasterizer& at(raster::SimdLevel simd) {
        if (!rasterizer || rasterizer->simdLevel() != simd) rasterizer.emplace(simd);
        rasterizer->resetStats();
        return *rasterizer;
    }
    std::optional<raster::Rasterizer> rasterizer;
};

}  // namespace shadowlab
