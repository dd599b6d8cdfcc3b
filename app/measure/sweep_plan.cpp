#include "app/measure/sweep_plan.h"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace shadowlab {
namespace {

using Settings = std::map<std::string, std::string>;

bool hasParam(const Technique& technique, const std::string& name) {
    return std::ranges::any_of(technique.params, [&](const ParamSpec& p) { return p.name == name; });
}

// Every combination of the axes' values, the first axis varying slowest.
std::vector<Settings> crossProduct(const std::vector<SweepAxis>& axes) {
    std::vector<Settings> combinations{{}};
    for (const SweepAxis& axis : axes) {
        std::vector<Settings> next;
        for (const Settings& partial : combinations) {
            for (const std::string& value : axis.values) {
                Settings extended = partial;
                extended[axis.name] = value;
                next.push_back(std::move(extended));
            }
        }
        combinations = std::move(next);
    }
    return combinations;
}

}  // namespace

SweepAxis parseSweepAxis(const std::string& text) {
    std::map<std::string, std::string> assignment;
    parseParamAssignment(text, assignment);
    SweepAxis axis{assignment.begin()->first, {}};
    std::istringstream values(assignment.begin()->second + ",");
    for (std::string value; std::getline(values, value, ',');) {
        if (value.empty()) throw std::invalid_argument("--param " + text + ": empty value in the comma-separated list");
        axis.values.push_back(value);
    }
    return axis;
}

std::string settingsLabel(const std::map<std::string, std::string>& params) {
    std::string label;
    for (const auto& [name, value] : params) label += (label.empty() ? "" : " ") + name + "=" + value;
    return label.empty() ? "defaults" : label;
}

std::vector<SweepPlan> planSweep(const std::vector<const Technique*>& techniques, const std::vector<SweepAxis>& axes) {
    std::vector<SweepPlan> plans;
    uint64_t index = 0;
    for (const Technique* technique : techniques) {
        if (std::ranges::any_of(plans, [&](const SweepPlan& p) { return p.technique->name == technique->name; }))
            throw std::invalid_argument("technique '" + technique->name + "' is listed twice");
        std::vector<SweepAxis> own;
        std::ranges::copy_if(axes, std::back_inserter(own),
                             [&](const SweepAxis& a) { return hasParam(*technique, a.name); });
        uint64_t combinations = 1;   // saturated past the limit, so that it cannot overflow
        for (const SweepAxis& axis : own)
            combinations = std::min<uint64_t>(combinations * axis.values.size(), kMaxSweepSettings + 1);
        if (index + combinations > kMaxSweepSettings)
            throw std::invalid_argument("sweep: the grid has more than " + std::to_string(kMaxSweepSettings) +
                                        " settings; split it into several sweeps");
        SweepPlan& plan = plans.emplace_back(SweepPlan{technique, {}});
        for (Settings& params : crossProduct(own)) plan.settings.push_back({index++, std::move(params)});
    }
    for (size_t i = 0; i < axes.size(); ++i) {
        const SweepAxis& axis = axes[i];
        const auto sameName = [&](const SweepAxis& a) { return a.name == axis.name; };
        if (std::ranges::any_of(axes.begin(), axes.begin() + i, sameName))
            throw std::invalid_argument("--param " + axis.name + ": given twice; list every value in one axis");
        if (std::ranges::none_of(plans, [&](const SweepPlan& p) { return hasParam(*p.technique, axis.name); }))
            throw std::invalid_argument("--param " + axis.name +
                                        ": none of the techniques has this parameter (see `shadowlab techniques`)");
    }
    return plans;
}

uint64_t settingCount(const std::vector<SweepPlan>& plans) {
    uint64_t count = 0;
    for (const SweepPlan& plan : plans) count += plan.settings.size();
    return count;
}

void checkSettings(const PreparedScene& prepared, const std::vector<SweepPlan>& plans, raster::SimdLevel simd,
                   Progress* progress, const std::string& command) {
    const ProgressStage checked(progress, command + ": checking setting", settingCount(plans));
    for (const SweepPlan& plan : plans) {
        for (const PlannedSetting& setting : plan.settings) {
            renderFrame(prepared, *plan.technique, {simd, setting.params, {}});
            checked.advance();
        }
    }
}

}  // namespace shadowlab
