#!/usr/bin/env bash
# The include check must fail where a family includes another the rule does not name, where
# files include each other, and where the rule lets two folders include each other;
# and pass where the include is allowed: planted violations in a scratch tree.
set -euo pipefail
source_dir=$1 scratch=$2
rm -rf "$scratch" && mkdir -p "$scratch/docs" "$scratch/shadows/izb" "$scratch/shadows/volumes"
cp "$source_dir/docs/architecture.md" "$scratch/docs/"
printf '#include "shadows/technique.h"\n#include "shadows/silhouettes/silhouette.h"\n' > "$scratch/shadows/volumes/allowed.cpp"
python3 "$source_dir/scripts/check_includes.py" "$scratch"

# The check must fail on what was planted and name it with a line matching PATTERN.
expect_named() {
    local what=$1 pattern=$2 output
    if output=$(python3 "$source_dir/scripts/check_includes.py" "$scratch"); then
        echo "FAIL: $what passed the check"; exit 1
    fi
    grep -q "$pattern" <<<"$output" || { echo "FAIL: $what was not named: $output"; exit 1; }
    echo "the check names $what: $output"
}

printf '#include "shadows/reference/reference.h"\n' > "$scratch/shadows/izb/planted.cpp"
expect_named "a family including another" '^shadows/izb/planted.cpp:1: includes shadows/reference/reference.h'
rm "$scratch/shadows/izb/planted.cpp"

# Files that include each other, even in one folder, are a cycle the rule cannot see.
printf '#include "shadows/izb/b.h"\n' > "$scratch/shadows/izb/a.h"
printf '#include "shadows/izb/a.h"\n' > "$scratch/shadows/izb/b.cpp"
expect_named "two files including each other" '^include cycle: shadows/izb/a -> shadows/izb/b -> shadows/izb/a$'
rm "$scratch/shadows/izb/a.h" "$scratch/shadows/izb/b.cpp"

sed -i 's#^shadows/izb: shadows$#shadows/izb: shadows shadows/maps#; s#^shadows/maps: shadows$#shadows/maps: shadows shadows/izb#' \
    "$scratch/docs/architecture.md"
expect_named "a rule letting two folders include each other" 'the rule lets shadows/izb and shadows/maps include each other'
