// The kernels behind portable::expRun (portable_exp.h), one per instruction set; each takes
// a multiple of its width. Plain data only: the per-ISA translation units include this
// header, and no inline function built for a wider instruction set may reach the rest of
// the program.
#pragma once

#include <cstddef>

namespace shadowlab::portable {

struct ExpKernel {
    int width;
    void (*run)(const double* x, double* out, size_t count);
};
ExpKernel expKernelScalar();
ExpKernel expKernelAvx2();
ExpKernel expKernelAvx512();

}  // namespace shadowlab::portable
