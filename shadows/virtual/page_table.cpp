#include "shadows/virtual/page_table.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

namespace shadowlab::vsm {
namespace {

// x mod n in [0, n) for any sign of x, n a power of two (every layout's page count is: the
// constructor checks): the low bits of two's complement, no division per request.
int32_t wrap(int32_t x, int n) { return x & (n - 1); }

}  // namespace

PageLayout PageLayout::of(const ClipmapSettings& clipmap) {
    checkClipmapSettings(clipmap);
    return {clipmap.firstLevel, std::vector<int>(size_t(clipmap.levelCount()), clipmap.pagesPerSide())};
}

PageTable::PageTable(const ClipmapSettings& settings, int poolPages) : PageTable(PageLayout::of(settings), poolPages) {}

PageTable::PageTable(const PageLayout& layout, int poolPages) : layout_(layout) {
    if (poolPages < 1 || poolPages > (1 << 20))
        throw std::invalid_argument("virtual shadow map: pool-pages must be in 1..1048576, got " +
                                    std::to_string(poolPages));
    firstSlot_.push_back(0);
    for (int n : layout.pagesPerSide) {
        if (n < 1 || (n & (n - 1)) != 0)
            throw std::logic_error("PageTable: a level's pages a side must be a power of two, got " + std::to_string(n));
        firstSlot_.push_back(firstSlot_.back() + size_t(n) * size_t(n));
    }
    slots_.resize(firstSlot_.back());
    requestedNow_.assign(slots_.size(), 0);
    owner_.assign(size_t(poolPages), -1);
    lastRequested_.assign(size_t(poolPages), 0);
    // Taken from the back: physical page 0 first.
    for (int32_t p = poolPages - 1; p >= 0; --p) free_.push_back(p);
}

size_t PageTable::slotIndex(const PageKey& key) const {
    const size_t l = size_t(key.level - layout_.firstLevel);
    const int n = layout_.pagesPerSide[l];
    return firstSlot_[l] + size_t(wrap(key.y, n)) * size_t(n) + size_t(wrap(key.x, n));
}

PageKey PageTable::windowPage(size_t slot) const {
    const size_t l = size_t(std::upper_bound(firstSlot_.begin(), firstSlot_.end(), slot) - firstSlot_.begin()) - 1;
    const int n = layout_.pagesPerSide[l];
    const LevelWindow& w = windows_[l];
    const int32_t sx = int32_t((slot - firstSlot_[l]) % size_t(n)), sy = int32_t((slot - firstSlot_[l]) / size_t(n));
    // The one page of the window in this slot: the window's first page plus how far the slot
    // lies past the first page's slot, round the torus.
    return {w.level, w.firstX + wrap(sx - wrap(w.firstX, n), n), w.firstY + wrap(sy - wrap(w.firstY, n), n)};
}

const PageTable::Slot* PageTable::holding(const PageKey& key) const {
    if (!holdsLevel(key.level)) return nullptr;
    const Slot& slot = slots_[slotIndex(key)];
    return slot.physical != kNoPhysicalPage && slot.key == key ? &slot : nullptr;
}

void PageTable::beginFrame(const std::vector<LevelWindow>& windows) {
    if (int(windows.size()) != layout_.levelCount())
        throw std::logic_error("PageTable::beginFrame: one window per level");
    windows_ = windows;
    ++frame_;
    std::fill(requestedNow_.begin(), requestedNow_.end(), uint8_t(0));
    overflow_ = 0;
    evictedNow_.clear();
}

void PageTable::request(const PageKey& key) {
    std::atomic_ref<uint8_t>(requestedNow_[slotIndex(key)]).store(1, std::memory_order_relaxed);
}

bool PageTable::requested(const PageKey& key) const {
    if (windows_.empty() || !holdsLevel(key.level)) return false;
    const size_t slot = slotIndex(key);
    return requestedNow_[slot] && windowPage(slot) == key;
}

size_t PageTable::requestedPages() const {
    return size_t(std::count(requestedNow_.begin(), requestedNow_.end(), uint8_t(1)));
}

void PageTable::release(Slot& slot) {
    if (slot.physical != kNoPhysicalPage) {
        owner_[size_t(slot.physical)] = -1;
        free_.push_back(slot.physical);
    }
    slot.physical = kNoPhysicalPage;
    slot.valid = false;
}

int32_t PageTable::takePhysicalPage() {
    if (!free_.empty()) {
        const int32_t p = free_.back();
        free_.pop_back();
        return p;
    }
    // The least recently requested page not requested this frame; the lowest index on a tie.
    int32_t victim = kNoPhysicalPage;
    for (int32_t p = 0; p < int32_t(owner_.size()); ++p) {
        if (lastRequested_[size_t(p)] == frame_) continue;
        if (victim == kNoPhysicalPage || lastRequested_[size_t(p)] < lastRequested_[size_t(victim)]) victim = p;
    }
    if (victim == kNoPhysicalPage) return victim;
    Slot& evicted = slots_[size_t(owner_[size_t(victim)])];
    evictedNow_.push_back(evicted.key);
    evicted.physical = kNoPhysicalPage;
    evicted.valid = false;
    owner_[size_t(victim)] = -1;
    return victim;
}

std::vector<PageKey> PageTable::allocate() {
    // First every requested page that has memory is marked as in use this frame, so that
    // making room for the others never evicts one of them.
    for (size_t s = 0; s < slots_.size(); ++s) {
        if (!requestedNow_[s]) continue;
        Slot& slot = slots_[s];
        const PageKey key = windowPage(s);
        if (slot.physical != kNoPhysicalPage && slot.key != key) release(slot);   // a page the window left
        slot.key = key;
        if (slot.physical != kNoPhysicalPage) lastRequested_[size_t(slot.physical)] = frame_;
    }
    std::vector<PageKey> toRender;
    for (int level = layout_.levelCount() - 1; level >= 0; --level) {
        for (size_t s = firstSlot_[size_t(level)]; s < firstSlot_[size_t(level) + 1]; ++s) {
            if (!requestedNow_[s]) continue;
            Slot& slot = slots_[s];
            if (slot.physical == kNoPhysicalPage) {
                slot.physical = takePhysicalPage();
                if (slot.physical == kNoPhysicalPage) {
                    ++overflow_;
                    continue;
                }
                owner_[size_t(slot.physical)] = int64_t(s);
                lastRequested_[size_t(slot.physical)] = frame_;
                slot.valid = false;
            }
            if (!slot.valid) toRender.push_back(slot.key);
        }
    }
    return toRender;
}

void PageTable::markRendered(const PageKey& key) {
    Slot& slot = slots_[slotIndex(key)];
    if (slot.physical == kNoPhysicalPage || slot.key != key)
        throw std::logic_error("PageTable::markRendered: the page has no memory");
    slot.valid = true;
}

void PageTable::invalidate(const PageKey& key) {
    if (holding(key)) slots_[slotIndex(key)].valid = false;
}

int PageTable::invalidateBox(int level, int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
    const size_t l = size_t(level - layout_.firstLevel);
    int invalidated = 0;
    for (size_t s = firstSlot_[l]; s < firstSlot_[l + 1]; ++s) {
        Slot& slot = slots_[s];
        const bool inside = slot.key.x >= x0 && slot.key.x <= x1 && slot.key.y >= y0 && slot.key.y <= y1;
        if (slot.physical == kNoPhysicalPage || !slot.valid || !inside) continue;
        slot.valid = false;
        ++invalidated;
    }
    return invalidated;
}

void PageTable::invalidateAll() {
    for (Slot& slot : slots_) slot.valid = false;
}

int32_t PageTable::physical(const PageKey& key) const {
    const Slot* slot = holding(key);
    return slot ? slot->physical : kNoPhysicalPage;
}

bool PageTable::valid(const PageKey& key) const {
    const Slot* slot = holding(key);
    return slot && slot->valid;
}

int PageTable::residentPages() const { return int(owner_.size() - free_.size()); }

}  // namespace shadowlab::vsm
