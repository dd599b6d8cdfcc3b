// Technique parameters: each spec is the one source of a parameter's type, default, range or
// choices and help line; values are checked against it when TechniqueParams is built.
#include <doctest/doctest.h>

#include <stdexcept>

#include "frame/registry.h"
#include "shadows/depth_map.h"
#include "shadows/technique.h"
#include "shadows/technique_params.h"

using namespace shadowlab;

namespace {

enum class Filter { Nearest, Bilinear };
enum class Other { A, B };

const std::vector<ParamSpec>& specs() {
    static const std::vector<ParamSpec> all = {
        integerParam("resolution", 2048, 16, 8192, "texels per side of each map"),
        realParam("bias", 0.05, 0.0, 10.0, "metres"),
        choiceParam<Filter>("filter", "bilinear", {{"nearest", Filter::Nearest}, {"bilinear", Filter::Bilinear, "2x2 PCF"}}),
        flagParam("snap", true, "snap to texels"),
        integerOrAutoParam("grid", 16, 8192, "light grid texels per side"),
    };
    return all;
}

TechniqueParams given(const std::map<std::string, std::string>& values) { return TechniqueParams("sm", specs(), values); }

}  // namespace

TEST_CASE("technique parameters: typed defaults and overrides") {
    const TechniqueParams defaults = given({});
    CHECK(defaults.integer("resolution") == 2048);
    CHECK(defaults.real("bias") == 0.05);   // the default's text reads back as the same double
    CHECK(defaults.choice<Filter>("filter") == Filter::Bilinear);
    CHECK(defaults.flag("snap"));
    CHECK_FALSE(defaults.integerOrAuto("grid").has_value());
    CHECK(defaults.values() == std::map<std::string, std::string>{
                                   {"bias", "0.05"}, {"filter", "bilinear"}, {"grid", "auto"}, {"resolution", "2048"}, {"snap", "on"}});
    const TechniqueParams set =
        given({{"resolution", "512"}, {"bias", "1e-3"}, {"filter", "nearest"}, {"snap", "off"}, {"grid", "64"}});
    CHECK(set.integer("resolution") == 512);
    CHECK(set.real("bias") == 1e-3);
    CHECK(set.choice<Filter>("filter") == Filter::Nearest);
    CHECK_FALSE(set.flag("snap"));
    CHECK(set.integerOrAuto("grid") == 64);
}

