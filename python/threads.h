// The library's worker threads for one call from Python: a TBB arena of its own per call, so
// that two Python threads may render at once with different counts (raster/thread_count.h's
// withThreads sets a process-wide limit, not for concurrent callers). Without that limit an
// arena runs at most as many threads at once as the machine has cores; every count gives the
// same bytes (the library's determinism).
#pragma once

#include <tbb/task_arena.h>

namespace shadowlab::python {

// f() on `threads` worker threads, 0 for every core.
template <class F>
decltype(auto) onThreads(int threads, F&& f) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    return arena.execute(std::forward<F>(f));
}

}  // namespace shadowlab::python
