// The line plot of the differential-rendering figures (app/line_plot.h): one polyline and
// one circle per point of each series, labels where given, every point inside the plot
// area, and bad series refused.
#include <doctest/doctest.h>

#include <cmath>
#include <regex>
#include <stdexcept>
#include <string>

#include "app/line_plot.h"
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
