#!/usr/bin/env bash
# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (clang-14
# from Debian, libclang-rt-14-dev), in build-asan/: any memory error, leak or undefined
# behaviour fails its test (-fno-sanitize-recover, halt_on_error). The same build holds the
# libFuzzer targets (tests/fuzz), whose seeds ctest runs once here and scripts/fuzz.sh
# fuzzes; the fuzzer's coverage instrumentation goes only into the libraries they link
# (tests/fuzz/CMakeLists.txt), so the rest of the suite runs at ASan's speed.
# scripts/setup.sh installs the compiler; .ci/run runs this after the ordinary tests.
#
# Line tables only (-gline-tables-only): a report's stack names every file and line, and
# the build skips the full debug information it would not use.
#
# Left out here, each checked in the ordinary build: the golden runs with 1 and 8 threads
# (with 2 threads every SIMD level's kernels still run under both sanitizers) and the golden
# runs again with glibc's non-FMA math (the same code, only glibc's choice of its own
# routines differs); SHADOWLAB_SANITIZE_ALL=1 runs them too (docs/reliability.md, "Reliability"). The
# peer benchmark's check is always left out: it drives Mesa's uninstrumented llvmpipe.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/steps.sh
source scripts/ccache.sh
build=${1:-build-asan}
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# Without the Python module: an interpreter loads it only with the sanitizer's runtime preloaded,
# and its tests run in build/ (docs/python.md, "Memory").
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_FUZZ=ON -DSHADOWLAB_BUILD_PYTHON=OFF \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" "${ccache_launcher[@]}"
step "build: clang ASan+UBSan, tests and fuzz targets" cmake --build "$build" -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export SHADOWLAB_CATALOGUE_MEMORY=unlimited
left_out="^peers:"
[[ ${SHADOWLAB_SANITIZE_ALL:-0} == 1 ]] ||
  left_out+="|^(built-in scenes render to their golden hashes|every technique gives its golden V and stencil bytes) at every SIMD level with (1 thread|8 threads)$|^determinism across CPUs: .*non-FMA builds$"
# The layout label's check compiles the sources with the ordinary compiler; no code runs.
step "tests: the suite under ASan+UBSan" ctest --test-dir "$build" --output-on-failure --timeout 900 -j"$(nproc)" \
    -E "$left_out" -LE "^layout$"
