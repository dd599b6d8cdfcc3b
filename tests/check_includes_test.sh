#!/usr/bin/env bash
# The include check must fail where a family includes another the rule does not name,
# and pass where the include is allowed: a planted violation in a scratch tree.
set -euo pipefail
source_dir=$1 scratch=$2
rm -rf "$scratch" && mkdir -p "$scratch/docs" "$scratch/shadows/izb" "$scratch/shadows/volumes"
cp "$source_dir/docs/architecture.md" "$scratch/docs/"
printf '#include "shadows/technique.h"\n#include "shadows/silhouettes/silhouette.h"\n' > "$scratch/shadows/volumes/allowed.cpp"
python3 "$source_dir/scripts/check_includes.py" "$scratch"
printf '#include "shadows/reference/reference.h"\n' > "$scratch/shadows/izb/planted.cpp"
if output=$(python3 "$source_dir/scripts/check_includes.py" "$scratch"); then
    echo "FAIL: a family including another passed the check"; exit 1
fi
grep -q '^shadows/izb/planted.cpp:1: includes shadows/reference/reference.h' <<<"$output" ||
    { echo "FAIL: the violation was not named: $output"; exit 1; }
echo "the check names the planted violation: $output"
