// The page table of a virtual shadow map and its physical page pool (docs/virtual-shadow-
// maps.md): which pages of the virtual map have memory, which of those hold a depth that
// is still right (valid), and which page to give up when the pool is full.
//
// The table of a level is n^2 slots (n its pages a side: the same for every level of a
// clipmap, halving from mip to mip of a local light's face, PageLayout) addressed
// toroidally, slot (px mod n, py mod n) for page (px, py), each tagged with the page it
// holds: a level's window spans n pages a side, so no two pages of one window share a slot,
// and a window that pans keeps every page it still covers in its slot (the clipmap's
// toroidal update, Tanner et al. 1998). A mip's window is the whole mip, at page (0, 0).
//
// A frame: beginFrame() with the levels' windows, request() every page a lookup will read
// (page_marking.h; only pages inside their level's window), then allocate(), which gives every requested page without memory a physical page, taking a
// free one or else evicting the least recently requested page (never one requested this
// frame), and returns the requested pages that must be rendered: those not valid. After
// rendering them, markRendered(). A page stays valid until invalidate() (a caster moved
// over it, page_invalidation.h) or its slot is taken by another page.
//
// Every step runs in a fixed order (levels, then rows, then columns), so the pages chosen,
// evicted and rendered are the same for any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "shadows/virtual/clipmap.h"

namespace shadowlab::vsm {

inline constexpr int32_t kNoPhysicalPage = -1;

// The levels a table holds: level firstLevel + i has pagesPerSide[i] pages a side in its
// window (a clipmap's levels, or a local light's faces' mips, mip_chain.h).
struct PageLayout {
    int firstLevel = 0;
    std::vector<int> pagesPerSide;

    static PageLayout of(const ClipmapSettings& clipmap);
    int levelCount() const { return int(pagesPerSide.size()); }
    bool operator==(const PageLayout&) const = default;
};

class PageTable {
public:
    // `poolPages` physical pages of pageTexels^2 texels each.
    PageTable(const ClipmapSettings& settings, int poolPages);
    PageTable(const PageLayout& layout, int poolPages);
    const PageLayout& layout() const { return layout_; }

    // The levels' windows this frame, one per level from the first.
    void beginFrame(const std::vector<LevelWindow>& windows);
    const std::vector<LevelWindow>& windows() const { return windows_; }
    // Page `key`, inside its level's window, will be read this frame. Safe to call from many
    // threads at once: it sets a flag.
    void request(const PageKey& key);
    bool requested(const PageKey& key) const;
    size_t requestedPages() const;   // this frame's, so far

    // Gives memory to the requested pages, coarse levels first (so that a full pool drops
    // fine pages, never the coarse ones a lookup falls back to), and returns the requested
    // pages that are not valid, in order. A page that finds no memory (every physical page
    // requested this frame) is counted in overflowPages() and left without.
    std::vector<PageKey> allocate();
    void markRendered(const PageKey& key);
    void invalidate(const PageKey& key);   // no effect on a page the table does not hold
    // Invalidates every page the table holds at `level` within pages [x0, x1] x [y0, y1]
    // (in the window or not: a page the window left may come back); returns how many were
    // valid.
    int invalidateBox(int level, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
    void invalidateAll();

    // The physical page holding `key`, or kNoPhysicalPage; valid(): and its depth is current.
    int32_t physical(const PageKey& key) const;
    bool valid(const PageKey& key) const;

    // This frame's figures.
    int overflowPages() const { return overflow_; }
    int evictedPages() const { return int(evictedNow_.size()); }
    const std::vector<PageKey>& evictedThisFrame() const { return evictedNow_; }   // in eviction order
    int residentPages() const;
    int poolPages() const { return int(owner_.size()); }

private:
    struct Slot {
        PageKey key;
        int32_t physical = kNoPhysicalPage;
        bool valid = false;
    };
    bool holdsLevel(int level) const { return level >= layout_.firstLevel && level - layout_.firstLevel < layout_.levelCount(); }
    size_t slotIndex(const PageKey& key) const;
    const Slot* holding(const PageKey& key) const;   // the slot, if it holds key
    PageKey windowPage(size_t slot) const;           // the page of this frame's window at a slot
    int32_t takePhysicalPage();                      // free, else least recently requested; or none
    void release(Slot& slot);

    PageLayout layout_;
    std::vector<size_t> firstSlot_;        // per level, and the slot count at the end
    std::vector<LevelWindow> windows_;
    std::vector<Slot> slots_;              // per level, its pagesPerSide^2
    std::vector<uint8_t> requestedNow_;    // per slot, this frame
    std::vector<int64_t> owner_;           // per physical page: its slot, or -1 (free)
    std::vector<uint64_t> lastRequested_;  // per physical page: the frame it was last requested in
    std::vector<int32_t> free_;            // physical pages without a slot, taken from the back
    uint64_t frame_ = 0;
    int overflow_ = 0;
    std::vector<PageKey> evictedNow_;      // the pages whose memory this frame took
};

}  // namespace shadowlab::vsm
