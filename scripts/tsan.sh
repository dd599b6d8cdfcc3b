#!/usr/bin/env bash
# The determinism and technique tests (ctest labels raster, frame, shadows) built with
# clang-14's ThreadSanitizer in build-tsan/: any data race or lock-order inversion fails its
# test (halt_on_error). .ci/run runs this after scripts/sanitize.sh.
#
# Debian's libtbb is not instrumented, so TSan would not see its task hand-offs and would
# report every parallel_for as a race. So oneTBB is built here from Debian's own source
# package of the installed version (apt-get source, with a deb-src entry added for
# Debian 12 if there is none), with -fsanitize=thread, once per build tree (30 s on 2 cores).
# Debian's Embree is not instrumented either: under TSan the exact reference builds its BVH
# in a one-thread arena (shadows/reference/reference.cpp), so no report needs suppressing.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build-tsan}
mkdir -p "$build"
tbb=$(realpath "$build")/onetbb
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

if [[ ! -f $tbb/install/lib/cmake/TBB/TBBConfig.cmake ]]; then
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
      -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF -DTBB_SANITIZE=thread -DCMAKE_INSTALL_PREFIX="$tbb/install" >/dev/null
  cmake --build "$tbb/build" -j"$(nproc)" >/dev/null
  cmake --install "$tbb/build" >/dev/null
fi

CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
    -DTBB_DIR="$tbb/install/lib/cmake/TBB"
cmake --build "$build" -j"$(nproc)" --target test_raster test_frame test_shadows
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
# Left out: the golden-bytes run on one thread, where no two threads meet, and the reruns of
# the golden runs with glibc's non-FMA math, the same parallel code with only glibc's choice
# of math routines changed (6.4 minutes of test time on the 2-core VM).
ctest --test-dir "$build" --output-on-failure --timeout 1800 -j"$(nproc)" -L "^(raster|frame|shadows)$" \
    -E "^every technique gives its golden V .* with 1 thread$|^determinism across CPUs: .*non-FMA builds$"
