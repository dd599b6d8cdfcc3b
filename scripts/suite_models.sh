#!/usr/bin/env bash
# The benchmark suite's real models (assets/scenes/suite/, docs/performance.md, "Real
# models"): installs the Debian packages that hold them where they are missing, and converts
# the IFC house to glTF into the suite's cache folder, assets/scenes/suite/cache/ (which git
# ignores; house.json names it there). The models are never copied into the repository:
# their sizes and some of their licences forbid it.
#
#   scripts/suite_models.sh [--no-install] [assimp] [castle]   (default: both sets)
#     assimp  assimp-testmodels (the engine, the house's IFC) and assimp-utils (`assimp
#             export`): engine.json, house.json
#     castle  castle-game-engine-doc (256 MB; the oak, the dungeon): grove.json, dungeon.json
#     --no-install  install nothing: fail, naming the package, where one is missing (the tests)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
install=yes
sets=()
for arg in "$@"; do
  case $arg in
    --no-install) install=no ;;
    assimp|castle) sets+=("$arg") ;;
    *) echo "usage: scripts/suite_models.sh [--no-install] [assimp] [castle]" >&2; exit 2 ;;
  esac
done
[ ${#sets[@]} -gt 0 ] || sets=(assimp castle)

ifc=/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc
cache=assets/scenes/suite/cache
castle=/usr/share/doc/castle-game-engine-doc/examples
# package, then the files of it the suite's scenes read
assimp_files=(assimp-testmodels /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb "$ifc"
              assimp-utils /usr/bin/assimp)
castle_files=(castle-game-engine-doc "$castle/terrain/data/oak_tree/oaktree.gltf"
              "$castle/creature_behaviors/data/level/level-dungeon.gltf")

source scripts/install_missing.sh
# Every file of a set is there after installing its packages, or a one-line error says which.
need() {
  local package="" item
  for item in "$@"; do
    if [[ $item != /* ]]; then
      package=$item
      [[ $install == no ]] || install_missing "$package"
    elif [[ ! -f $item ]]; then
      echo "suite_models.sh: $item is missing: install Debian's $package (scripts/suite_models.sh does)" >&2
      exit 1
    fi
  done
}
for set in "${sets[@]}"; do
  case $set in
    assimp)
      need "${assimp_files[@]}"
      # The house, once: assimp's glb2 export (glTF 2.0, binary) writes the same bytes each time.
      if [[ ! -f $cache/AC14-FZK-Haus.glb || $ifc -nt $cache/AC14-FZK-Haus.glb ]]; then
        mkdir -p "$cache"
        assimp export "$ifc" "$cache/AC14-FZK-Haus.tmp.glb" -f glb2 > /dev/null
        mv "$cache/AC14-FZK-Haus.tmp.glb" "$cache/AC14-FZK-Haus.glb"
      fi ;;
    castle) need "${castle_files[@]}" ;;
  esac
done
