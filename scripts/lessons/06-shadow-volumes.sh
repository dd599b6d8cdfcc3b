#!/bin/sh
# Pictures and figures of docs/lessons/06-shadow-volumes.md: stencil shadow volumes on
# sphere-box (480 x 300, 2 threads), their silhouettes, fill and stencil counts from the
# scene's camera, then from a camera inside the sphere's shadow, where z-pass counts from
# the wrong start and z-fail does not; the fill each mode costs.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
inside="--eye -1,0.5,-0.8 --target 2,0.6,-1 --fovy 60"

size="--width 480 --height 300 --threads 2"

# shot NAME [RENDER ARGS...]: sphere-box's image, error map, figures and buffers into $scratch/NAME*
shot() {
  name=$1; shift
  render "$name" assets/scenes/sphere-box.json shadow-volume "$@" --debug-buffers "$scratch/$name-buffers"
}

# The stages from the scene's camera (auto: z-pass here), and z-fail's fill with its caps.
for mode in zpass zfail; do
  shot "outside-$mode" --param mode="$mode"
  cp "$scratch/outside-$mode-buffers/shadow-volume-fill.png" "$images/outside-$mode-fill.png"
done
shot outside-auto
cp "$scratch/outside-auto-buffers/shadow-volume-silhouette.png" "$images/silhouette.png"
cp "$scratch/outside-auto-buffers/shadow-volume-stencil.png" "$images/stencil.png"
cp "$scratch/outside-auto.png" "$images/final.png"
cp "$scratch/outside-auto-error.png" "$images/error.png"

# The camera inside the sphere's shadow.
for mode in auto zpass zfail; do
  shot "inside-$mode" $inside --param mode="$mode"
done
cp "$scratch/inside-auto.png" "$images/inside.png"
for mode in zpass zfail; do
  cp "$scratch/inside-$mode-error.png" "$images/inside-$mode-error.png"
  cp "$scratch/inside-$mode-buffers/shadow-volume-stencil.png" "$images/inside-$mode-stencil.png"
done
cp "$scratch/inside-zfail-buffers/shadow-volume-fill.png" "$images/inside-zfail-fill.png"
echo "shadow-volume, sphere-box, camera and mode:"
$figures --stats zfail_flag,near_plane_shadowed_flag,silhouette_edges,fill_fragments_per_pixel \
  "scene's camera, auto=$scratch/outside-auto.json" "scene's camera, zpass=$scratch/outside-zpass.json" \
  "scene's camera, zfail=$scratch/outside-zfail.json" "inside the shadow, auto=$scratch/inside-auto.json" \
  "inside the shadow, zpass=$scratch/inside-zpass.json" "inside the shadow, zfail=$scratch/inside-zfail.json"
