#!/usr/bin/env bash
# Runs each libFuzzer target of tests/fuzz for a bounded time, starting from its seed corpus
# in the repository. The targets are built by scripts/sanitize.sh (clang-14, ASan + UBSan,
# SHADOWLAB_FUZZ=ON) in build-asan/, so a memory error, undefined behaviour, a leak, an
# input that runs longer than 10 s, grows past 8 GiB or asks for too much at once, or an exception other than the
# loader's documented error stops the run and fails this script; the input that did it is
# written to <build>/fuzz/artifacts/. The total memory bound leaves room for the largest
# input the limits allow (an EXR of 16 float channels at 8192 x 8192 pixels is 4 GiB);
# single allocations are bounded per target, below.
#
#   scripts/fuzz.sh [build-dir] [seconds per target] [targets...]
#
# .ci/run gives each target 20 s from its seeds; docs/reliability.md ("Reliability") says how to run them
# for hours.
# SHADOWLAB_FUZZ_FLAGS adds libFuzzer flags after the defaults (a later flag wins): on a
# busy machine, -timeout=60, since the timeout is wall-clock time.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build-asan}
seconds=${2:-60}
shift $(( $# < 2 ? $# : 2 ))
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(scene_file compositing_file camera_path obj_reader ply_reader exr_reader environment_file gltf_file)

# Extra seeds beside tests/fuzz/corpus/<target>: the built-in scene files (copied, since
# libFuzzer reads folders recursively and assets/scenes/ also holds fly-through paths) and
# the tiny meshes.
rm -rf "$build/fuzz/seeds/scene_file" && mkdir -p "$build/fuzz/seeds/scene_file"
for file in assets/scenes/*.json assets/scenes/*/*.json; do cp "$file" "$build/fuzz/seeds/scene_file/${file//\//_}"; done
declare -A more_seeds=(
  [scene_file]="$build/fuzz/seeds/scene_file"
  [compositing_file]="assets/scenes/compositing"
  [camera_path]="assets/scenes/flythrough"
  [obj_reader]="tests/fuzz/meshes"
  [ply_reader]="tests/fuzz/meshes"
  [exr_reader]=""
  [environment_file]=""
  [gltf_file]=""
)
# The largest single allocation an input within the limits may ask for: an EXR channel of
# 8192 x 8192 floats or a tile of 16 (256 MB); a scene's vectors of 2^25 triangles (400 MB,
# twice that while growing); an environment map of 8192^2 RGB floats (805 MB). A larger one
# is a finding (the EXR headers that asked for 2 GB).
declare -A malloc_limit_mb=([scene_file]=2048 [compositing_file]=2048 [camera_path]=1024 [obj_reader]=2048 [ply_reader]=2048 [exr_reader]=1024 [environment_file]=1024 [gltf_file]=2048)
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p "$build/fuzz/artifacts"
for target in "${targets[@]}"; do
  binary=$build/tests/fuzz/fuzz_$target
  [[ -x $binary ]] || { echo "fuzz.sh: no $binary; build it with scripts/sanitize.sh" >&2; exit 1; }
  corpus=$build/fuzz/corpus/$target   # what the fuzzer finds; the repository's seeds stay as they are
  mkdir -p "$corpus"
  dictionary=()
  [[ -f tests/fuzz/$target.dict ]] && dictionary=(-dict="tests/fuzz/$target.dict")
  echo "fuzz.sh: $target for $seconds s" >&2
  # shellcheck disable=SC2086 # the extra seed folders are a word list
  "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=8192 -malloc_limit_mb="${malloc_limit_mb[$target]}" -print_final_stats=1 \
      -artifact_prefix="$build/fuzz/artifacts/$target-" "${dictionary[@]}" ${SHADOWLAB_FUZZ_FLAGS:-} \
      "$corpus" "tests/fuzz/corpus/$target" ${more_seeds[$target]}
done
