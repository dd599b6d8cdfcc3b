# Lesson 8: multi-layered shadow fins (Cai et al. 2006) and their baselines, smoothies and
# penumbra maps, on sphere-box under a disk light of radius 1 m, seen from the shadow's side.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
size="--width 480 --height 300 --threads 2"
view="--eye -3,5,4.5 --target -0.3,0.3,-0.6 --light-radius 1"

# The stages of `fins`, as buffers: the light's maps of the layer that holds the sphere and
# the box, and the camera's illuminance buffer.
rm -rf "$scratch/debug"
render_shown fins assets/scenes/sphere-box.json fins $view --debug-buffers "$scratch/debug"
layer=$(ls "$scratch/debug" | sed -n 's/^fins-layer-\([0-9]*\)-shadow-map\.png$/\1/p' | head -n 1)
for buffer in shadow-map outer-weight inner-weight outer-depth illuminance; do
  cp "$scratch/debug/fins-layer-$layer-$buffer.png" "$images/fins-occluder-layer-$buffer.png"
done
cp "$scratch/debug/fins-fin-coverage.png" "$images/fins-fin-coverage.png"
cp "$scratch/debug/fins-layers.png" "$images/fins-layers.png"
echo "the occluders' layer: $layer of $(ls "$scratch/debug" | grep -c 'shadow-map\.png$') drawn"

# The baselines: outer fins only.
render_shown penumbra-maps assets/scenes/sphere-box.json penumbra-maps $view
render_shown smoothies-0.06 assets/scenes/sphere-box.json smoothies $view --param size=0.06
render_shown smoothies-0.2 assets/scenes/sphere-box.json smoothies $view --param size=0.2

# Figure 7 of the paper: one layer against sixteen on the torus over the green plane.
render_shown torus-layers-1 assets/scenes/soft/torus-over-plane.json fins --param layers=1
render_shown torus-layers-16 assets/scenes/soft/torus-over-plane.json fins --param layers=16

python3 - "$scratch" <<'PY'
import json, sys
print("| run | RMS | max | umbra over % | umbra lit % |")
print("| --- | --- | --- | --- | --- |")
for name in ["fins", "penumbra-maps", "smoothies-0.06", "smoothies-0.2", "torus-layers-1", "torus-layers-16"]:
    e = json.load(open(f"{sys.argv[1]}/{name}.json"))["errors"]
    print(f"| {name} | {e['rms']:.4f} | {e['max_abs']:.3f} "
          f"| {e['umbra_over_percent']:.3f} | {e['umbra_lit_percent']:.3f} |")
PY
