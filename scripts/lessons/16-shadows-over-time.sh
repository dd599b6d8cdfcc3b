#!/bin/sh
# Pictures and figures of docs/lessons/16-shadows-over-time.md: frames of fly-throughs at
# 320 x 200, 2 threads, one run a frame. A still view of square-over-plane's disk light with
# one ray a pixel, raw and accumulated; sphere-stops' moving sphere under a temporally
# accumulated shadow map (the lag, then the settling); a still view of sphere-box under
# confidence-reprojection at 128 texels (the staircase sharpening).
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
need_convert
fly="nice -n 10 $app flythrough --width 320 --height 200 --runs 1 --warmup 0 --threads 2 --images"
still="$scratch/still.csv"
printf 'time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n0,0,4,9,0,0.5,0\n1,0,4,9,0,0.5,0\n' > "$still"

# frame DIR SERIES N KIND: frame N's picture (image, error-map or visibility) of a series.
frame() { echo "$1/$2/$(printf %04d "$3")-$4.png"; }
# rms CSV SETTINGS FRAMES...: the RMS of those frames of the series with those settings.
rms() {
  csv=$1 settings=$2; shift 2
  python3 - "$csv" "$settings" "$@" <<'PY'
import csv, sys
rows = {int(r["frame"]): r for r in csv.DictReader(open(sys.argv[1])) if r["settings"] == sys.argv[2]}
print(" ".join(f"frame {f}: {float(rows[int(f)]['rms']):.4f}" for f in sys.argv[3:]))
PY
}

# 1. One ray a pixel on a still view: frame 0, frame 15 raw, frame 15 accumulated.
$fly assets/scenes/soft/square-over-plane.json --path "$still" --frames 16 --technique ray-traced \
  --param temporal=off,on --out "$scratch/rays" > /dev/null
d="$scratch/rays/square-over-plane-flythrough-ray-traced-frames"
# The square's shadow, magnified 3 times.
for shot in temporal=off:0 temporal=off:15 temporal=on:15; do
  $convert "$(frame "$d" "ray-traced_${shot%:*}" "${shot#*:}" visibility)" -crop 100x50+115+85 +repage -sample 300% \
    "$scratch/rays-${shot%:*}-${shot#*:}.png"
done
$convert "$scratch/rays-temporal=off-0.png" "$scratch/rays-temporal=off-15.png" "$scratch/rays-temporal=on-15.png" \
  -bordercolor white -border 2 +append "$images/rays-still.png"
echo "rays raw:         $(rms "$scratch/rays/square-over-plane-flythrough-ray-traced.csv" temporal=off 0 3 15)"
echo "rays accumulated: $(rms "$scratch/rays/square-over-plane-flythrough-ray-traced.csv" temporal=on 0 3 15)"

# 2. The moving sphere under temporal accumulation: error maps while it moves and after.
$fly assets/scenes/flythrough/sphere-stops.json --technique shadow-map --param filter=poisson \
  --param poisson-rotation=ign --param temporal=off,on --out "$scratch/moving" > /dev/null
d="$scratch/moving/sphere-stops-flythrough-shadow-map-frames"
for f in 5 9 12 20; do
  $convert "$(frame "$d" shadow-map_filter=poisson_poisson-rotation=ign_temporal=on $f error-map)" \
    -crop 200x110+40+50 +repage "$scratch/moving-$f.png"
done
$convert "$scratch/moving-5.png" "$scratch/moving-9.png" "$scratch/moving-12.png" "$scratch/moving-20.png" \
  -bordercolor white -border 2 +append "$images/moving-sphere.png"
csv="$scratch/moving/sphere-stops-flythrough-shadow-map.csv"
echo "moving, temporal=off: $(rms "$csv" "filter=poisson poisson-rotation=ign temporal=off" 5 9 12 20)"
echo "moving, temporal=on:  $(rms "$csv" "filter=poisson poisson-rotation=ign temporal=on" 5 9 12 20)"


# 3. Confidence reprojection on a still view at 128 texels: frames 0, 7 and 47, the shadow's
# edge magnified 3 times.
$fly sphere-box --path "$still" --frames 48 --technique confidence-reprojection --param resolution=128 \
  --out "$scratch/confidence" > /dev/null
d="$scratch/confidence/sphere-box-flythrough-confidence-reprojection-frames"
for f in 0 7 47; do
  $convert "$(frame "$d" "confidence-reprojection_resolution=128" $f visibility)" -crop 100x40+95+85 +repage \
    -sample 300% "$scratch/confidence-$f.png"
done
$convert "$scratch/confidence-0.png" "$scratch/confidence-7.png" "$scratch/confidence-47.png" \
  -bordercolor white -border 2 +append "$images/confidence-sharpening.png"
echo "confidence: $(rms "$scratch/confidence/sphere-box-flythrough-confidence-reprojection.csv" resolution=128 0 7 47)"
