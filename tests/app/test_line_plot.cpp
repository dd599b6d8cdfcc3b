// The line plot of the differential-rendering figures (app/plots/line_plot.h): one polyline and
// one circle per point of each series, labels where given, every point inside the plot
// area, and bad series refused.
#include <doctest/doctest.h>

#include <cmath>
#include <regex>
#include <stdexcept>
#include <string>

#include "app/plots/line_plot.h"
#include "tests/app/text_count.h"

using namespace shadowlab;
using test::countOf;

TEST_CASE("line plot: a polyline per series, a circle per point, all inside the plot area") {
    LinePlot plot{"title & more", "x", "y", {{"a", {0, 1, 2}, {3, 1, 0.5}, {"n = 1", "n = 2", "n = 3"}}, {"b", {4}, {2}, {}}}};
    const std::string svg = formatLinePlotSvg(plot);
    CHECK(svg.starts_with("<svg"));
    CHECK(svg.ends_with("</svg>\n"));
    CHECK(countOf(svg, "<polyline") == 2);
    CHECK(countOf(svg, "class=\"point\"") == 4);
    CHECK(countOf(svg, "class=\"label\"") == 3);
    CHECK(svg.find("title &amp; more") != std::string::npos);
    const std::regex circle(R"re(cx="([0-9.]+)" cy="([0-9.]+)")re");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it) {
        const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
        CHECK(x >= 70.0);
        CHECK(x <= 620.0);
        CHECK(y >= 40.0);
        CHECK(y <= 440.0);
    }
}

TEST_CASE("line plot: no points, mismatched lengths and negative or non-finite values are refused") {
    CHECK_THROWS_AS(formatLinePlotSvg({"t", "x", "y", {}}), std::invalid_argument);
    CHECK_THROWS_AS(formatLinePlotSvg({"t", "x", "y", {{"a", {}, {}, {}}}}), std::invalid_argument);
    CHECK_THROWS_AS(formatLinePlotSvg({"t", "x", "y", {{"a", {1, 2}, {1}, {}}}}), std::invalid_argument);
    CHECK_THROWS_AS(formatLinePlotSvg({"t", "x", "y", {{"a", {1}, {1}, {"p", "q"}}}}), std::invalid_argument);
    CHECK_THROWS_AS(formatLinePlotSvg({"t", "x", "y", {{"a", {-1}, {1}, {}}}}), std::invalid_argument);
    CHECK_THROWS_AS(formatLinePlotSvg({"t", "x", "y", {{"a", {1}, {std::nan("")}, {}}}}), std::invalid_argument);
}

// A fly-through names its series by their settings ("chs filter-nodes=4 search-nodes=32"),
// and a cross product of settings makes many: every legend entry must fit on the canvas.
TEST_CASE("line plot: the canvas widens for long series names and deepens for many series") {
    const std::regex size(R"re(<svg [^>]*width="([0-9.]+)" height="([0-9.]+)")re");
    const auto canvasOf = [&](const LinePlot& plot) {
        const std::string svg = formatLinePlotSvg(plot);
        std::smatch m;
        REQUIRE(std::regex_search(svg, m, size));
        return std::pair(std::stod(m[1]), std::stod(m[2]));
    };
    const std::pair<double, double> plain = canvasOf({"t", "x", "y", {{"a", {1}, {1}, {}}}});
    CHECK(plain == std::pair(800.0, 500.0));

    const std::string name(60, 'n');   // 'n' is 7.6 units wide in 12-unit DejaVu Sans
    const std::pair<double, double> wide = canvasOf({"t", "x", "y", {{name, {1}, {1}, {}}}});
    CHECK(wide.first >= 666.0 + 60 * 7.6);
    CHECK(wide.second == 500.0);

    LinePlot many{"t", "x", "y", {}};
    for (int k = 0; k < 40; ++k) many.series.push_back({std::to_string(k), {1}, {double(k)}, {}});
    const std::string svg = formatLinePlotSvg(many);
    const std::pair<double, double> deep = canvasOf(many);
    const std::regex legend(R"re(<text x="666.0" y="([0-9.]+)">39</text>)re");
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, legend));
    CHECK(std::stod(m[1]) + 4.0 <= deep.second);   // the last entry's descent is on the canvas
}
