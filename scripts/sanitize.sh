#!/usr/bin/env bash
# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (clang-14
# from Debian, libclang-rt-14-dev), in build-asan/: any memory error, leak or undefined
# behaviour fails its test (-fno-sanitize-recover, halt_on_error). The same build holds the
# libFuzzer targets (tests/fuzz; the libraries carry the fuzzer's coverage instrumentation),
# whose seeds ctest runs once here and scripts/fuzz.sh fuzzes. scripts/setup.sh installs
# the compiler; .ci/run runs this after the ordinary tests.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build-asan}
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=all -fno-omit-frame-pointer"
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_FUZZ=ON \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build "$build" -j"$(nproc)"
# The peer benchmark drives Mesa's uninstrumented llvmpipe, whose own leaks are not ours.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export SHADOWLAB_CATALOGUE_MEMORY=unlimited
ctest --test-dir "$build" --output-on-failure --timeout 900 -j"$(nproc)" -E "^peers:"