TEST_CASE("technique parameters: ranges and choices come from the spec, ends included") {
    CHECK(given({{"resolution", "16"}}).integer("resolution") == 16);
    CHECK(given({{"resolution", "8192"}}).integer("resolution") == 8192);
    CHECK(given({{"bias", "10"}}).real("bias") == 10.0);
    CHECK_THROWS_WITH_AS(given({{"resolution", "15"}}), "sm: parameter resolution=15: must be an integer in 16..8192",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(given({{"resolution", "8193"}}), "sm: parameter resolution=8193: must be an integer in 16..8192",
                         std::invalid_argument);
    for (const char* bad : {"12x", "", "1.5", "auto"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(given({{"resolution", bad}}), std::invalid_argument);
    }
    CHECK_THROWS_WITH_AS(given({{"bias", "10.5"}}), "sm: parameter bias=10.5: must be a finite number in 0..10",
                         std::invalid_argument);
    for (const char* bad : {"nan", "inf", "-1", "0.5m"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(given({{"bias", bad}}), std::invalid_argument);
    }
    CHECK_THROWS_WITH_AS(given({{"filter", "box"}}), "sm: parameter filter=box: must be one of nearest, bilinear",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(given({{"snap", "yes"}}), "sm: parameter snap=yes: must be on or off", std::invalid_argument);
    CHECK_THROWS_WITH_AS(given({{"grid", "8"}}), "sm: parameter grid=8: must be an integer in 16..8192 or auto",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(given({{"resolutoin", "1"}}),
                         "technique 'sm' has no parameter 'resolutoin' (known: resolution, bias, filter, snap, grid)",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(TechniqueParams("none", {}, {{"resolution", "1"}}),
                         "technique 'none' has no parameter 'resolution' (it has none)", std::invalid_argument);
}

TEST_CASE("technique parameters: the help line is made from the spec") {
    CHECK(paramHelp(specs()[0]) == "texels per side of each map (16..8192)");
    CHECK(paramHelp(specs()[1]) == "metres (0..10)");
    CHECK(paramHelp(specs()[2]) == "nearest | bilinear (2x2 PCF)");
    CHECK(paramHelp(specs()[3]) == "snap to texels (on | off)");
    CHECK(paramHelp(specs()[4]) == "light grid texels per side (16..8192 or auto)");
    CHECK(paramHelp(choiceParam<Filter>("blur", "nearest", {{"nearest", Filter::Nearest}}, "filter=blur")) ==
          "filter=blur: nearest");
    CHECK(paramHelp(realParam("region", 1.0, 1e-3, 1.0, "fraction")) == "fraction (0.001..1)");
    CHECK(paramHelp(realParam("size", 0.06, 1e-4, 1e6, "tangent")) == "tangent (1e-4..1e6)");
    CHECK(paramHelp(realParam("y", 0.0, -1.5e-10, 2.5e+20, "m")) == "m (-1.5e-10..2.5e20)");
    CHECK(realParam("size", 0.06, 1e-4, 1.0, "").defaultValue == "0.06");
}

TEST_CASE("technique parameters: a bad spec or a misread is a bug, caught") {
    const auto build = [](const ParamSpec& spec) { return TechniqueParams("sm", {spec}, {}); };
    CHECK_THROWS_WITH_AS(build(integerParam("taps", 5, 10, 20, "")), "sm: the default taps=5 is not an integer in 10..20",
                         std::logic_error);
    CHECK_THROWS_AS(build(realParam("bias", -1.0, 0.0, 1.0, "")), std::logic_error);
    CHECK_THROWS_WITH_AS(build(choiceParam<Filter>("filter", "box", {{"nearest", Filter::Nearest}})),
                         "sm: the default filter=box is not one of nearest", std::logic_error);
    CHECK_THROWS_AS(TechniqueParams("sm", {flagParam("snap", true, ""), flagParam("snap", false, "")}, {}), std::logic_error);
    const TechniqueParams p = given({});
    CHECK_THROWS_AS(p.real("resolution"), std::logic_error);
    CHECK_THROWS_AS(p.integer("grid"), std::logic_error);
    CHECK_THROWS_AS(p.integerOrAuto("resolution"), std::logic_error);
    CHECK_THROWS_AS(p.choice<Other>("filter"), std::logic_error);
    CHECK_THROWS_AS(p.flag("sharpness"), std::logic_error);
}

TEST_CASE("technique parameters: every technique's defaults pass its own specs") {
    for (const Technique& t : techniques()) {
        CAPTURE(t.name);
        CHECK_NOTHROW(TechniqueParams(t.name, t.params, {}));
        for (const ParamSpec& p : t.params) {
            if (p.name == "resolution") CHECK(p.max == kMaxMapResolution);
        }
    }
}

TEST_CASE("technique parameters: name=value assignments") {
    std::map<std::string, std::string> parsed;
    parseParamAssignment("resolution=1024", parsed);
    CHECK(parsed.at("resolution") == "1024");
    CHECK_THROWS_AS(parseParamAssignment("resolution", parsed), std::invalid_argument);
    CHECK_THROWS_AS(parseParamAssignment("=3", parsed), std::invalid_argument);
}

TEST_CASE("technique parameters: a list of names joined by '+', or auto") {
    const std::vector<ParamSpec> spec = {namesParam("occluders", "instances that occlude")};
    CHECK_FALSE(TechniqueParams("pt", spec, {}).names("occluders").has_value());
    CHECK(TechniqueParams("pt", spec, {{"occluders", "box"}}).names("occluders") == std::vector<std::string>{"box"});
    CHECK(TechniqueParams("pt", spec, {{"occluders", "box+tree[3]"}}).names("occluders") ==
          std::vector<std::string>{"box", "tree[3]"});
    for (const char* bad : {"", "+", "box+", "+box", "box++tree", "a=b", "a,b"}) {
        CAPTURE(bad);
        CHECK_THROWS_WITH_AS(TechniqueParams("pt", spec, {{"occluders", bad}}),
                             doctest::Contains("must be auto or names joined by '+'"), std::invalid_argument);
    }
    CHECK(paramHelp(spec[0]) == "instances that occlude (auto | name+name+...)");
}
