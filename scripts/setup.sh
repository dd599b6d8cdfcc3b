#!/usr/bin/env bash
# Installs shadowlab's dependencies from Debian 12's packages (only what is missing) and
# builds everything in build/ (Release, -Wall -Wextra, -ffp-contract=off).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(g++ cmake make pkg-config python3
          libglm-dev libstb-dev libopenexr-dev libimath-dev libtbb-dev doctest-dev
          libbenchmark-dev libembree-dev nlohmann-json3-dev libtinyobjloader-dev libcli11-dev
          libmeshoptimizer-dev
          libegl-dev libgl-dev libgl1-mesa-dri
          clang-14 libclang-rt-14-dev    # the sanitizer build (scripts/sanitize.sh)
          chromium                       # the report's browser test (tests/report)
          imagemagick librsvg2-bin)      # the lessons' crops, contrast stretches and plots (scripts/lessons/)
# Node and npm drive that browser; Debian's nodejs npm only if the machine has no node.
command -v node > /dev/null || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "installing: ${missing[*]}"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# playwright-core, at the version package-lock.json pins, into tests/report/node_modules.
(cd tests/report && npm ci --no-audit --no-fund --silent)

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
