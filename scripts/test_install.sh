#!/usr/bin/env bash
# The installed package, as a user sees it (scripts/test.sh runs this after the tests):
# installs build/ into a temporary prefix, builds examples/ against it in a separate build
# directory, and runs an example, the installed command and the installed Python package from
# outside the source tree, checking that they read the installed built-in scenes.
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

# The installed Python package (a build with the module), imported from its site directory
# below the prefix, finds the installed data beside itself: it renders the scene only the
# prefix has.
module=$(find "$prefix" -name "_shadowlab*.so" -print -quit)
python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$source_dir/build/CMakeCache.txt")   # the module's interpreter
if [ -n "$module" ]; then
    PYTHONPATH=$(dirname "$(dirname "$module")") "${python:-/usr/bin/python3}" - "$prefix" <<'PYTHON' || fail "the installed Python package failed"
import os, sys
import shadowlab
prefix = sys.argv[1]
assert shadowlab.__file__.startswith(prefix), shadowlab.__file__
assert shadowlab.scene_dir() == os.path.join(prefix, "share", "shadowlab", "scenes"), shadowlab.scene_dir()
scene = shadowlab.load_scene("only-installed")
scene.apply_overrides(width=32, height=20)
frame = shadowlab.render(shadowlab.prepare(scene), "shadow-map", {"resolution": 64})
assert frame.visibility.shape == (20, 32) and frame.hit.any()
print("test_install: the installed Python package rendered", scene.name, "from", shadowlab.scene_dir())
PYTHON
fi
echo "test_install: the installed package works ($prefix)"
