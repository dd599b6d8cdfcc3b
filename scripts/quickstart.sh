#!/usr/bin/env bash
# The main job: set up, render sphere-box unshadowed and with the exact reference, and
# score the unshadowed image against the reference. Outputs go to out/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh
mkdir -p out
build/app/shadowlab render sphere-box --technique reference -o out/sphere-box-reference.png --aov out/sphere-box-reference.exr
build/app/shadowlab render sphere-box --technique none -o out/sphere-box-none.png --aov out/sphere-box-none.exr
build/app/shadowlab compare out/sphere-box-reference.exr out/sphere-box-none.exr --heatmap out/sphere-box-none-diff.png
echo "images in out/: sphere-box-reference.png, sphere-box-none.png, sphere-box-none-diff.png"
