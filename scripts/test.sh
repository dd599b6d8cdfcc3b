#!/usr/bin/env bash
# Set up, then run every test (doctest cases, one ctest test each), then install into a
# temporary prefix and build and run the examples against the installed package.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/steps.sh
scripts/setup.sh
# --timeout: for tests added without one.
step "tests: every test (ctest)" ctest --test-dir build --output-on-failure --timeout 300 -j"$(nproc)"
step "tests: the installed package's examples" scripts/test_install.sh
