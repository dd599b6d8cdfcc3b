#include "shadows/virtual/virtual_stats.h"

namespace shadowlab::vsm {

void addPageStats(ShadowOutputs& out, const PageTable& table, size_t rendered, int invalidated,
                  const LookupResult& lookup, const PagePool& pool) {
    const size_t requested = table.requestedPages();
    out.stats.push_back({"virtual_map_flag", 1.0});
    out.stats.push_back({"requested_pages", double(requested)});
    out.stats.push_back({"cache_drawn_pages", double(rendered)});
    // A hit is a requested page valid already: neither drawn nor left without memory.
    const double hits = double(requested - rendered) - double(table.overflowPages());
    out.stats.push_back({"cache_hit_percent", requested ? 100.0 * hits / double(requested) : 0.0});
    out.stats.push_back({"cache_invalidated_pages", double(invalidated)});
    out.stats.push_back({"cache_evicted_pages", double(table.evictedPages())});
    out.stats.push_back({"cache_overflowed_pages", double(table.overflowPages())});
    out.stats.push_back({"cache_resident_pages", double(table.residentPages())});
    out.stats.push_back({"cache_pool_bytes", double(pool.depth.size() * sizeof(float))});
    out.stats.push_back({"cache_missing_pixels", double(lookup.missingPixels)});
    out.stats.push_back({"unleveled_pixels", double(lookup.unleveledPixels)});
}

}  // namespace shadowlab::vsm
