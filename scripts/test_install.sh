#!/usr/bin/env bash
# The installed package, as a user sees it (scripts/test.sh runs this after the tests):
# installs build/ into a temporary prefix, builds examples/ against it in a separate build
# directory, and runs an example and the installed command from outside the source tree,
# checking that they read the installed built-in scenes.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source_dir=$(pwd)

scratch=$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-install.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
prefix=$scratch/prefix
unset SHADOWLAB_SCENE_DIR   # the override would hide which directory is found

fail() { echo "test_install: $*" >&2; exit 1; }

cmake --install build --prefix "$prefix" > "$scratch/install.log"
for f in bin/shadowlab include/shadowlab/frame/render.h include/shadowlab/raster/simd/simd_avx2.h \
         lib/cmake/shadowlab/shadowlabConfig.cmake lib/cmake/shadowlab/FindStb.cmake \
         share/shadowlab/scenes/sphere-box.json share/shadowlab/meshes/LICENSE.md \
         share/shadowlab/scenes/hard/sun.json share/shadowlab/textures/leaf.png share/shadowlab/photos/LICENSE.md; do
    [ -e "$prefix/$f" ] || fail "$f is not installed"
done
! grep -rq "$source_dir" "$prefix/lib/cmake/shadowlab" || fail "the CMake package names the source tree"

cmake -S examples -B "$scratch/build-examples" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
    > "$scratch/configure.log" || { cat "$scratch/configure.log"; fail "configuring the examples failed"; }
cmake --build "$scratch/build-examples" -j"$(nproc)"

# From a directory outside the source tree: a built-in scene with a mesh file (bunny).
cd "$scratch"
"$scratch/build-examples/render_and_score" bunny.png bunny shadow-map --size 320 200 | tee render.log
grep -qxF "built-in scenes: $prefix/share/shadowlab/scenes" render.log ||
    fail "the example did not use the installed scenes"
[ -s bunny.png ] && [ -s bunny-errors.png ] || fail "the example wrote no image"
# The installed command finds the scenes beside itself: a scene only the prefix has.
cp "$prefix/share/shadowlab/scenes/sphere-box.json" "$prefix/share/shadowlab/scenes/only-installed.json"
"$prefix/bin/shadowlab" render only-installed --technique shadow-map --width 160 --height 100 -o command.png
[ -s command.png ] || fail "the installed command wrote no image"
echo "test_install: the installed package works ($prefix)"
