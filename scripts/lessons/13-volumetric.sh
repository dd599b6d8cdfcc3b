# Lesson 13: volumetric shadows, casters that let some light through: the coloured shadow map,
# opacity shadow maps, deep shadow maps and adaptive volumetric shadow maps, on
# assets/scenes/volumetric/stacked-sheets.json (twelve sheets passing 70% each), and the coloured map
# on assets/scenes/volumetric/tinted-glass.json.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch. Needs rsvg-convert
# (librsvg) to turn the transmittance curve plots into PNGs.
set -eu
. scripts/lessons/common.sh
size="--width 480 --height 300 --threads 2"
sheets=assets/scenes/volumetric/stacked-sheets.json

# curve TECHNIQUE SHOWN_NAME: the plot of the busiest texel's curve, exact against kept.
curve() {
  plot=$(ls "$scratch/debug/$1"-curve-*.svg | head -n 1)
  rsvg-convert -w 480 -b white "$plot" > "$images/$2.png"
}

rm -rf "$scratch/debug"
nice -n 10 "$app" render "$sheets" --technique reference $size -o "$images/sheets-reference.png" \
  > "$scratch/sheets-reference.log"
render sheets-shadow-map "$sheets" shadow-map

# The stages, each technique's buffers on the sheets at its defaults.
render sheets-deep "$sheets" deep-shadow-maps --debug-buffers "$scratch/debug"
keep deep-shadow-maps-events-per-texel events-per-texel
keep deep-shadow-maps-vertices-per-texel deep-vertices-per-texel
curve deep-shadow-maps deep-curve
render sheets-coloured "$sheets" coloured-shadow-map --debug-buffers "$scratch/debug"
render sheets-opacity-16 "$sheets" opacity-shadow-maps --debug-buffers "$scratch/debug"
keep opacity-shadow-maps-slice-4 opacity-slice-4
keep opacity-shadow-maps-slice-12 opacity-slice-12
curve opacity-shadow-maps opacity-curve-16
render sheets-avsm-8 "$sheets" adaptive-volumetric-shadow-maps --debug-buffers "$scratch/debug"
keep adaptive-volumetric-shadow-maps-nodes-per-texel avsm-nodes-per-texel
curve adaptive-volumetric-shadow-maps avsm-curve-8

# The parameters that move each one's error: slices, nodes.
rm -rf "$scratch/debug"
render sheets-opacity-4 "$sheets" opacity-shadow-maps --param slices=4 --debug-buffers "$scratch/debug"
curve opacity-shadow-maps opacity-curve-4
render sheets-opacity-64 "$sheets" opacity-shadow-maps --param slices=64
rm -rf "$scratch/debug"
render sheets-avsm-2 "$sheets" adaptive-volumetric-shadow-maps --param nodes=2 --debug-buffers "$scratch/debug"
curve adaptive-volumetric-shadow-maps avsm-curve-2
render sheets-avsm-16 "$sheets" adaptive-volumetric-shadow-maps --param nodes=16

# Colour: the coloured shadow map on the tinted panes, its colour map, and the reference.
rm -rf "$scratch/debug"
render glass-coloured assets/scenes/volumetric/tinted-glass.json coloured-shadow-map --debug-buffers "$scratch/debug"
keep coloured-shadow-map-colour glass-colour-map
nice -n 10 "$app" render assets/scenes/volumetric/tinted-glass.json --technique reference $size \
  -o "$images/glass-reference.png" > "$scratch/glass-reference.log"
show sheets-shadow-map sheets-coloured sheets-opacity-4 sheets-opacity-64 sheets-deep sheets-avsm-2 \
  glass-coloured glass-coloured-error

python3 - "$scratch" <<'PY'
import json, sys
runs = ["sheets-shadow-map", "sheets-coloured", "sheets-opacity-4", "sheets-opacity-16", "sheets-opacity-64",
        "sheets-deep", "sheets-avsm-2", "sheets-avsm-8", "sheets-avsm-16", "glass-coloured"]
print("| run | RMS | mean abs | max | bytes per texel |")
print("| --- | --- | --- | --- | --- |")
for name in runs:
    j = json.load(open(f"{sys.argv[1]}/{name}.json"))
    e, stats = j["errors"], j["stats"]
    per_texel = f"{stats['storage_per_texel_bytes']:.1f}" if "storage_per_texel_bytes" in stats else ""
    print(f"| {name} | {e['rms']:.4f} | {e['mean_abs']:.4f} | {e['max_abs']:.3f} | {per_texel} |")
PY
