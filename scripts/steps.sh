# shellcheck shell=bash
# Sourced by the scripts CI runs: `step NAME COMMAND...` runs COMMAND and, where
# SHADOWLAB_STEP_LOG names a file (.ci/run sets it), appends the step's name, its wall time
# in seconds and its exit status, from which .ci/run prints its step table. COMMAND runs in
# a subshell with errexit of its own, so a function run as a step stops at its first
# failing command (called as `COMMAND || ...`, bash would ignore errexit inside it).
step() {
  local name=$1 start=$SECONDS status
  shift
  set +e
  (set -e; "$@")
  status=$?
  set -e
  if [[ -n ${SHADOWLAB_STEP_LOG:-} ]]; then
    printf '%s\t%d\t%d\n' "$name" $((SECONDS - start)) "$status" >> "$SHADOWLAB_STEP_LOG"
  fi
  return "$status"
}
