#!/usr/bin/env bash
# The determinism tests built with clang-14's ThreadSanitizer in build-tsan/: any data race or
# lock-order inversion fails its test (halt_on_error). .ci/run runs this after
# scripts/sanitize.sh. They are the raster and frame tests (every technique's golden bytes
# at 8 threads, more than the cores: the most interleavings; every technique with simplified
# casters, cookies, an empty view, at the world's bound) and, of the shadows tests, those
# that run a family's parallel code on more than one thread and compare the bytes (their
# names say "threads", "the same bytes" or "the same bits": one or more per family, every
# filter and bias of the lookup among them) and every technique with its debug buffers. The
# other shadows tests are accuracy tests: the same parallel loops on other scenes, run in the
# ordinary build and under ASan; under TSan they were two thirds of the step's time (854 of
# 1282 CPU-seconds, 6 December 2026).
#
# Debian's libtbb is not instrumented, so TSan would not see its task hand-offs and would
# report every parallel_for as a race. So oneTBB is built here from Debian's own source
# package of the installed version (apt-get source, with a deb-src entry added for
# Debian 12 if there is none), with -fsanitize=thread, once per build tree (30 s on 2 cores).
# Debian's Embree is not instrumented either: under TSan the exact reference builds its BVH
# in a one-thread arena (shadows/reference/reference.cpp), so no report needs suppressing.
#
# Also left out, each checked in the ordinary build and under ASan: the golden runs with 1 thread,
# where no two threads meet, and with 2 threads (the run with 8 threads, more threads than
# cores, meets the same code with the most interleavings), and the golden runs again with
# glibc's non-FMA math, the same parallel code with only glibc's choice of its routines
# changed. SHADOWLAB_SANITIZE_ALL=1 runs them all, every shadows test too.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/steps.sh
source scripts/ccache.sh
build=${1:-build-tsan}
mkdir -p "$build"
tbb=$(realpath "$build")/onetbb
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

build_onetbb() {
  # An active deb-src entry, one-line or deb822 (a commented-out line does not count).
  if ! grep -rqsE '^[[:space:]]*deb-src[[:space:]]|^Types:.*deb-src' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm bookworm-updates\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
        $sudo tee /etc/apt/sources.list.d/shadowlab-deb-src.sources >/dev/null
  fi
  $sudo apt-get update -qq
  dpkg-query -W -f='${Status}' dpkg-dev 2>/dev/null | grep -q "install ok installed" ||
      DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends dpkg-dev
  rm -rf "$tbb" && mkdir -p "$tbb"
  version=$(dpkg-query -W -f='${source:Version}' libtbb-dev)
  (cd "$tbb" && apt-get source -qq "onetbb=$version" >/dev/null)
  source_dir=$(find "$tbb" -mindepth 1 -maxdepth 1 -type d -name 'onetbb-*')
  CC=clang-14 CXX=clang++-14 cmake -S "$source_dir" -B "$tbb/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF -DTBB_SANITIZE=thread -DCMAKE_INSTALL_PREFIX="$tbb/install" "${ccache_launcher[@]}" >/dev/null
  cmake --build "$tbb/build" -j"$(nproc)" >/dev/null
  cmake --install "$tbb/build" >/dev/null
}
[[ -f $tbb/install/lib/cmake/TBB/TBBConfig.cmake ]] || step "build: oneTBB for TSan (Debian's source)" build_onetbb

CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_BUILD_PYTHON=OFF \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
    -DTBB_DIR="$tbb/install/lib/cmake/TBB" "${ccache_launcher[@]}"
step "build: clang TSan, raster, frame and shadows tests" cmake --build "$build" -j"$(nproc)" --target test_raster test_frame test_shadows
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
left_out='^$'
[[ ${SHADOWLAB_SANITIZE_ALL:-0} == 1 ]] ||
  left_out="^(built-in scenes render to their golden hashes|every technique gives its golden V and stencil bytes) at every SIMD level with (1 thread|2 threads)$|^determinism across CPUs: .*non-FMA builds$"
shadows_kept="threads|thread count|the same bytes|the same bits|debug buffers of every technique"
[[ ${SHADOWLAB_SANITIZE_ALL:-0} == 1 ]] && shadows_kept="."
tsan_tests() {
  ctest --test-dir "$build" --output-on-failure --timeout 1800 -j"$(nproc)" -L "^(raster|frame)$" -E "$left_out"
  ctest --test-dir "$build" --output-on-failure --timeout 1800 -j"$(nproc)" -L "^shadows$" -R "$shadows_kept" -E "$left_out"
}
step "tests: the determinism tests under TSan" tsan_tests
