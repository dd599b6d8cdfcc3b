// withThreads(): an arena of its own for a count the machine's cores hold, the process-wide
// limit raised only for more threads than cores, so that concurrent callers keep their counts.
#include <cstddef>
#include <utility>

#include <doctest/doctest.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "raster/thread_count.h"

namespace {

size_t processLimit() {
    return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
}

}  // namespace

TEST_CASE("withThreads sets no process-wide limit within the cores, and raises it beyond them") {
    const size_t before = processLimit();
    const int cores = tbb::info::default_concurrency();
    // One thread: the arena's, while a limit of 1 would have capped every other caller too.
    const std::pair<int, size_t> inside = shadowlab::withThreads(1, [] {
        return std::pair(tbb::this_task_arena::max_concurrency(), processLimit());
    });
    CHECK(inside.first == 1);
    CHECK(inside.second == before);
    const int many = cores + 6;
    const size_t raised = shadowlab::withThreads(many, [] { return processLimit(); });
    CHECK(raised == size_t(many));
    CHECK(processLimit() == before);   // and lowered again when the call returns
}
