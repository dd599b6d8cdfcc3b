#!/usr/bin/env bash
# Set up, then run every test (doctest cases, one ctest test each), then install into a
# temporary prefix and build and run the examples against the installed package.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure --timeout 300 -j"$(nproc)"   # --timeout: tests added without one
scripts/test_install.sh
