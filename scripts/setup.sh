#!/usr/bin/env bash
# Installs shadowlab's dependencies from Debian 12's packages (only what is missing) and
# builds in build/ (Release, -Wall -Wextra, -ffp-contract=off).
#
#   scripts/setup.sh command   the command's packages, then the shadowlab command alone
#                              (scripts/quickstart.sh: no test, benchmark or browser package)
#   scripts/setup.sh           everything: the tests', the sanitizers' and the report test's
#                              packages, ccache, playwright-core; every target (scripts/test.sh)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mode=${1:-all}
[[ $mode == command || $mode == all ]] || { echo "usage: scripts/setup.sh [command]" >&2; exit 2; }

packages=(g++ cmake make
          libglm-dev libstb-dev libopenexr-dev libimath-dev libtbb-dev libembree-dev
          nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libmeshoptimizer-dev
          libtinygltf-dev)
if [[ $mode == all ]]; then
  packages+=(python3                          # the layout checks and the figures' scripts
             doctest-dev libbenchmark-dev     # the tests and the stage benchmarks
             ccache                           # the compiler cache of every build (scripts/ccache.sh)
             libegl-dev libgl-dev libopengl-dev libgl1-mesa-dri   # the llvmpipe peer (bench/peers)
             clang-14 libclang-rt-14-dev      # the sanitizer builds (scripts/sanitize.sh, tsan.sh)
             chromium                         # the report's browser test (tests/report)
             imagemagick librsvg2-bin         # the lessons' crops, contrast stretches and plots (scripts/lessons/)
             assimp-testmodels                # the Khronos glTF sample models the glTF reader's tests load (tests/scenes)
             assimp-utils                     # `assimp export`: the suite's house from IFC to glTF (scripts/suite_models.sh)
             pybind11-dev python3-dev python3-numpy python3-pytest   # the Python module and its tests (python/, tests/python)
             python3-distributed python3-pandas)   # sweep(client=) on Dask and to_dataframe(), which tests/python tests
  # Node and npm drive that browser; Debian's nodejs npm only if the machine has no node.
  command -v node > /dev/null || packages+=(nodejs npm)
  # Not slurm-wlm and munge: scripts/slurm_sweep_test.sh (run by test.sh) installs them, so
  # that their system services (munged starts at once) are not enabled on every developer's
  # machine (docs/building.md).
fi
source scripts/install_missing.sh
source scripts/steps.sh
step "packages (apt)" install_missing "${packages[@]}"

if [[ $mode == command ]]; then
  # A build/ that test.sh configured keeps its tests; a new one leaves them out.
  [[ -f build/CMakeCache.txt ]] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSHADOWLAB_BUILD_TESTS=OFF
  cmake --build build -j"$(nproc)" --target shadowlab
  exit 0
fi

# playwright-core, at the version package-lock.json pins, into tests/report/node_modules.
step "playwright-core (npm ci)" bash -c "cd tests/report && npm ci --no-audit --no-fund --silent"

source scripts/ccache.sh
# The Python module is built for Debian's interpreter, whose numpy and pytest apt installs
# (a python3 earlier in PATH, e.g. pyenv's, may have neither).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSHADOWLAB_BUILD_TESTS=ON -DPython3_EXECUTABLE=/usr/bin/python3 \
    "${ccache_launcher[@]}"
step "build: GCC Release, every target" cmake --build build -j"$(nproc)"
