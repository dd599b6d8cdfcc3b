#!/usr/bin/env bash
# Set up, then run every test (doctest and pytest cases, one ctest test each), install into a
# temporary prefix and build and run the examples against the installed package, then run a
# sharded sweep on a real one-node Slurm (scripts/slurm_sweep_test.sh: as root, since slurmd
# runs the jobs; it installs slurm-wlm and munge itself, docs/scale.md).
#
#   scripts/test.sh                all of it (the README's quick start; CI runs this)
#   scripts/test.sh --no-cluster   all but the Slurm sweep (not root, or a machine with a Slurm
#                                  of its own to leave alone)
# The Slurm test alone, on a machine set up already: scripts/slurm_sweep_test.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cluster=true
case ${1:-} in
  "") ;;
  --no-cluster) cluster=false ;;
  *) echo "usage: scripts/test.sh [--no-cluster]" >&2; exit 2 ;;
esac
source scripts/steps.sh
scripts/setup.sh
# --timeout: for tests added without one.
step "tests: every test (ctest)" ctest --test-dir build --output-on-failure --timeout 300 -j"$(nproc)"
step "tests: the installed package's examples" scripts/test_install.sh
if $cluster; then
  step "tests: a sharded sweep on one-node Slurm" scripts/slurm_sweep_test.sh
fi
