#!/bin/sh
# Pictures and figures of docs/lessons/02-shadow-maps-and-bias.md: a shadow map on
# sphere-box (480 x 300, 2 threads), its depth map and texel density from the scene's
# camera, then a close view of the box and the sphere where the constant bias moves acne
# into leaks and the resolution moves the staircase.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
close="--eye -1.5,2.2,-4.5 --target 1.2,0.3,-1 --fovy 45"

size="--width 480 --height 300 --threads 2"

# shot NAME [RENDER ARGS...]: sphere-box's image, error map, figures and buffers into $scratch/NAME*
shot() {
  name=$1; shift
  render "$name" assets/scenes/sphere-box.json shadow-map "$@" --debug-buffers "$scratch/$name-buffers"
}

# The stages from the scene's camera: the depth map, the texel density, V.
shot overview --param resolution=512
cp "$scratch/overview-buffers/shadow-map-depth.png" "$images/depth-map.png"
cp "$scratch/overview-buffers/shadow-map-texel-density.png" "$images/texel-density.png"
cp "$scratch/overview.png" "$images/final.png"
cp "$scratch/overview-error.png" "$images/error.png"
echo "shadow-map, sphere-box, resolution=512, the default bias (slope-scaled 1.5, 4):"
$figures --stats median_texels_per_pixel,light_near_m,light_far_m "scene's camera=$scratch/overview.json"

# Acne and leaks: the constant bias, from too small to too large, in the close view.
for bias in 0.01 0.1 0.6; do
  shot "constant-$bias" $close --param resolution=512 --param bias=constant --param constant-bias="$bias"
  cp "$scratch/constant-$bias-error.png" "$images/close-constant-$bias-error.png"
done
cp "$scratch/constant-0.1.png" "$images/close-final.png"
cp "$scratch/constant-0.1-buffers/shadow-map-texel-density.png" "$images/close-texel-density.png"
echo "shadow-map, close view, resolution=512, bias=constant, constant-bias:"
$figures "0.01 m=$scratch/constant-0.01.json" "0.1 m=$scratch/constant-0.1.json" "0.6 m=$scratch/constant-0.6.json"

# The other bias models at the same resolution and view.
shot slope $close --param resolution=512
shot normal $close --param resolution=512 --param bias=normal-offset
shot plane $close --param resolution=512 --param bias=receiver-plane
echo "shadow-map, close view, resolution=512, bias model:"
$figures "slope-scaled (1.5, 4)=$scratch/slope.json" "normal-offset (1 texel + 0.05 m)=$scratch/normal.json" \
  "receiver-plane=$scratch/plane.json"

# The staircase: the resolution, with the default bias.
for resolution in 128 2048; do
  shot "resolution-$resolution" $close --param resolution="$resolution"
  cp "$scratch/resolution-$resolution-error.png" "$images/close-resolution-$resolution-error.png"
done
cp "$scratch/resolution-128.png" "$images/close-resolution-128.png"
echo "shadow-map, close view, the default bias, resolution:"
$figures --stats median_texels_per_pixel "128=$scratch/resolution-128.json" "512=$scratch/slope.json" \
  "2048=$scratch/resolution-2048.json"

# The figures of the page's "Try this" list, from the scene's camera at 512 texels.
shot try-no-bias --param resolution=512 --param bias=constant --param constant-bias=0
shot try-no-slope --param resolution=512 --param slope-factor=0 --param slope-units=4
shot try-second --param resolution=512 --param layer=second
shot try-midpoint --param resolution=512 --param layer=midpoint
shot try-grazing --param resolution=512 --light-pos 9,1.5,3
echo "Try this (the scene's camera, resolution=512):"
$figures --stats median_texels_per_pixel "bias=constant, constant-bias=0=$scratch/try-no-bias.json" \
  "slope-factor=0, slope-units=4=$scratch/try-no-slope.json" "layer=second=$scratch/try-second.json" \
  "layer=midpoint=$scratch/try-midpoint.json" "the default=$scratch/overview.json" \
  "light at (9, 1.5, 3)=$scratch/try-grazing.json"
