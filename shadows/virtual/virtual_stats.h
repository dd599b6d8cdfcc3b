// The stats a virtual shadow map reports for any light (docs/virtual-shadow-maps.md,
// "Parameters"): virtual_map_flag 1 (the frame went through pages, not a fallback), the
// pages requested, and what the history saved, named cache_... (docs/architecture.md, "Stat
// names"), then the pixels left lit for want of a level.
#pragma once

#include <cstddef>

#include "shadows/technique.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

void addPageStats(ShadowOutputs& out, const PageTable& table, size_t rendered, int invalidated,
                  const LookupResult& lookup, const PagePool& pool);

}  // namespace shadowlab::vsm
