#!/bin/sh
# Pictures and figures of docs/lessons/05-cascades-and-warping.md: perspective aliasing of
# one sun shadow map on assets/scenes/hard/sun.json seen low and close (480 x 300, 2 threads), then
# cascaded shadow maps (splits, the cascades' maps, texel density) against the number of
# cascades and the split scheme, then LiSPSM's warp and its dueling-frusta limit.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
scene=assets/scenes/hard/sun.json
view="--eye -3.2,1.1,1.8 --target 0,0.2,-1 --fovy 55"

# shot NAME SCENE TECHNIQUE [RENDER ARGS...]: image, error map, figures and buffers into $scratch/NAME*
shot() {
  name=$1; file=$2; technique=$3; shift 3
  "$app" render "$file" --technique "$technique" $view "$@" --width 480 --height 300 --threads 2 \
    -o "$scratch/$name.png" --error-map "$scratch/$name-error.png" --json "$scratch/$name.json" \
    --debug-buffers "$scratch/$name-buffers" > "$scratch/$name.log"
}

# One map of 512 x 512 texels fitted to everything the camera sees.
shot single "$scene" shadow-map --param resolution=512
cp "$scratch/single.png" "$images/single.png"
cp "$scratch/single-buffers/shadow-map-depth.png" "$images/single-depth.png"
cp "$scratch/single-buffers/shadow-map-texel-density.png" "$images/single-texel-density.png"

# Four cascades of 256 x 256: the same number of texels.
shot csm "$scene" csm --param resolution=256
cp "$scratch/csm.png" "$images/csm.png"
cp "$scratch/csm-buffers/csm-cascades.png" "$images/csm-cascades.png"
cp "$scratch/csm-buffers/csm-texel-density.png" "$images/csm-texel-density.png"
for k in 0 1 2 3; do
  cp "$scratch/csm-buffers/csm-depth-cascade$k.png" "$images/csm-depth-cascade$k.png"
done
echo "csm, 4 cascades (practical split, lambda 0.75, sample bounds): split distances, m from the eye:"
python3 -c 'import json, sys
stats = json.load(open(sys.argv[1]))["stats"]
for k in range(int(stats["cascades_count"])):
    near, far = stats["cascade%d_split_near_m" % k], stats["cascade%d_split_far_m" % k]
    print("cascade %d: %.3f .. %.3f" % (k, near, far))' \
  "$scratch/csm.json"

# The number of cascades, each 256 x 256.
for count in 1 2 8; do
  shot "cascades-$count" "$scene" csm --param resolution=256 --param cascades="$count"
done
cp "$scratch/cascades-1.png" "$images/cascades-1.png"
cp "$scratch/cascades-8-buffers/csm-cascades.png" "$images/cascades-8-colouring.png"
echo "one shadow map of 512^2 texels, and csm with 256^2 texels per cascade:"
$figures --stats median_texels_per_pixel "shadow-map, 512=$scratch/single.json" \
  "csm, 1 cascade=$scratch/cascades-1.json" "csm, 2 cascades=$scratch/cascades-2.json" \
  "csm, 4 cascades=$scratch/csm.json" "csm, 8 cascades=$scratch/cascades-8.json"

# The split scheme, 4 cascades.
for split in uniform log; do
  shot "split-$split" "$scene" csm --param resolution=256 --param split="$split"
done
echo "csm, 4 cascades of 256^2, split scheme:"
$figures --stats median_texels_per_pixel "uniform=$scratch/split-uniform.json" "log (eq. 7.5)=$scratch/split-log.json" \
  "practical, lambda 0.75=$scratch/csm.json"

# LiSPSM: the same 512 x 512 map, warped towards the eye.
shot lispsm "$scene" shadow-map --param resolution=512 --param warp=lispsm
cp "$scratch/lispsm.png" "$images/lispsm.png"
cp "$scratch/lispsm-buffers/shadow-map-depth.png" "$images/lispsm-depth.png"
cp "$scratch/lispsm-buffers/shadow-map-texel-density.png" "$images/lispsm-texel-density.png"

# Dueling frusta's neighbour: the sun behind the camera, where sin(gamma) is small.
behind="$scratch/sun-behind-camera.json"
python3 -c 'import json, sys
scene = json.load(open(sys.argv[1]))
scene["lights"][0]["direction"] = [-3.2, 2, 2.8]
json.dump(scene, open(sys.argv[2], "w"), indent=1)' "$scene" "$behind"
shot behind-single "$behind" shadow-map --param resolution=512
shot behind-lispsm "$behind" shadow-map --param resolution=512 --param warp=lispsm
cp "$scratch/behind-lispsm-buffers/shadow-map-texel-density.png" "$images/behind-lispsm-texel-density.png"
echo "shadow-map 512, warp, sun direction:"
$figures --stats median_texels_per_pixel,lispsm_n_opt_m \
  "lispsm, the scene's sun (4, 8, 3)=$scratch/lispsm.json" \
  "lispsm, sun behind the camera (-3.2, 2, 2.8)=$scratch/behind-lispsm.json"
$figures --stats median_texels_per_pixel \
  "none, the scene's sun=$scratch/single.json" "none, sun behind the camera=$scratch/behind-single.json"

# The figures of the page's "Try this" list.
shot try-camera-bounds "$scene" csm --param resolution=256 --param bounds=camera
shot try-no-snap "$scene" csm --param resolution=256 --param snap=off
echo "Try this (csm, 4 cascades of 256^2):"
$figures --stats cascade0_split_far_m,cascade1_split_far_m,cascade2_split_far_m \
  "bounds=camera=$scratch/try-camera-bounds.json" "snap=off=$scratch/try-no-snap.json" \
  "the default=$scratch/csm.json"
