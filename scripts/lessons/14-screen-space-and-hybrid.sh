# Lesson 14: screen-space contact shadows on assets/scenes/hard/box-contact.json (at its own 640 x 400)
# and the izb-pcss hybrid on assets/scenes/soft/branch-over-crate.json (480 x 300).
# Run by scripts/lessons.sh, which sets $app, $images and $scratch. Needs rsvg-convert
# (librsvg) to turn the march plot into a PNG.
set -eu
. scripts/lessons/common.sh
size="--threads 2"   # each scene at its own size
box=assets/scenes/hard/box-contact.json
branch=assets/scenes/soft/branch-over-crate.json

rm -rf "$scratch/debug"
# 1. Contact shadows: the map alone, then the map and the march at three lengths, and the
# march alone. The plotted pixel lies in the map's strip of light at the box's foot.
nice -n 10 "$app" render "$box" --technique reference --threads 2 -o "$images/box-reference.png" \
  > "$scratch/box-reference.log"
render box-shadow-map "$box" shadow-map
render box-contact-0.25 "$box" contact-shadows --param plot-x=330 --param plot-y=290 --debug-buffers "$scratch/debug"
keep contact-shadows-march-mask march-mask
keep contact-shadows-march-path march-path
rsvg-convert -w 640 -b white "$scratch/debug/contact-shadows-march.svg" > "$images/march-plot.png"
render box-contact-0.05 "$box" contact-shadows --param march-length=0.05
render box-contact-1 "$box" contact-shadows --param march-length=1
render box-march-alone "$box" contact-shadows --param shadow-map=off

# 2. The hybrid: PCSS and the irregular z-buffer alone, then blended at two pairs of distances.
branch_size="--width 480 --height 300"
nice -n 10 "$app" render "$branch" --technique reference-soft --threads 2 $branch_size -o "$images/branch-reference.png" \
  > "$scratch/branch-reference.log"
render branch-pcss "$branch" pcss $branch_size
render branch-izb "$branch" izb $branch_size --reference reference-soft
render branch-hybrid "$branch" izb-pcss $branch_size --debug-buffers "$scratch/debug"
for buffer in blend-weight izb pcss blocker-distance; do keep "izb-pcss-$buffer" "hybrid-$buffer"; done
render branch-hybrid-wide "$branch" izb-pcss $branch_size --param hard-below=0.5 --param soft-above=1.5
show box-shadow-map-error box-contact-0.05-error box-contact-0.25-error box-contact-1-error \
  box-march-alone-error branch-pcss-error branch-izb-error branch-hybrid branch-hybrid-error \
  branch-hybrid-wide-error

python3 - "$scratch" <<'PY'
import json, sys
def load(name):
    return json.load(open(f"{sys.argv[1]}/{name}.json"))
print("box-contact, against reference:")
print("| run | misclassified % | false shadow % | false light % | RMS | restored pixels |")
print("| --- | --- | --- | --- | --- | --- |")
for name in ["box-shadow-map", "box-contact-0.05", "box-contact-0.25", "box-contact-1", "box-march-alone"]:
    j = load(name)
    e, restored = j["errors"], j["stats"].get("restored_pixels", "")
    restored = f"{restored:.0f}" if restored != "" else ""
    print(f"| {name} | {e['misclassified_percent']:.3f} | {e['false_shadow_percent']:.3f} "
          f"| {e['false_light_percent']:.3f} | {e['rms']:.4f} | {restored} |")
print("branch-over-crate, against reference-soft:")
print("| run | RMS | max | umbra lit % | umbra over % | lit shadowed % | hard / blended / soft pixels |")
print("| --- | --- | --- | --- | --- | --- | --- |")
for name in ["branch-pcss", "branch-izb", "branch-hybrid", "branch-hybrid-wide"]:
    j = load(name)
    e, s = j["errors"], j["stats"]
    split = ""
    if "hard_pixels" in s:
        split = " / ".join(f"{s[k]:.0f}" for k in ["hard_pixels", "blended_pixels", "soft_pixels"])
    print(f"| {name} | {e['rms']:.4f} | {e['max_abs']:.3f} | {e['umbra_lit_percent']:.3f} "
          f"| {e['umbra_over_percent']:.3f} | {e['lit_shadowed_percent']:.3f} | {split} |")
PY
