# Lesson 10: accurate soft shadows: the min/max depth hierarchy, contact-hardening shadows
# (chs), backprojection and soft shadow volumes, on sphere-box under a disk light of radius
# 1 m, and soft shadow volumes' known error on assets/scenes/soft/stacked-squares.json.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch. Needs rsvg-convert
# (librsvg) to turn backprojection's light plot into a PNG.
set -eu
. scripts/lessons/common.sh
size="--width 480 --height 300 --threads 2"
view="--eye -3,5,4.5 --target -0.3,0.3,-0.6 --light-radius 1"

rm -rf "$scratch/debug"
# 1. The min/max hierarchy, as PCSS builds and reads it (the same V with it on or off).
render pcss-hierarchy-off assets/scenes/sphere-box.json pcss $view --param min-max-hierarchy=off
render pcss-hierarchy-on assets/scenes/sphere-box.json pcss $view --param min-max-hierarchy=on --debug-buffers "$scratch/debug"
for level in 2 4; do
  keep "pcss-hierarchy-min-$level" "hierarchy-min-$level"
  keep "pcss-hierarchy-max-$level" "hierarchy-max-$level"
done
keep pcss-known-taps hierarchy-known-taps

# 2. chs: PCSS's search read on the hierarchy's levels.
render chs-filter-nodes-8 assets/scenes/sphere-box.json chs $view --debug-buffers "$scratch/debug"
keep chs-search-level chs-search-level
render chs-filter-nodes-2 assets/scenes/sphere-box.json chs $view --param filter-nodes=2

# 3. Backprojection: the light plot of one ground pixel in the sphere's penumbra.
render backprojection-samples-16 assets/scenes/sphere-box.json backprojection $view --param plot-x=166 --param plot-y=200 \
  --debug-buffers "$scratch/debug"
keep backprojection-level backprojection-level
keep backprojection-patches backprojection-patches
rsvg-convert -w 480 "$scratch/debug/backprojection-light.svg" > "$images/backprojection-light.png"
render backprojection-samples-4 assets/scenes/sphere-box.json backprojection $view --param light-samples=4
render backprojection-samples-8 assets/scenes/sphere-box.json backprojection $view --param light-samples=8

# 4. Soft shadow volumes: the centre's stencil count, the wedges, the summed coverage.
render ssv assets/scenes/sphere-box.json soft-shadow-volumes $view --debug-buffers "$scratch/debug"
for buffer in stencil wedges correction; do keep "soft-shadow-volumes-$buffer" "ssv-$buffer"; done
# Its known error: two squares that overlap as the light sees them are counted twice.
render ssv-stacked-count assets/scenes/soft/stacked-squares.json soft-shadow-volumes --param hard-shadow=count
render ssv-stacked-binary assets/scenes/soft/stacked-squares.json soft-shadow-volumes --param hard-shadow=binary
nice -n 10 "$app" render assets/scenes/soft/stacked-squares.json --technique reference-soft $size \
  -o "$images/stacked-reference.png" > "$scratch/stacked-reference.log"
for run in pcss-hierarchy-on chs-filter-nodes-8 chs-filter-nodes-2 backprojection-samples-4 \
  backprojection-samples-8 backprojection-samples-16 ssv ssv-stacked-count ssv-stacked-binary; do
  show "$run" "$run-error"
done

python3 - "$scratch" <<'PY'
import json, sys
runs = ["pcss-hierarchy-off", "pcss-hierarchy-on", "chs-filter-nodes-8", "chs-filter-nodes-2",
        "backprojection-samples-4", "backprojection-samples-8", "backprojection-samples-16", "ssv",
        "ssv-stacked-count", "ssv-stacked-binary"]
print("| run | RMS | max | umbra lit % | umbra over % | lit shadowed % |")
print("| --- | --- | --- | --- | --- | --- |")
for name in runs:
    e = json.load(open(f"{sys.argv[1]}/{name}.json"))["errors"]
    print(f"| {name} | {e['rms']:.4f} | {e['max_abs']:.3f} | {e['umbra_lit_percent']:.3f} "
          f"| {e['umbra_over_percent']:.3f} | {e['lit_shadowed_percent']:.3f} |")
stats = json.load(open(f"{sys.argv[1]}/pcss-hierarchy-on.json"))["stats"]
print("pcss, hierarchy on:", ", ".join(f"{k} {v:.1f}" for k, v in stats.items() if k.startswith("hierarchy_")
                                        and k.endswith("_percent")))
stats = json.load(open(f"{sys.argv[1]}/ssv.json"))["stats"]
print("soft-shadow-volumes:", ", ".join(f"{k} {stats[k]:.0f}" for k in
      ["silhouette_edges", "wedges_count", "wedge_inside_fragments", "stencil_side_fragments"]))
PY
