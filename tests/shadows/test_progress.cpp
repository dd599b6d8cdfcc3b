// The progress line (shadows/progress.h) on a string stream, timed by a clock the test
// sets: silent for the first two seconds, then done/total, elapsed and the estimate, at
// most ten redraws a second, ended with a newline; counted exactly from many threads.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "shadows/progress.h"

using namespace shadowlab;
using namespace std::chrono_literals;

namespace {

// A clock that stands still until the test moves it; safe to read and move from any thread.
class TestClock {
public:
    void set(Progress::Clock::duration t) { ticks_ = t.count(); }
    void wait(Progress::Clock::duration d) { ticks_ += d.count(); }
    std::function<Progress::Clock::time_point()> reader() {
        return [this] { return Progress::Clock::time_point(Progress::Clock::duration(ticks_.load())); };
    }

private:
    std::atomic<Progress::Clock::rep> ticks_{0};
};

}  // namespace

TEST_CASE("progress: nothing before the delay, then done/total and the estimate, ended with a newline") {
    TestClock clock;
    std::ostringstream out;
    Progress progress(out, clock.reader());
    {
        const ProgressStage stage(&progress, "sweep: frame", 10);
        clock.set(1s);
        stage.advance();
        CHECK(out.str().empty());
        clock.set(2s);
        stage.advance();
        CHECK(out.str() == "\rsweep: frame 2/10 (20%), 0:02 elapsed, ~0:08 left");
        clock.set(2050ms);   // within the redraw interval: counted, not drawn
        stage.advance();
        CHECK(out.str() == "\rsweep: frame 2/10 (20%), 0:02 elapsed, ~0:08 left");
        clock.set(3s);
        stage.advance(6);
        CHECK(out.str().ends_with("\rsweep: frame 9/10 (90%), 0:03 elapsed, ~0:00 left"));
        out.str("");
        clock.set(150s);
        stage.advance();
    }
    // The last line is 10 characters shorter than the one before it: blanks cover the rest.
    CHECK(out.str() == "\rsweep: frame 10/10 (100%), 2:30 elapsed" + std::string(10, ' ') + "\n");
}

TEST_CASE("progress: a stage that ends within the delay prints nothing") {
    TestClock clock;
    std::ostringstream out;
    Progress progress(out, clock.reader());
    {
        const ProgressStage stage(&progress, "scaling: frame", 3);
        for (int k = 0; k < 3; ++k) {
            clock.wait(600ms);
            stage.advance();
        }
    }
    CHECK(out.str().empty());
}

TEST_CASE("progress: each stage starts its own line and its own clock") {
    TestClock clock;
    std::ostringstream out;
    Progress progress(out, clock.reader());
    {
        const ProgressStage first(&progress, "bench: run", 2);
        clock.set(3600s);
        first.advance();
    }
    CHECK(out.str() == "\rbench: run 1/2 (50%), 1:00:00 elapsed, ~1:00:00 left\n");
    out.str("");
    {
        const ProgressStage second(&progress, "reference rays: row", 4);
        clock.wait(1s);
        second.advance();
    }
    CHECK(out.str().empty());
}

TEST_CASE("progress: units counted from many threads all arrive") {
    TestClock clock;   // moved 1 ms a unit: past the delay half way, then drawn by any thread
    std::ostringstream out;
    Progress progress(out, clock.reader());
    {
        const ProgressStage stage(&progress, "reference rays: row", 4000);
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t) {
            threads.emplace_back([&] {
                for (int k = 0; k < 1000; ++k) {
                    stage.advance();
                    clock.wait(1ms);
                }
            });
        }
        for (std::thread& thread : threads) thread.join();
    }
    const std::string text = out.str();
    const std::string last = text.substr(text.rfind('\r'));
    CHECK(last.starts_with("\rreference rays: row 4000/4000 (100%), "));
    CHECK(last.back() == '\n');
}
