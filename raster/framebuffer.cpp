#include "raster/framebuffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

namespace shadowlab::raster {

Framebuffer::Framebuffer(int width, int height, Attachments attachments)
    : width_(width), height_(height), attachments_(attachments) {
    if (width < 1 || height < 1 || width > kMaxViewport || height > kMaxViewport) {
        throw std::invalid_argument("framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " is outside 1.." + std::to_string(kMaxViewport));
    }
    tilesX_ = (width + kTileSize - 1) / kTileSize;
    tilesY_ = (height + kTileSize - 1) / kTileSize;
    const size_t storage = size_t(tilesX_) * size_t(tilesY_) * kPixelsPerTile;
    depth_.assign(storage, 1.0f);
    if (attachments.stencil) stencil_.assign(storage, 0);
    if (attachments.color) {
        for (auto& plane : color_) plane.assign(storage, 0.0f);
    }
    if (attachments.primitiveId) primitiveId_.assign(storage, 0);
}

void Framebuffer::clearDepth(float value) { std::fill(depth_.begin(), depth_.end(), value); }
void Framebuffer::clearStencil(uint8_t value) { std::fill(stencil_.begin(), stencil_.end(), value); }
void Framebuffer::clearPrimitiveId(uint32_t value) { std::fill(primitiveId_.begin(), primitiveId_.end(), value); }
void Framebuffer::clearColor(const glm::vec4& value) {
    for (int c = 0; c < 4; ++c) std::fill(color_[c].begin(), color_[c].end(), value[c]);
}

FramebufferView Framebuffer::view() {
    auto dataOrNull = [](auto& v) { return v.empty() ? nullptr : v.data(); };
    return {width_, height_, tilesX_, depth_.data(), dataOrNull(stencil_),
            {dataOrNull(color_[0]), dataOrNull(color_[1]), dataOrNull(color_[2]), dataOrNull(color_[3])},
            dataOrNull(primitiveId_)};
}

template <class T>
std::vector<T> Framebuffer::rowMajor(const std::vector<T>& blockLinear) const {
    if (blockLinear.empty()) throw std::logic_error("framebuffer has no such attachment");
    std::vector<T> image(size_t(width_) * size_t(height_));
    // A block's row of 8 pixels is contiguous in both layouts; rows are copied in parallel.
    tbb::parallel_for(0, height_, [&](int y) {
        for (int x = 0; x < width_; x += kBlockSize) {
            std::copy_n(blockLinear.begin() + ptrdiff_t(index(x, y)), std::min(kBlockSize, width_ - x),
                        image.begin() + ptrdiff_t(size_t(y) * size_t(width_) + size_t(x)));
        }
    });
    return image;
}

std::vector<float> Framebuffer::depthImage() const { return rowMajor(depth_); }
std::vector<uint8_t> Framebuffer::stencilImage() const { return rowMajor(stencil_); }
std::vector<float> Framebuffer::colorImage(int channel) const { return rowMajor(color_[channel]); }
std::vector<uint32_t> Framebuffer::primitiveIdImage() const { return rowMajor(primitiveId_); }

}  // namespace shadowlab::raster
