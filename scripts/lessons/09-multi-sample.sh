# Lesson 9: multi-sample soft shadows (Heckbert and Herf 1997), the average of N hard shadow
# maps from points on the area light, on sphere-box under a disk light of radius 1 m.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
size="--width 480 --height 300 --threads 2"
view="--eye -3,5,4.5 --target -0.3,0.3,-0.6 --light-radius 1"
# render_view NAME TECHNIQUE [ARGS]: render_shown on sphere-box from the lesson's view.
render_view() {
  name=$1 technique=$2
  shift 2
  render_shown "$name" assets/scenes/sphere-box.json "$technique" $view "$@"
}

# The stages at N = 16: the first point's shadow map, the per-pixel count of lit points.
rm -rf "$scratch/debug"
render_view samples-16 multi-sample --param samples=16 --debug-buffers "$scratch/debug"
cp "$scratch/debug/multi-sample-depth-sample0.png" "$images/depth-sample0.png"
cp "$scratch/debug/multi-sample-lit-count.png" "$images/lit-count-16.png"

# The level of detail: N = 1 (one hard shadow), 4, 64 and 256 points.
for n in 1 4 64 256; do
  render_view "samples-$n" multi-sample --param samples=$n
done
# The same 256 points with maps of 256 texels a side.
render_view samples-256-resolution-256 multi-sample --param samples=256 --param resolution=256

python3 - "$scratch" <<'PY'
import json, sys
print("| run | maps | RMS | mean abs | max | umbra over % | lit shadowed % |")
print("| --- | --- | --- | --- | --- | --- | --- |")
for name in ["samples-1", "samples-4", "samples-16", "samples-64", "samples-256", "samples-256-resolution-256"]:
    j = json.load(open(f"{sys.argv[1]}/{name}.json"))
    e = j["errors"]
    print(f"| {name} | {j['stats']['maps_count']:.0f} | {e['rms']:.4f} | {e['mean_abs']:.5f} | {e['max_abs']:.3f} "
          f"| {e['umbra_over_percent']:.3f} | {e['lit_shadowed_percent']:.3f} |")
PY
