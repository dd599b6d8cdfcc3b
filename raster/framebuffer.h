// Depth (float), stencil (8-bit), RGBA colour (float planes) and primitive-id buffers.
// Storage is block-linear (triangle_setup.h, FramebufferView); the *Image() accessors
// return ordinary row-major copies with row 0 at the top, as conventions.md requires.
//
// Clears are lazy: a clear records the value and marks every tile pending, and a draw
// fills a pending tile only when one of its tasks first writes that tile (a 2048^2 depth
// map is 16 MB, and many tiles of a shadow map see no triangle). Whatever reads the
// buffers from outside sees resolved values: the images read pending tiles as the clear
// value, and view() fills every pending tile before handing out the storage.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
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

// The pixel (x, y) at storage index `index` of a block-linear buffer tilesX tiles wide: the
// inverse of blockLinearIndex.
inline void blockLinearPixel(size_t index, int tilesX, int& x, int& y) {
    const size_t tile = index / kPixelsPerTile, inTile = index % kPixelsPerTile;
    const size_t block = inTile / kPixelsPerBlock, inBlock = inTile % kPixelsPerBlock;
    x = int(tile % size_t(tilesX)) * kTileSize + int(block % kBlocksPerTileSide) * kBlockSize + int(inBlock % kBlockSize);
    y = int(tile / size_t(tilesX)) * kTileSize + int(block / kBlocksPerTileSide) * kBlockSize + int(inBlock / kBlockSize);
}

// The row-major index (y width + x) of the pixel at block-linear storage index `index`:
// where a fragment list's pixel lands in an image.
inline size_t rowMajorIndexOf(size_t index, int tilesX, int width) {
    int x = 0, y = 0;
    blockLinearPixel(index, tilesX, x, y);
    return size_t(y) * size_t(width) + size_t(x);
}

// An allocator whose new elements are left uninitialised (default-initialised). A lazily
// cleared buffer fills every tile before anything reads it, so zeroing its fresh storage
// first would cost a pass over memory for nothing: 16 MiB, about 1.5 ms on one core, for
// a 2048^2 depth map drawn every frame.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template <class U>
    UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) { ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...); }
};

// The storage of a framebuffer's buffers (and of the depth a shadow map keeps).
template <class T>
using BufferStorage = std::vector<T, UninitializedAllocator<T>>;

// One block-linear buffer with a per-tile pending clear.
// The memory of a framebuffer's buffers, handed from one framebuffer (release()) to the next
// of the same kind so that a frame in a steady state draws without allocating them again
// (shadows/technique_history.h). Its values are stale: the framebuffer made from it clears
// every buffer as a new one would. A buffer of another size is resized (reallocated only to
// grow), one the framebuffer does not attach is dropped.
struct FramebufferStorage {
    BufferStorage<float> depth = {};
    BufferStorage<uint8_t> stencil = {};
    BufferStorage<float> color[4] = {};
    BufferStorage<uint32_t> primitiveId = {};
};

template <class T>
class LazyClearedBuffer {
public:
    // `tiles` tiles cleared to `value`, in `memory` (FramebufferStorage) where it is given.
    void allocate(size_t tiles, T value, BufferStorage<T> memory = {});
    bool empty() const { return data_.empty(); }
    void clear(T value);
    // Fills the tile if its clear is pending; during a draw only the tile's task calls it.
    void fillTile(size_t tile);
    // The storage with every pending tile filled (in parallel): the only way out for the
    // data as a whole, so nothing leaves the framebuffer unresolved.
    BufferStorage<T>& resolved();
    // The storage as it is, pending tiles unfilled: for the rasterizer, which calls
    // fillTile before writing a tile.
    T* unresolvedData() { return data_.empty() ? nullptr : data_.data(); }
    // Copies `count` values from storage index `from` (all in one tile), reading a
    // pending tile as its clear value.
    void copyRun(size_t from, size_t count, T* out) const;
    // The memory, unresolved, for a later buffer; this one is empty afterwards.
    BufferStorage<T> release() { return std::move(data_); }

private:
    BufferStorage<T> data_;
    std::vector<uint8_t> pending_;   // per tile: 1 while the tile still holds stale data
    T value_{};
};

struct Attachments {
    bool stencil = false;
    bool color = false;         // four float planes R, G, B, A
    bool primitiveId = false;
    bool fragments = false;     // a list of fragments per tile (FragmentOutput::FragmentList)
};

class Framebuffer {
public:
    // Cleared to depth 1, stencil 0, colour 0 and primitive id 0, in `memory` where it is
    // given (an earlier framebuffer's release()). Throws std::invalid_argument unless
    // 1 <= width, height <= kMaxViewport.
    Framebuffer(int width, int height, Attachments attachments = {}, FramebufferStorage memory = {});

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
    // The storage, every pending clear resolved first.
    FramebufferView view();

    std::vector<float> depthImage() const;
    // The depth buffer itself, block-linear (index()), resolved and moved out without a
    // copy; the framebuffer has no depth afterwards.
    BufferStorage<float> takeDepth() { return std::move(depth_.resolved()); }
    // A colour plane likewise (0 = R); the framebuffer has no such plane afterwards.
    BufferStorage<float> takeColor(int channel) { return std::move(color_[channel].resolved()); }
    // The memory of every buffer (but the fragment lists) for a later framebuffer, which
    // clears it; this one is left empty.
    FramebufferStorage release() &&;
    std::vector<uint8_t> stencilImage() const;
    // The stencil buffer itself, block-linear (index()), its pending tiles resolved and no
    // other buffer's: to read in place, without the copy stencilImage() makes.
    const BufferStorage<uint8_t>& stencil() { return stencil_.resolved(); }
    std::vector<float> colorImage(int channel) const;
    std::vector<uint32_t> primitiveIdImage() const;
    // The fragments drawn into tile t (row-major over tiles) since the last clear, in the
    // order they were drawn; each fragment's pixel is a storage index (index()).
    std::span<const Fragment> tileFragments(int tile) const;
    void clearFragments();

private:
    // The rasterizer writes tiles through the unresolved storage, filling each pending
    // tile it is about to touch.
    friend class Rasterizer;
    FramebufferView unresolvedView();
    void fillPendingTile(int tile);

    template <class T> std::vector<T> rowMajor(const LazyClearedBuffer<T>& buffer) const;

    int width_, height_, tilesX_, tilesY_;
    Attachments attachments_;
    LazyClearedBuffer<float> depth_;
    LazyClearedBuffer<uint8_t> stencil_;
    LazyClearedBuffer<float> color_[4];
    LazyClearedBuffer<uint32_t> primitiveId_;
    // The tiles' fragment lists: each sink's array is malloc'ed and grown by growSink.
    struct FreeSinks {
        void operator()(std::vector<FragmentSink>* sinks) const;
    };
    std::unique_ptr<std::vector<FragmentSink>, FreeSinks> fragments_;
};

}  // namespace shadowlab::raster
