// The program's operator new and delete (replacing the library's, as [replacement.functions]
// allows): malloc and free, counting the bytes asked for while an AllocationCount is open.
// Only this test program has them.
#include "tests/steady_state/allocation_count.h"

#include <atomic>
#include <cstdlib>
#include <new>
#include <stdexcept>

namespace {

std::atomic<bool> counting{false};
std::atomic<size_t> counted{0};

void* allocate(size_t size, size_t alignment) {
    if (counting.load(std::memory_order_relaxed)) counted.fetch_add(size, std::memory_order_relaxed);
    if (size == 0) size = 1;
    void* p = alignment <= alignof(std::max_align_t) ? std::malloc(size)
                                                     : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    if (!p) throw std::bad_alloc();
    return p;
}

}  // namespace

namespace shadowlab::test {

AllocationCount::AllocationCount() {
    if (counting.exchange(true)) throw std::logic_error("one AllocationCount at a time");
    counted = 0;
}
AllocationCount::~AllocationCount() { counting = false; }
size_t AllocationCount::bytes() const { return counted.load(); }

}  // namespace shadowlab::test

void* operator new(size_t size) { return allocate(size, 0); }
void* operator new[](size_t size) { return allocate(size, 0); }
void* operator new(size_t size, std::align_val_t alignment) { return allocate(size, size_t(alignment)); }
void* operator new[](size_t size, std::align_val_t alignment) { return allocate(size, size_t(alignment)); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t, std::align_val_t) noexcept { std::free(p); }
