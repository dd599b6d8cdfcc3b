// `shadowlab scaling`: the least-squares fit on exact synthetic data (Cai et al. 2006,
// eq. 8), a hand-computed noisy case, and a run over two scenes with its outputs.
#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/measure/scaling.h"
#include "app/plots/scaling_plot.h"
#include "frame/registry.h"
#include "scenes/scene_file.h"
#include "tests/app/text_count.h"

using namespace shadowlab;
using test::countOf;

namespace {

ScalingOptions quickOptions(std::vector<std::string> scenes) {
    ScalingOptions options;
    for (const std::string& name : scenes) options.scenes.push_back(builtinSceneDir() + "/scaling/" + name + ".json");
    options.technique = &findTechnique("none");
    options.threads = 1;
    options.warmupRuns = 0;
    options.runs = 1;
    return options;
}

}  // namespace

TEST_CASE("line fit: recovers eq. 8 from exact points") {
    // The polygon counts of the paper's Table 1 and the times its fit predicts.
    const std::vector<double> n = {984, 1536, 3516, 6620, 7172, 9906};
    std::vector<double> t;
    for (double x : n) t.push_back(22.69 + x / 238.72);
    const LineFit fit = fitLine(n, t);
    CHECK(fit.a == doctest::Approx(22.69).epsilon(1e-12));
    CHECK(1.0 / fit.b == doctest::Approx(238.72).epsilon(1e-12));
    CHECK(fit.r2 == doctest::Approx(1.0).epsilon(1e-12));
    // The same inputs give the same bits.
    const LineFit again = fitLine(n, t);
    CHECK(again.a == fit.a);
    CHECK(again.b == fit.b);
    CHECK(again.r2 == fit.r2);
}

TEST_CASE("line fit: a hand-computed case, constant data, bad inputs") {
    // Mean (1.5, 2.5); Sxy = 4, Sxx = 5: b = 0.8, a = 1.3; residuals -0.3, 0.9, -0.9, 0.3
    // give SS_res = 1.8 of SS_tot = 5: R^2 = 0.64.
    const LineFit fit = fitLine({0, 1, 2, 3}, {1, 3, 2, 4});
    CHECK(fit.b == doctest::Approx(0.8).epsilon(1e-14));
    CHECK(fit.a == doctest::Approx(1.3).epsilon(1e-14));
    CHECK(fit.r2 == doctest::Approx(0.64).epsilon(1e-14));
    const LineFit flat = fitLine({1, 2, 3}, {5, 5, 5});
    CHECK(flat.b == 0.0);
    CHECK(flat.a == 5.0);
    CHECK(flat.r2 == 1.0);
    CHECK_THROWS_AS(fitLine({1, 2}, {1}), std::invalid_argument);
    CHECK_THROWS_AS(fitLine({2, 2, 2}, {1, 2, 3}), std::invalid_argument);
    CHECK_THROWS_AS(fitLine({}, {}), std::invalid_argument);
}

TEST_CASE("scaling: two scenes, their triangle counts, a fit through both, CSV/JSON/SVG") {
    const ScalingResults results = runScaling(quickOptions({"sphere-24", "sphere-48"}));
    CHECK(results.technique == "none");
    CHECK(results.threads == 1);
    REQUIRE(results.points.size() == 2);
    CHECK(results.points[0].scene == "sphere-24");
    CHECK(results.points[0].triangles == 24 * 11 * 2 + 2);   // the sphere and a two-triangle ground
    CHECK(results.points[1].triangles == 48 * 23 * 2 + 2);
    for (const ScalingPoint& p : results.points) CHECK(results.fit.at(double(p.triangles)) == doctest::Approx(p.medianMs));
    CHECK(scalingFileStem(results) == "scaling-none");

    std::istringstream csv(formatScalingCsv(results));
    std::string line;
    std::getline(csv, line);
    CHECK(line == "scene,triangles,median_ms,min_ms,fitted_ms");
    std::getline(csv, line);
    CHECK(line.rfind("sphere-24,530,", 0) == 0);
    const nlohmann::json j = nlohmann::json::parse(formatScalingJson(results));
    CHECK(j["fit"]["a_ms"].get<double>() == results.fit.a);
    CHECK(j["fit"]["r2"].get<double>() == results.fit.r2);
    CHECK(j["points"].size() == 2);
    CHECK(j["points"][1]["triangles"] == 2210);
    const std::string svg = formatScalingSvg(results);
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(countOf(svg, "class=\"point\"") == 2);
    CHECK(countOf(svg, "</svg>") == 1);
    CHECK(formatScalingText(results).find("R^2") != std::string::npos);
}

TEST_CASE("scaling: at least two scenes with different triangle counts") {
    CHECK_THROWS_AS(runScaling(quickOptions({"sphere-24"})), std::invalid_argument);
    CHECK_THROWS_WITH_AS(runScaling(quickOptions({"sphere-24", "sphere-24"})), doctest::Contains("different triangle counts"),
                         std::invalid_argument);
    ScalingOptions noTechnique = quickOptions({"sphere-24", "sphere-48"});
    noTechnique.technique = nullptr;
    CHECK_THROWS_AS(runScaling(noTechnique), std::invalid_argument);
    CHECK_THROWS_AS(runScaling(quickOptions({"sphere-24", "no-such-scene"})), SceneError);
}
