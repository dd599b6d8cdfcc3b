#!/bin/sh
# Pictures and figures of docs/lessons/03-filtering-and-pcss.md: percentage-closer filtering
# of a coarse shadow map, then PCSS's blocker search, penumbra width and Poisson filter, on
# sphere-box (480 x 300, 2 threads) seen closely around the sphere's shadow; the failures:
# noise against filter-taps, and the light's centre standing in for the disk as it grows.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
need_convert
close="--eye -0.5,3.2,3.8 --target -0.4,0.4,-0.6 --fovy 40"

# shot NAME TECHNIQUE [RENDER ARGS...]: sphere-box's image, buffers, error map and figures
# into $scratch/NAME*, and when $reference names the soft reference's EXR for the same
# light, the heat map of V's error against it.
reference=""
shot() {
  name=$1; technique=$2; shift 2
  "$app" render assets/scenes/sphere-box.json --technique "$technique" $close "$@" --width 480 --height 300 --threads 2 \
    -o "$scratch/$name.png" --aov "$scratch/$name.exr" --error-map "$scratch/$name-error.png" \
    --json "$scratch/$name.json" --debug-buffers "$scratch/$name-buffers" > "$scratch/$name.log"
  if [ -n "$reference" ]; then
    "$app" compare "$reference" "$scratch/$name.exr" --heatmap "$scratch/$name-diff.png" \
      > "$scratch/$name-compare.log"
  fi
}

# Percentage-closer filtering of a 256-texel map: the hard staircase becomes a ramp.
for filter in nearest bilinear poisson; do
  shot "pcf-$filter" shadow-map --param resolution=256 --param filter="$filter" --param poisson-radius=2
  cp "$scratch/pcf-$filter.png" "$images/pcf-$filter.png"
done
echo "shadow-map, resolution=256, filter (against the hard reference; poisson: 16 taps, radius 2 texels):"
$figures "nearest=$scratch/pcf-nearest.json" "bilinear=$scratch/pcf-bilinear.json" "poisson=$scratch/pcf-poisson.json"

# soft_reference NAME [RENDER ARGS...]: the exact soft V (the disk's visible fraction) into
# $scratch/NAME.exr, which the next shots compare against.
soft_reference() {
  name=$1; shift
  "$app" render assets/scenes/sphere-box.json --technique reference-soft $close "$@" --width 480 --height 300 --threads 2 \
    -o "$scratch/$name.png" --aov "$scratch/$name.exr" > "$scratch/$name.log"
  reference="$scratch/$name.exr"
}

# PCSS's stages.
soft_reference reference-soft
cp "$scratch/reference-soft.png" "$images/reference-soft.png"
shot pcss pcss
cp "$scratch/pcss-buffers/pcss-depth.png" "$images/pcss-depth.png"
# Blocker distances are mapped from the light's near to far plane and use less than a
# quarter of that range: stretched so that 0 (no blocker) is black and the farthest white.
$convert "$scratch/pcss-buffers/pcss-blocker-distance.png" -auto-level "$images/pcss-blocker-distance.png"
cp "$scratch/pcss-buffers/pcss-penumbra-width.png" "$images/pcss-penumbra-width.png"
cp "$scratch/pcss.png" "$images/pcss-final.png"
cp "$scratch/pcss-diff.png" "$images/pcss-diff.png"

# Noise: the Poisson filter's taps.
for taps in 4 128; do
  shot "taps-$taps" pcss --param filter-taps="$taps"
  cp "$scratch/taps-$taps.png" "$images/pcss-taps-$taps.png"
  cp "$scratch/taps-$taps-diff.png" "$images/pcss-taps-$taps-diff.png"
done
echo "pcss, filter-taps:"
$figures --stats mean_filter_width_texels "4=$scratch/taps-4.json" "32 (default)=$scratch/pcss.json" \
  "128=$scratch/taps-128.json"

# The light's centre stands in for the disk: the error as the disk grows.
for radius in 0.15 1.5; do
  soft_reference "reference-soft-$radius" --light-radius "$radius"
  shot "radius-$radius" pcss --light-radius "$radius"
  cp "$scratch/radius-$radius.png" "$images/pcss-radius-$radius.png"
  cp "$scratch/radius-$radius-diff.png" "$images/pcss-radius-$radius-diff.png"
done
echo "pcss, light radius (--light-radius):"
$figures --stats mean_filter_width_texels "0.15 m=$scratch/radius-0.15.json" "0.5 m (the scene's)=$scratch/pcss.json" \
  "1.5 m=$scratch/radius-1.5.json"
