// Running work on an exact number of TBB worker threads.
#pragma once

#include <cstddef>
#include <utility>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

namespace shadowlab {

// The most worker threads a command accepts: far beyond any core count this project runs
// on, and few enough that creating them takes a moment, not minutes.
inline constexpr int kMaxThreads = 1024;

// Runs f() on `threads` threads (0 or less: TBB's default, every core) and returns its
// result. A global_control alone only caps the count at the machine's cores, so 8 threads
// on a 2-core machine need an arena of 8 as well; the determinism tests rely on it, since
// more threads than cores interleave the tiles in more orders. Not for nesting or for
// concurrent callers: TBB applies the smallest active limit, so an inner call could not
// raise the count.
template <class F>
decltype(auto) withThreads(int threads, F&& f) {
    if (threads <= 0) return std::forward<F>(f)();
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    tbb::task_arena arena(threads);
    return arena.execute(std::forward<F>(f));
}

}  // namespace shadowlab
