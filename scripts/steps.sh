# Sourced by the scripts CI runs: `step NAME COMMAND...` runs COMMAND and, where
# SHADOWLAB_STEP_LOG names a file (.ci/run sets it), appends the step's name, its wall time
# in seconds and its exit status, from which .ci/run prints its step table.
step() {
  local name=$1 start=$SECONDS status=0
  shift
  "$@" || status=$?
  if [[ -n ${SHADOWLAB_STEP_LOG:-} ]]; then
    printf '%s\t%d\t%d\n' "$name" $((SECONDS - start)) "$status" >> "$SHADOWLAB_STEP_LOG"
  fi
  return "$status"
}
