#!/usr/bin/env bash
# The bytes of the exact references on a set of scenes and lights: one line per case, the
# SHA-256 of the OpenEXR file `shadowlab render --aov` writes (V per light, or the
# reference-env radiance, as float32), so two builds' lists are compared with diff: a change
# to how the references trace must leave every line alone (docs/performance.md, "The exact
# references").
#
# usage: scripts/reference_hashes.sh SHADOWLAB [THREADS]
set -euo pipefail
shadowlab=$1
threads=${2:-2}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scenes=$(cd "$(dirname "$0")/../assets/scenes" && pwd)

hash() {   # name, then the render arguments
  local name=$1
  shift
  local file="$out/${name//\//-}.exr"
  "$shadowlab" render "$@" --threads "$threads" --aov "$file" > /dev/null
  echo "$(sha256sum < "$file" | cut -c1-16)  $name"
}

hash sphere-box-reference sphere-box --technique reference --width 320 --height 200
hash sphere-box-reference-soft sphere-box --technique reference-soft --width 160 --height 100
hash bunny-reference bunny --technique reference --width 160 --height 100
hash bunny-reference-soft bunny --technique reference-soft --width 120 --height 75
for f in "$scenes"/soft/*.json; do
  hash "soft/$(basename "$f" .json)" "$f" --technique reference-soft --width 64 --height 40
done
for f in "$scenes"/volumetric/*.json; do
  hash "volumetric/$(basename "$f" .json)-reference" "$f" --technique reference --width 96 --height 60
  hash "volumetric/$(basename "$f" .json)-reference-soft" "$f" --technique reference-soft --width 96 --height 60 \
    --param samples-per-axis=12
done
for name in hard/spot hard/sun cookies/spot-cookie many-lights/three-lights; do
  hash "$name" "$scenes/$name.json" --technique reference --width 96 --height 60
done
for name in sphere-sky bunny-interior; do
  hash "environment/$name" "$scenes/environment/$name.json" --technique reference-env --width 64 --height 40 \
    --param samples=128
done
