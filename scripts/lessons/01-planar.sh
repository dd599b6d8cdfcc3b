#!/bin/sh
# Pictures and figures of docs/lessons/01-planar.md: planar projected shadows and projected
# shadow textures on sphere-box (480 x 300, 2 threads), their buffers, and the failures:
# no shadow off the plane as the light moves, and shadows cast backward on backward-cast.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh

# shot NAME SCENE [RENDER ARGS...]: image, error map, figures and buffers into $scratch/NAME*
shot() {
  name=$1; shift
  "$app" render "$@" --width 480 --height 300 --threads 2 -o "$scratch/$name.png" \
    --error-map "$scratch/$name-error.png" --json "$scratch/$name.json" \
    --debug-buffers "$scratch/$name-buffers" > "$scratch/$name.log"
}

# Planar projected shadows: the stencil, the classic translucent composite, V in the image.
shot planar assets/scenes/sphere-box.json --technique planar
cp "$scratch/planar-buffers/planar-stencil.png" "$images/planar-stencil.png"
cp "$scratch/planar-buffers/planar-shadow.png" "$images/planar-shadow.png"
cp "$scratch/planar.png" "$images/planar-final.png"
cp "$scratch/planar-error.png" "$images/planar-error.png"

# The failure: nothing off the plane is shadowed; a lower light shows more of it.
for light in 2,3,4 6,3,3; do
  shot "planar-light-$light" assets/scenes/sphere-box.json --technique planar --light-pos "$light"
  cp "$scratch/planar-light-$light-error.png" "$images/planar-error-light-$(echo "$light" | tr , _).png"
done
echo "planar, sphere-box, light position (--light-pos):"
$figures "4,8,3 (the scene's)=$scratch/planar.json" "2,3,4=$scratch/planar-light-2,3,4.json" \
  "6,3,3=$scratch/planar-light-6,3,3.json"

# Projected shadow textures: the occluders' texture from the light, the receivers, V.
shot projected assets/scenes/sphere-box.json --technique projected-texture --param resolution=256
cp "$scratch/projected-buffers/projected-texture-texture.png" "$images/projected-texture.png"
cp "$scratch/projected-buffers/projected-texture-receivers.png" "$images/projected-receivers.png"
cp "$scratch/projected-error.png" "$images/projected-error.png"

# The failures the application's choice of roles brings: backward-cast's screen between the
# light and the card.
shot backward-auto assets/scenes/projected/backward-cast.json --technique projected-texture
shot backward-chosen assets/scenes/projected/backward-cast.json --technique projected-texture \
  --param occluders=card --param receivers=ground+screen
cp "$scratch/backward-auto-error.png" "$images/backward-auto-error.png"
cp "$scratch/backward-chosen-error.png" "$images/backward-chosen-error.png"
echo "projected-texture, sphere-box (resolution=256) and backward-cast (roles):"
$figures "sphere-box, auto roles=$scratch/projected.json" "backward-cast, auto roles=$scratch/backward-auto.json" \
  "backward-cast, occluders=card receivers=ground+screen=$scratch/backward-chosen.json"

# The figures of the page's "Try this" list.
shot try-plane assets/scenes/sphere-box.json --technique planar --param plane-y=0.5
shot try-low-light assets/scenes/sphere-box.json --technique planar --light-pos 0,1.5,3
shot try-receivers assets/scenes/sphere-box.json --technique projected-texture --param receivers=ground+sphere
echo "Try this:"
$figures --stats receiver_pixels "planar, plane-y=0.5=$scratch/try-plane.json" \
  "planar, light at (0, 1.5, 3)=$scratch/try-low-light.json" \
  "projected-texture, receivers=ground+sphere=$scratch/try-receivers.json"
