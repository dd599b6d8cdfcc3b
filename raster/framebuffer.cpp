#include "raster/framebuffer.h"

#include <algorithm>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

namespace shadowlab::raster {
namespace {

// Doubles a tile's fragment array (FragmentSink::grow), in baseline code: the per-ISA
// kernels call it through the pointer rather than instantiating an allocator of their own.
void growSink(FragmentSink& sink) {
    const uint32_t capacity = sink.capacity == 0 ? 1024 : 2 * sink.capacity;
    if (capacity < sink.capacity) throw std::length_error("a tile holds more than 2^32 fragments");
    auto* grown = static_cast<Fragment*>(std::realloc(sink.data, size_t(capacity) * sizeof(Fragment)));
    if (!grown) throw std::bad_alloc();
    sink.data = grown, sink.capacity = capacity;
}

}  // namespace

template <class T>
void LazyClearedBuffer<T>::allocate(size_t tiles, T value, BufferStorage<T> memory) {
    data_ = std::move(memory);
    data_.resize(tiles * kPixelsPerTile);
    pending_.resize(tiles);
    clear(value);
}

template <class T>
void LazyClearedBuffer<T>::clear(T value) {
    value_ = value;
    std::fill(pending_.begin(), pending_.end(), uint8_t(1));
}

template <class T>
void LazyClearedBuffer<T>::fillTile(size_t tile) {
    if (pending_.empty() || !pending_[tile]) return;
    std::fill_n(data_.begin() + ptrdiff_t(tile * kPixelsPerTile), kPixelsPerTile, value_);
    pending_[tile] = 0;
}

template <class T>
BufferStorage<T>& LazyClearedBuffer<T>::resolved() {
    tbb::parallel_for(size_t(0), pending_.size(), [&](size_t tile) { fillTile(tile); });
    return data_;
}

template <class T>
void LazyClearedBuffer<T>::copyRun(size_t from, size_t count, T* out) const {
    if (pending_[from / kPixelsPerTile]) {
        std::fill_n(out, count, value_);
    } else {
        std::copy_n(data_.begin() + ptrdiff_t(from), count, out);
    }
}

template class LazyClearedBuffer<float>;
template class LazyClearedBuffer<uint8_t>;
template class LazyClearedBuffer<uint32_t>;

Framebuffer::Framebuffer(int width, int height, Attachments attachments, FramebufferStorage memory)
    : width_(width), height_(height), attachments_(attachments) {
    if (width < 1 || height < 1 || width > kMaxViewport || height > kMaxViewport) {
        throw std::invalid_argument("framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " is outside 1.." + std::to_string(kMaxViewport));
    }
    tilesX_ = (width + kTileSize - 1) / kTileSize;
    tilesY_ = (height + kTileSize - 1) / kTileSize;
    const size_t tiles = size_t(tilesX_) * size_t(tilesY_);
    depth_.allocate(tiles, 1.0f, std::move(memory.depth));
    if (attachments.stencil) stencil_.allocate(tiles, 0, std::move(memory.stencil));
    if (attachments.color) {
        for (int c = 0; c < 4; ++c) color_[c].allocate(tiles, 0.0f, std::move(memory.color[c]));
    }
    if (attachments.primitiveId) primitiveId_.allocate(tiles, 0, std::move(memory.primitiveId));
    if (attachments.fragments) {
        fragments_.reset(new std::vector<FragmentSink>(tiles, FragmentSink{nullptr, 0, 0, growSink}));
    }
}

void Framebuffer::FreeSinks::operator()(std::vector<FragmentSink>* sinks) const {
    for (FragmentSink& sink : *sinks) std::free(sink.data);
    delete sinks;
}

std::span<const Fragment> Framebuffer::tileFragments(int tile) const {
    if (!fragments_) throw std::logic_error("framebuffer has no fragment lists");
    if (tile < 0 || size_t(tile) >= fragments_->size()) throw std::out_of_range("tileFragments: no tile " + std::to_string(tile));
    const FragmentSink& sink = (*fragments_)[size_t(tile)];
    return {sink.data, sink.size};
}

void Framebuffer::clearFragments() {
    if (!fragments_) return;
    for (FragmentSink& sink : *fragments_) sink.size = 0;
}

FramebufferStorage Framebuffer::release() && {
    return {depth_.release(),
            stencil_.release(),
            {color_[0].release(), color_[1].release(), color_[2].release(), color_[3].release()},
            primitiveId_.release()};
}

void Framebuffer::clearDepth(float value) { depth_.clear(value); }
void Framebuffer::clearStencil(uint8_t value) { stencil_.clear(value); }
void Framebuffer::clearPrimitiveId(uint32_t value) { primitiveId_.clear(value); }
void Framebuffer::clearColor(const glm::vec4& value) {
    for (int c = 0; c < 4; ++c) color_[c].clear(value[c]);
}

FramebufferView Framebuffer::view() {
    depth_.resolved(), stencil_.resolved(), primitiveId_.resolved();
    for (auto& plane : color_) plane.resolved();
    return unresolvedView();
}

FramebufferView Framebuffer::unresolvedView() {
    return {width_, height_, tilesX_, depth_.unresolvedData(), stencil_.unresolvedData(),
            {color_[0].unresolvedData(), color_[1].unresolvedData(), color_[2].unresolvedData(), color_[3].unresolvedData()},
            primitiveId_.unresolvedData(), fragments_ ? fragments_->data() : nullptr};
}

void Framebuffer::fillPendingTile(int tile) {
    depth_.fillTile(size_t(tile)), stencil_.fillTile(size_t(tile)), primitiveId_.fillTile(size_t(tile));
    for (auto& plane : color_) plane.fillTile(size_t(tile));
}

template <class T>
std::vector<T> Framebuffer::rowMajor(const LazyClearedBuffer<T>& buffer) const {
    if (buffer.empty()) throw std::logic_error("framebuffer has no such attachment");
    std::vector<T> image(size_t(width_) * size_t(height_));
    // A block's row of 8 pixels is contiguous in both layouts; rows are copied in parallel.
    tbb::parallel_for(0, height_, [&](int y) {
        for (int x = 0; x < width_; x += kBlockSize) {
            buffer.copyRun(index(x, y), size_t(std::min(kBlockSize, width_ - x)),
                           image.data() + size_t(y) * size_t(width_) + size_t(x));
        }
    });
    return image;
}

std::vector<float> Framebuffer::depthImage() const { return rowMajor(depth_); }
std::vector<uint8_t> Framebuffer::stencilImage() const { return rowMajor(stencil_); }
std::vector<float> Framebuffer::colorImage(int channel) const { return rowMajor(color_[channel]); }
std::vector<uint32_t> Framebuffer::primitiveIdImage() const { return rowMajor(primitiveId_); }

}  // namespace shadowlab::raster
