// StageTimer: laps become "<stage>_ms" stats in the order stages first ran; a stage that
// runs again (a cube face's fit and draw, say) adds to its one stat.
#include <doctest/doctest.h>

#include <thread>

#include "shadows/stage_timer.h"

using namespace shadowlab;

TEST_CASE("a stage timed twice is one stat holding both laps") {
    StageTimer timer;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    timer.lap("fit");
    timer.lap("draw");
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    timer.lap("fit");
    std::vector<TechniqueStat> stats = {{"maps_count", 6.0}};
    timer.appendTo(stats);
    REQUIRE(stats.size() == 3);
    CHECK(stats[0].name == "maps_count");
    CHECK(stats[1].name == "fit_ms");
    CHECK(stats[2].name == "draw_ms");
    CHECK(stats[1].value >= 4.0);   // both sleeps, each at least 2 ms
    CHECK(stats[2].value >= 0.0);
}
