// Irregular z-buffer, stage 3: the per-texel lists of receivers (Johnson et al. 2005;
// RTR4 Figure 7.30, lower left: "for each texel a list of all dots inside its grid cell").
//
// Built as a counting sort rather than as linked lists with atomic heads (as the GPU
// versions in RTR4 7.9 do), because the order of an atomic list depends on timing: count
// the receivers per texel, turn the counts into offsets by an exclusive prefix sum, then
// place each receiver at its texel's next free slot, in receiver order. Every list is
// therefore sorted by pixel, whatever the number of threads; the passes are linear, and
// parallel (by chunks of receivers, then by tiles of texels: countingSort).
//
// The traversal then reads the receivers of a texel, and of a row of texels, as one run:
// listReceivers() copies them in list order (Johnson et al. 2005 keep each sample's data in
// the list node for the same reason), which turns its scattered loads into streams.
#include <algorithm>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadows/izb/izb.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {

namespace {

// The sort runs in two levels so that every pass is parallel and none needs a count array
// per task as long as the keys: items are first sorted by group (kKeysPerGroup consecutive
// keys; a tile's texels are one group), chunk by chunk, then each group by key on its own.
// Both levels are stable, so the buckets are the serial sort's, entry for entry.
constexpr size_t kKeysPerGroup = size_t(kTileSize) * kTileSize;
constexpr size_t kItemsPerChunk = 16384;

struct Chunks {
    size_t items, count;
    size_t begin(size_t c) const { return c * kItemsPerChunk; }
    size_t end(size_t c) const { return std::min(items, (c + 1) * kItemsPerChunk); }
};

// slot[c * groups + g]: where chunk c's first item of group g goes in group order, so that
// the groups follow one another and, inside one, the chunks do (an exclusive prefix sum
// over (group, chunk)); groupFirst[g]: where group g begins, groupFirst[groups] = items.
void groupSlots(std::span<const uint32_t> key, const Chunks& chunks, size_t groups, std::vector<uint32_t>& slot,
                std::vector<uint32_t>& groupFirst) {
    slot.assign(chunks.count * groups, 0);
    tbb::parallel_for(size_t(0), chunks.count, [&](size_t c) {
        for (size_t item = chunks.begin(c); item < chunks.end(c); ++item) ++slot[c * groups + key[item] / kKeysPerGroup];
    });
    groupFirst.resize(groups + 1);
    uint32_t running = 0;
    for (size_t g = 0; g < groups; ++g) {
        groupFirst[g] = running;
        for (size_t c = 0; c < chunks.count; ++c) running += std::exchange(slot[c * groups + g], running);
    }
    groupFirst[groups] = running;
}

// One group's items, already in item order, sorted by key into the buckets: count, prefix
// sum from the group's start, scatter with first[] as each bucket's next free slot.
void sortGroup(size_t g, size_t keyCount, const raster::BufferStorage<uint32_t>& groupedKey,
               const raster::BufferStorage<uint32_t>& groupedValue, uint32_t begin, uint32_t end, Buckets& b) {
    const size_t low = g * kKeysPerGroup, high = std::min(keyCount, low + kKeysPerGroup);
    uint32_t next[kKeysPerGroup] = {};
    for (uint32_t p = begin; p < end; ++p) ++next[groupedKey[p] - low];
    uint32_t running = begin;
    for (size_t k = low; k < high; ++k) b.first[k] = running, running += std::exchange(next[k - low], running);
    for (uint32_t p = begin; p < end; ++p) b.entry[next[groupedKey[p] - low]++] = groupedValue[p];
}

}  // namespace

Buckets countingSort(std::span<const uint32_t> key, size_t keyCount, std::span<const uint32_t> value) {
    const Chunks chunks{key.size(), (key.size() + kItemsPerChunk - 1) / kItemsPerChunk};
    const size_t groups = (keyCount + kKeysPerGroup - 1) / kKeysPerGroup;
    std::vector<uint32_t> slot, groupFirst;
    groupSlots(key, chunks, groups, slot, groupFirst);
    raster::BufferStorage<uint32_t> groupedKey(key.size()), groupedValue(key.size());   // every slot written once
    tbb::parallel_for(size_t(0), chunks.count, [&](size_t c) {
        for (size_t item = chunks.begin(c); item < chunks.end(c); ++item) {
            const uint32_t p = slot[c * groups + key[item] / kKeysPerGroup]++;
            groupedKey[p] = key[item], groupedValue[p] = value.empty() ? uint32_t(item) : value[item];
        }
    });
    Buckets b;
    b.first.resize(keyCount + 1);
    b.first[keyCount] = uint32_t(key.size());
    b.entry.resize(key.size());
    tbb::parallel_for(size_t(0), groups, [&](size_t g) {
        sortGroup(g, keyCount, groupedKey, groupedValue, groupFirst[g], groupFirst[g + 1], b);
    });
    return b;
}

ListedReceivers listReceivers(const Receivers& receivers, const TexelLists& lists) {
    const size_t n = receivers.size();
    ListedReceivers listed;
    for (raster::BufferStorage<float>* column : {&listed.x, &listed.y, &listed.z}) {
        column->resize(n + kKernelPadding);
        std::fill(column->begin() + n, column->end(), 0.0f);
    }
    listed.tFar.resize(n + kKernelPadding);
    std::fill(listed.tFar.begin() + n, listed.tFar.end(), 0.0);
    listed.pixel.resize(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t e = r.begin(); e != r.end(); ++e) {
            const Receiver& receiver = receivers[lists.entry[e]];
            listed.x[e] = receiver.origin.x, listed.y[e] = receiver.origin.y, listed.z[e] = receiver.origin.z;
            listed.tFar[e] = receiver.tFar;
            listed.pixel[e] = receiver.pixel;
        }
    });
    return listed;
}

}  // namespace shadowlab::izb
