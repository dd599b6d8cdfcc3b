// Irregular z-buffer, stage 3: the per-texel lists of receivers (Johnson et al. 2005;
// RTR4 Figure 7.30, lower left: "for each texel a list of all dots inside its grid cell").
//
// Built as a counting sort rather than as linked lists with atomic heads (as the GPU
// versions in RTR4 7.9 do), because the order of an atomic list depends on timing: count
// the receivers per texel, turn the counts into offsets by an exclusive prefix sum, then
// place each receiver at its texel's next free slot, in receiver order. Every list is
// therefore sorted by pixel, whatever the number of threads; the three passes are linear.
#include <algorithm>

#include "shadows/izb/izb.h"

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

}  // namespace shadowlab::izb
