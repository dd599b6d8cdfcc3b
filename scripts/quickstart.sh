#!/usr/bin/env bash
# The first picture: install what the shadowlab command needs and build the command alone
# (scripts/setup.sh command), then render sphere-box with the exact reference and with the
# default shadow map, and score the shadow map against the reference. Outputs go to out/.
# scripts/test.sh installs and builds the rest.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh command
mkdir -p out
build/app/shadowlab render sphere-box --technique reference -o out/sphere-box-reference.png --aov out/sphere-box-reference.exr
build/app/shadowlab render sphere-box --technique shadow-map -o out/sphere-box-shadow-map.png --aov out/sphere-box-shadow-map.exr \
    --error-map out/sphere-box-shadow-map-errors.png
build/app/shadowlab compare out/sphere-box-reference.exr out/sphere-box-shadow-map.exr --heatmap out/sphere-box-shadow-map-diff.png
echo "images in out/: sphere-box-reference.png, sphere-box-shadow-map.png, sphere-box-shadow-map-errors.png, sphere-box-shadow-map-diff.png"
