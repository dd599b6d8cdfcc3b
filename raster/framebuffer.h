// Depth (float), stencil (8-bit), RGBA colour (float planes) and primitive-id buffers.
// Storage is block-linear (triangle_setup.h, FramebufferView); the *Image() accessors
// return ordinary row-major copies with row 0 at the top, as conventions.md requires.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/triangle_setup.h"

namespace shadowlab::raster {

// Storage index of pixel (x, y) in a block-linear buffer tilesX tiles wide (FramebufferView).
inline size_t blockLinearIndex(int x, int y, int tilesX) {
    const size_t tile = size_t(y >> kTileShift) * size_t(tilesX) + size_t(x >> kTileShift);
    const int blockX = (x >> kBlockShift) & (kBlocksPerTileSide - 1);
    const int blockY = (y >> kBlockShift) & (kBlocksPerTileSide - 1);
    const int inBlock = (y & (kBlockSize - 1)) * kBlockSize + (x & (kBlockSize - 1));
    return tile * kPixelsPerTile + size_t(blockY * kBlocksPerTileSide + blockX) * kPixelsPerBlock + size_t(inBlock);
}

struct Attachments {
    bool stencil = false;
    bool color = false;         // four float planes R, G, B, A
    bool primitiveId = false;
};

class Framebuffer {
public:
    // Cleared to depth 1, stencil 0, colour 0 and primitive id 0. Throws
    // std::invalid_argument unless 1 <= width, height <= kMaxViewport.
    Framebuffer(int width, int height, Attachments attachments = {});

    int width() const { return width_; }
    int height() const { return height_; }
    int tilesX() const { return tilesX_; }
    int tilesY() const { return tilesY_; }
    const Attachments& attachments() const { return attachments_; }

    void clearDepth(float value);
    void clearStencil(uint8_t value);
    void clearColor(const glm::vec4& value);
    void clearPrimitiveId(uint32_t value);

    // Storage index of pixel (x, y).
    size_t index(int x, int y) const { return blockLinearIndex(x, y, tilesX_); }
    FramebufferView view();

    std::vector<float> depthImage() const;
    // The depth buffer itself, block-linear (index()), moved out without a copy; the
    // framebuffer has no depth afterwards.
    std::vector<float> takeDepth() { return std::move(depth_); }
    std::vector<uint8_t> stencilImage() const;
    std::vector<float> colorImage(int channel) const;
    std::vector<uint32_t> primitiveIdImage() const;

private:
    template <class T> std::vector<T> rowMajor(const std::vector<T>& blockLinear) const;

    int width_, height_, tilesX_, tilesY_;
    Attachments attachments_;
    std::vector<float> depth_;
    std::vector<uint8_t> stencil_;
    std::vector<float> color_[4];
    std::vector<uint32_t> primitiveId_;
};

}  // namespace shadowlab::raster
