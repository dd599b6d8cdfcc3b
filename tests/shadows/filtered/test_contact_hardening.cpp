// `chs` (shadows/filtered/contact_hardening.cpp): PCSS read on the min/max hierarchy's
// levels. Its error stays near PCSS's while its taps stay fixed however wide the penumbra,
// and V is the same for any thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include <tbb/global_control.h>

#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;
using shadowlab::test::smallScene;
using shadowlab::test::softCase;
using shadowlab::test::SoftScene;

TEST_CASE("chs stays within a stated RMS of the soft reference, near PCSS, reading coarse levels") {
    // Measured at 200 x 125: sphere-box 0.0168 (PCSS 0.0160); at 320 x 200 two-boxes and bunny within 5%.
    for (const std::string& name : {std::string("sphere-box"), softCase("two-boxes")}) {
        CAPTURE(name);
        const SoftScene s(smallScene(name, 200, 125));
        const ShadowOutputs chs = s.run("chs");
        const double e = s.rms(chs.visibility), pcss = s.rms(s.run("pcss").visibility);
        const double hard = s.rms(s.run("shadow-map").visibility);
        CAPTURE(e);
        CAPTURE(pcss);
        CHECK(e < 0.025);
        CHECK(e < 1.3 * pcss);
        CHECK(e < 0.8 * hard);
        const auto coarse = std::find_if(chs.stats.begin(), chs.stats.end(),
                                         [](const TechniqueStat& st) { return st.name == "coarse_search_percent"; });
        REQUIRE(coarse != chs.stats.end());
        CHECK(coarse->value > 10.0);   // the wide cones' searches read the hierarchy, not texels
    }
}

TEST_CASE("chs gives the same bytes for 1 and 2 threads") {
    const SoftScene s(smallScene(softCase("two-heights"), 160, 100), 2);
    std::vector<float> one, two;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = s.run("chs").visibility;
    }
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = s.run("chs").visibility;
    }
    CHECK(one == two);
}
