// The settings a sweep or a fly-through runs: each technique over the cross product of the
// --param axes it has (an axis a technique lacks does not multiply its runs), numbered in a
// fixed order, technique by technique, the first axis varying slowest.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "frame/render.h"
#include "shadows/progress.h"
#include "shadows/technique.h"

namespace shadowlab {

struct SweepAxis {
    std::string name;
    std::vector<std::string> values;
};

// "name=v1,v2,v3" -> axis; throws std::invalid_argument without a name or with an empty value.
SweepAxis parseSweepAxis(const std::string& text);

// One setting of a technique; a sweep's shard selects settings by their index.
struct PlannedSetting {
    uint64_t index;
    std::map<std::string, std::string> params;
};

// One technique with the settings it runs.
struct SweepPlan {
    const Technique* technique;
    std::vector<PlannedSetting> settings;
};

// A setting's values as "a=1 b=2", or "defaults" for none.
std::string settingsLabel(const std::map<std::string, std::string>& params);

// The most settings a sweep plans. Every shard holds the whole plan, a few hundred bytes a
// setting, and at a second a setting a million are 12 node-days; a grid that asks for more
// (one Python range() asks for billions) filled the memory before the sweep began.
inline constexpr uint64_t kMaxSweepSettings = uint64_t(1) << 20;

// Each technique with the cross product of the axes it has. Throws std::invalid_argument
// for a technique listed twice, an axis given twice, an axis no technique has (a typo), or
// more than kMaxSweepSettings settings in all (checked before any is made).
std::vector<SweepPlan> planSweep(const std::vector<const Technique*>& techniques, const std::vector<SweepAxis>& axes);

uint64_t settingCount(const std::vector<SweepPlan>& plans);

// One frame per setting, so that a value a technique rejects fails before the long part.
void checkSettings(const PreparedScene& prepared, const std::vector<SweepPlan>& plans, raster::SimdLevel simd,
                   Progress* progress, const std::string& command);

}  // namespace shadowlab
