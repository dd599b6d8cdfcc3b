// Running work on an exact number of TBB worker threads.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

namespace shadowlab {

// The most worker threads a command accepts: far beyond any core count this project runs
// on, and few enough that creating them takes a moment, not minutes.
inline constexpr int kMaxThreads = 1024;

// Runs f() on `threads` threads (0 or less: TBB's default, every core) and returns its
// result, in a task arena of that many threads of its own, so that callers on other threads
// (two sweeps, or a sweep and a render from Python) keep their own counts. TBB lets at most
// the machine's cores run at once, though, so 8 threads on a 2-core machine also need that
// limit raised (the determinism tests rely on it, since more threads than cores interleave
// the tiles in more orders): a global_control, which is process-wide. Of concurrent or nested
// calls above the core count TBB applies the smallest such limit, so those cap each other.
template <class F>
decltype(auto) withThreads(int threads, F&& f) {
    if (threads <= 0) return std::forward<F>(f)();
    std::optional<tbb::global_control> raised;
    if (threads > tbb::info::default_concurrency())
        raised.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));
    tbb::task_arena arena(threads);
    return arena.execute(std::forward<F>(f));
}

}  // namespace shadowlab
