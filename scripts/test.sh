#!/usr/bin/env bash
# Set up, then run every test (doctest cases, one ctest test each), then install into a
# temporary prefix and build and run the examples against the installed package.
#
#   scripts/test.sh             the above
#   scripts/test.sh --cluster   the above, then a sharded sweep on a real one-node Slurm
#                               (scripts/slurm_sweep_test.sh: as root; it installs slurm-wlm
#                               and munge). CI runs this. The Slurm test alone, on a machine
#                               set up already: scripts/slurm_sweep_test.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cluster=false
case ${1:-} in
  "") ;;
  --cluster) cluster=true ;;
  *) echo "usage: scripts/test.sh [--cluster]" >&2; exit 2 ;;
esac
source scripts/steps.sh
scripts/setup.sh
# --timeout: for tests added without one.
step "tests: every test (ctest)" ctest --test-dir build --output-on-failure --timeout 300 -j"$(nproc)"
step "tests: the installed package's examples" scripts/test_install.sh
if $cluster; then
  step "tests: a sharded sweep on one-node Slurm" scripts/slurm_sweep_test.sh
fi
