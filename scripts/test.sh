#!/usr/bin/env bash
# Set up, then run every test (doctest cases, one ctest test each).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
