#!/bin/sh
# Pictures and figures of docs/lessons/04-filtered-maps.md: variance shadow maps' buffers
# (linear depth, moments, filtered moments, their variance) on torus-over-plane (480 x 300,
# 2 threads), light bleeding where the torus's penumbra crosses the green plane's umbra
# against bleeding-reduction, the four moment kinds side by side, and the filter's width.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
need_convert
scene=assets/scenes/soft/torus-over-plane.json
size="--width 480 --height 300 --threads 2"
# The enlarged part of the image where the torus's shadow leaves the green plane's umbra.
crop="-crop 240x150+100+100 +repage -scale 200%"

# The exact soft shadow, scored against once: every shot below compares with it.
"$app" render "$scene" --technique reference-soft $size -o "$scratch/reference.png" \
  --aov "$scratch/reference.exr" > "$scratch/reference.log"
$convert "$scratch/reference.png" $crop "$images/reference-crop.png"

# shot NAME TECHNIQUE [RENDER ARGS...]: image, buffers, heat map and error figures into $scratch/NAME*
shot() {
  name=$1; technique=$2; shift 2
  "$app" render "$scene" --technique "$technique" "$@" $size -o "$scratch/$name.png" --aov "$scratch/$name.exr" \
    --debug-buffers "$scratch/$name-buffers" > "$scratch/$name.log"
  "$app" compare "$scratch/reference.exr" "$scratch/$name.exr" --heatmap "$scratch/$name-diff.png" \
    --json "$scratch/$name.json" > "$scratch/$name-compare.log"
  $convert "$scratch/$name.png" $crop "$scratch/$name-crop.png"
}

# VSM's stages, without light-bleeding reduction, over a 15-texel box.
shot vsm-0 vsm --param filter-width=15 --param bleeding-reduction=0
buffers="$scratch/vsm-0-buffers"
for buffer in linear-depth filtered1; do
  $convert "$buffers/vsm-$buffer.png" -resize 512x512 "$images/vsm-$buffer.png"
done
# The variance the Chebyshev bound reads, sigma^2 = M2 - M1^2, from the two filtered EXR
# buffers: 0 black, 0.02 (normalised depth squared) and above white.
$convert "$buffers/vsm-filtered2.exr" "$buffers/vsm-filtered1.exr" -fx "min(1, 50*(u - v*v))" -depth 8 \
  -resize 512x512 "$images/vsm-variance.png"
cp "$scratch/reference.png" "$images/reference.png"

# Light bleeding against bleeding-reduction.
for amount in 0.2 0.5; do
  shot "vsm-$amount" vsm --param filter-width=15 --param bleeding-reduction="$amount"
done
for amount in 0 0.2 0.5; do
  cp "$scratch/vsm-$amount-crop.png" "$images/vsm-bleeding-$amount-crop.png"
done
for amount in 0 0.5; do
  cp "$scratch/vsm-$amount-diff.png" "$images/vsm-bleeding-$amount-diff.png"
done
echo "vsm, filter-width=15, bleeding-reduction:"
$figures "0=$scratch/vsm-0.json" "0.2 (default)=$scratch/vsm-0.2.json" "0.5=$scratch/vsm-0.5.json"

# The other moment kinds over the same box.
for kind in esm evsm msm; do
  shot "$kind" "$kind" --param filter-width=15
  cp "$scratch/$kind-crop.png" "$images/$kind-crop.png"
done
echo "filter-width=15, the moment kinds at their defaults:"
$figures "vsm (bleeding-reduction 0.2)=$scratch/vsm-0.2.json" "esm (c = 80)=$scratch/esm.json" \
  "evsm (c+ = 40, c- = 5)=$scratch/evsm.json" "msm=$scratch/msm.json"

# The filter's width: fixed, or PCSS's per pixel over a summed-area table.
shot vsm-7 vsm
shot vsm-pcss vsm --param filter=sat --param width=pcss
cp "$scratch/vsm-7.png" "$images/vsm-width-7.png"
cp "$scratch/vsm-pcss.png" "$images/vsm-width-pcss.png"
cp "$scratch/vsm-pcss-buffers/vsm-filter-width.png" "$images/vsm-pcss-filter-width.png"
cp "$scratch/vsm-pcss-diff.png" "$images/vsm-width-pcss-diff.png"
echo "vsm (bleeding-reduction 0.2), filter width:"
$figures "fixed 7 texels (default)=$scratch/vsm-7.json" "fixed 15 texels=$scratch/vsm-0.2.json" \
  "width=pcss, filter=sat=$scratch/vsm-pcss.json"
