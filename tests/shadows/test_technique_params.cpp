#include <doctest/doctest.h>

#include <stdexcept>

#include "shadows/technique_params.h"

using namespace shadowlab;

TEST_CASE("technique parameters: defaults, overrides, types, ranges and unknown names") {
    const std::vector<ParamSpec> specs = {{"resolution", "2048", ""}, {"bias", "0.5", ""}, {"filter", "pcf", ""}, {"snap", "on", ""}};
    const TechniqueParams defaults("sm", specs, {});
    CHECK(defaults.integer("resolution", 16, 8192) == 2048);
    CHECK(defaults.real("bias", 0, 10) == 0.5);
    CHECK(defaults.choice("filter", {"nearest", "pcf"}) == "pcf");
    CHECK(defaults.flag("snap"));
    const TechniqueParams given("sm", specs, {{"resolution", "512"}, {"bias", "1e-3"}, {"snap", "off"}});
    CHECK(given.integer("resolution", 16, 8192) == 512);
    CHECK(given.real("bias", 0, 10) == 1e-3);
    CHECK_FALSE(given.flag("snap"));
    CHECK(given.values().at("filter") == "pcf");
    CHECK_THROWS_WITH_AS(TechniqueParams("sm", specs, {{"resolutoin", "1"}}), doctest::Contains("known: resolution"), std::invalid_argument);
    const TechniqueParams bad("sm", specs, {{"resolution", "12x"}, {"bias", "nan"}, {"filter", "box"}});
    CHECK_THROWS_WITH_AS(bad.integer("resolution", 16, 8192), doctest::Contains("resolution=12x"), std::invalid_argument);
    CHECK_THROWS_AS(bad.real("bias", 0, 1), std::invalid_argument);
    CHECK_THROWS_WITH_AS(bad.choice("filter", {"nearest", "pcf"}), doctest::Contains("nearest, pcf"), std::invalid_argument);
    CHECK_THROWS_AS(given.integer("resolution", 1024, 8192), std::invalid_argument);
    std::map<std::string, std::string> parsed;
    parseParamAssignment("resolution=1024", parsed);
    CHECK(parsed.at("resolution") == "1024");
    CHECK_THROWS_AS(parseParamAssignment("resolution", parsed), std::invalid_argument);
    CHECK_THROWS_AS(parseParamAssignment("=3", parsed), std::invalid_argument);
}
