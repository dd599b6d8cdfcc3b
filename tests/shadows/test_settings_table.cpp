// Typed settings: one table binds each parameter to a member of a settings struct; the specs
// take their defaults from the struct, and reading sets every member, nested ones included.
#include <doctest/doctest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadows/settings_table.h"

using namespace shadowlab;

namespace {

enum class TapFilter { Nearest, Bilinear };

struct Bias {
    float slope = 0.05f;   // not exactly 0.05: its default must still read "0.05"
    double constant = 1.5;
};

struct MapSettings {
    int resolution = 2048;
    Bias bias = {};
    TapFilter filter = TapFilter::Bilinear;
    bool snap = true;
    std::optional<int> grid = {};
    std::optional<std::vector<std::string>> receivers = {};
};

const SettingsTable<MapSettings>& mapTable() {
    static const auto table =
        SettingsTable<MapSettings>()
            .integer("resolution", member(&MapSettings::resolution), 16, 8192, "texels per side")
            .real("slope", member(&MapSettings::bias, &Bias::slope), 0.0, 10.0, "polygon offset factor")
            .real("constant", member(&MapSettings::bias, &Bias::constant), 0.0, 10.0, "metres")
            .choice("filter", member(&MapSettings::filter),
                    {{"nearest", TapFilter::Nearest}, {"bilinear", TapFilter::Bilinear, "2x2 PCF"}})
            .flag("snap", member(&MapSettings::snap), "snap to texels")
            .integerOrAuto("grid", member(&MapSettings::grid), 16, 8192, "light grid texels per side")
            .names("receivers", member(&MapSettings::receivers), "instances that receive");
    return table;
}

// A technique built on the map's settings, with a smaller map by default.
struct SoftSettings {
    MapSettings map{.resolution = 1024};
    double lightSize = 0.5;
};

const SettingsTable<SoftSettings>& softTable() {
    static const auto table = SettingsTable<SoftSettings>()
                                  .include(member(&SoftSettings::map), mapTable())
                                  .real("light-size", member(&SoftSettings::lightSize), 0.0, 4.0, "metres");
    return table;
}

std::string defaultOf(const std::vector<ParamSpec>& specs, const std::string& name) {
    for (const ParamSpec& spec : specs) {
        if (spec.name == name) return spec.defaultValue;
    }
    FAIL("no parameter " << name);
    return "";
}

}  // namespace

TEST_CASE("settings table: the specs' defaults are the struct's, in the rows' order") {
    const std::vector<ParamSpec> specs = mapTable().specs();
    REQUIRE(specs.size() == 7);
    CHECK(specs[0].name == "resolution");
    CHECK(specs[6].name == "receivers");
    CHECK(defaultOf(specs, "resolution") == "2048");
    CHECK(defaultOf(specs, "slope") == "0.05");
    CHECK(defaultOf(specs, "constant") == "1.5");
    CHECK(defaultOf(specs, "filter") == "bilinear");
    CHECK(defaultOf(specs, "snap") == "on");
    CHECK(defaultOf(specs, "grid") == "auto");
    CHECK(defaultOf(specs, "receivers") == "auto");
    CHECK(specs[0].max == 8192);
    CHECK(specs[3].choices.size() == 2);
}

TEST_CASE("settings table: read sets every member, nested ones included, from given values or defaults") {
    const std::vector<ParamSpec> specs = mapTable().specs();
    const MapSettings defaults = mapTable().read(TechniqueParams("sm", specs, {}));
    CHECK(defaults.resolution == 2048);
    CHECK(defaults.bias.slope == 0.05f);
    CHECK(defaults.filter == TapFilter::Bilinear);
    CHECK_FALSE(defaults.grid);
    const MapSettings given = mapTable().read(TechniqueParams(
        "sm", specs,
        {{"resolution", "512"}, {"slope", "0.25"}, {"constant", "3"}, {"filter", "nearest"}, {"snap", "off"},
         {"grid", "64"}, {"receivers", "floor+wall"}}));
    CHECK(given.resolution == 512);
    CHECK(given.bias.slope == 0.25f);
    CHECK(given.bias.constant == 3.0);
    CHECK(given.filter == TapFilter::Nearest);
    CHECK_FALSE(given.snap);
    CHECK(given.grid == 64);
    CHECK(given.receivers == std::vector<std::string>{"floor", "wall"});
}

TEST_CASE("settings table: an included table's rows keep the including struct's defaults") {
    const std::vector<ParamSpec> specs = softTable().specs();
    CHECK(specs.size() == 8);
    CHECK(defaultOf(specs, "resolution") == "1024");   // SoftSettings's, not MapSettings's 2048
    CHECK(defaultOf(specs, "light-size") == "0.5");
    const SoftSettings s = softTable().read(TechniqueParams("soft", specs, {{"slope", "2"}}));
    CHECK(s.map.resolution == 1024);
    CHECK(s.map.bias.slope == 2.0f);
    CHECK(s.lightSize == 0.5);
}

TEST_CASE("settings table: a default outside the spec is a bug, found when the specs are made or checked") {
    struct Odd {
        int resolution = 4;   // below the range
        TapFilter filter = static_cast<TapFilter>(7);
    };
    const auto outOfRange = SettingsTable<Odd>().integer("resolution", member(&Odd::resolution), 16, 64, "");
    CHECK_THROWS_AS(TechniqueParams("odd", outOfRange.specs(), {}), std::logic_error);
    const auto noChoice = SettingsTable<Odd>().choice("filter", member(&Odd::filter), {{"nearest", TapFilter::Nearest}});
    CHECK_THROWS_AS(noChoice.specs(), std::logic_error);
}

TEST_CASE("settings table: a one-value table, included for a member, takes the including struct's default") {
    struct Soft {
        int resolution = 1024;
        double size = 0.5;
    };
    const auto resolution = SettingsTable<int>().integer("resolution", itself<int>(), 16, 8192, "texels per side");
    const auto table = SettingsTable<Soft>()
                           .include(member(&Soft::resolution), resolution)
                           .real("size", member(&Soft::size), 0.0, 4.0, "m");
    const std::vector<ParamSpec> specs = table.specs();
    REQUIRE(specs.size() == 2);
    CHECK(defaultOf(specs, "resolution") == "1024");
    const Soft s = table.read(TechniqueParams("soft", specs, {{"resolution", "256"}}));
    CHECK(s.resolution == 256);
    CHECK(s.size == 0.5);
}
