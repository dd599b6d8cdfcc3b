#!/bin/sh
# Pictures and figures of docs/lessons/07-irregular-z-buffer.md: the irregular z-buffer on
# sphere-box (480 x 300, 2 threads), its light grid's lists of receivers, their occupancy
# and the occluders covering each texel; the grid's resolution, which moves the work and
# never V, and a grazing light, which lengthens the lists.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
need_convert
work=receiver_pixels,resolution_texels,list_max_receivers,list_mean_nonempty_receivers,empty_texels_percent
work=$work,texel_triangle_pairs_count,segment_tests_count

# lists NAME OUT.png [CONVERT ARGS...]: NAME's list-length buffer, which maps 0 .. the longest
# list to black .. white, stretched so that lists of 8 receivers or more are white.
lists() {
  name=$1; out=$2; shift 2
  percent=$(python3 -c 'import json, sys
print(min(100.0, 800.0 / json.load(open(sys.argv[1]))["stats"]["list_max_receivers"]))' "$scratch/$name.json")
  $convert "$scratch/$name-buffers/izb-list-length.png" -level "0%,$percent%" "$@" "$out"
}

# shot NAME [RENDER ARGS...]: sphere-box's image, error map, figures and buffers into $scratch/NAME*
shot() {
  name=$1; shift
  "$app" render assets/scenes/sphere-box.json --technique izb "$@" --width 480 --height 300 --threads 2 \
    -o "$scratch/$name.png" --error-map "$scratch/$name-error.png" --json "$scratch/$name.json" \
    --debug-buffers "$scratch/$name-buffers" > "$scratch/$name.log"
}

# The stages at the automatic resolution (about 2 receivers per non-empty texel).
shot auto
for buffer in occupancy occluders; do
  cp "$scratch/auto-buffers/izb-$buffer.png" "$images/$buffer.png"
done
lists auto "$images/list-length.png"
cp "$scratch/auto.png" "$images/final.png"
cp "$scratch/auto-error.png" "$images/error.png"

# The resolution: the same V, different work.
for resolution in 64 2048; do
  shot "resolution-$resolution" --param resolution="$resolution"
done
lists resolution-64 "$images/list-length-64.png" -scale 343x343
# A 512 x 512 window of the 2048 grid around the sphere, at one pixel per texel.
lists resolution-2048 "$images/list-length-2048-window.png" -crop 512x512+400+450 +repage
echo "izb, sphere-box, light-grid resolution:"
$figures --stats "$work" "64=$scratch/resolution-64.json" "auto=$scratch/auto.json" \
  "2048=$scratch/resolution-2048.json"

# A grazing light: the ground's receivers crowd into few texels along the light's rays.
shot grazing --light-pos 9,1.5,3
lists grazing "$images/list-length-grazing.png"
cp "$scratch/grazing.png" "$images/grazing.png"
echo "izb, sphere-box, the light at (9, 1.5, 3), automatic resolution:"
$figures --stats "$work" "grazing light=$scratch/grazing.json"

# The figures of the page's "Try this" list.
shot try-16 --param resolution=16
"$app" render assets/scenes/hard/point-light-inside.json --technique izb --width 480 --height 300 --threads 2 \
  -o "$scratch/try-point-inside.png" --error-map "$scratch/try-point-inside-error.png" \
  --json "$scratch/try-point-inside.json" > "$scratch/try-point-inside.log"
echo "Try this:"
$figures --stats views_count,list_mean_nonempty_receivers,segment_tests_count \
  "sphere-box, resolution=16=$scratch/try-16.json" "point-light-inside=$scratch/try-point-inside.json"
