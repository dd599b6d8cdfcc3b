// Counts the bytes operator new hands out while an AllocationCount lives, on any thread: the
// test program's own operator new (allocation_count.cpp) adds them up. One count at a time.
#pragma once

#include <cstddef>

namespace shadowlab::test {

class AllocationCount {
public:
    AllocationCount();
    ~AllocationCount();
    AllocationCount(const AllocationCount&) = delete;
    AllocationCount& operator=(const AllocationCount&) = delete;
    size_t bytes() const;
};

}  // namespace shadowlab::test
