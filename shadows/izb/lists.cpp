// Irregular z-buffer, stage 3: the per-texel lists of receivers (Johnson et al. 2005;
// RTR4 Figure 7.30, lower left: "for each texel a list of all dots inside its grid cell").
//
// Built as a counting sort rather than as linked lists with atomic heads (as the GPU
// versions in RTR4 7.9 do), because the order of an atomic list depends on timing: count
// the receivers per texel, turn the counts into offsets by an exclusive prefix sum, then
// place each receiver at its texel's next free slot, in receiver order. Every list is
// therefore sorted by pixel, whatever the number of threads; the three passes are linear.
//
// The traversal then reads the receivers of a texel, and of a row of texels, as one run:
// listReceivers() copies them in list order (Johnson et al. 2005 keep each sample's data in
// the list node for the same reason), which turns its scattered loads into streams.
#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadows/izb/izb.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {

Buckets countingSort(const std::vector<uint32_t>& key, size_t keyCount, const std::vector<uint32_t>& value) {
    Buckets b;
    b.first.assign(keyCount + 1, 0);
    // Count into first[k + 1], so that the prefix sum leaves first[k] = the items before k.
    for (const uint32_t k : key) ++b.first[k + 1];
    for (size_t k = 0; k < keyCount; ++k) b.first[k + 1] += b.first[k];
    // Scatter with first[k] as bucket k's next free slot; it ends at the start of bucket
    // k + 1, so one shift restores the offsets (no second array of keyCount cursors).
    b.entry.resize(key.size());
    for (size_t item = 0; item < key.size(); ++item) b.entry[b.first[key[item]]++] = value.empty() ? uint32_t(item) : value[item];
    std::copy_backward(b.first.begin(), b.first.end() - 1, b.first.end());
    b.first[0] = 0;
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
