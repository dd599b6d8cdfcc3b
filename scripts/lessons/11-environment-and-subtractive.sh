# Lesson 11: natural light, the glossy bunny under an environment map, lit by N lights sampled
# from the map: additive shadows against subtractive shadows (DeCoro and Rusinkiewicz 2008),
# assets/scenes/environment/bunny-interior.json at 480 x 300.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch. Every run is scored
# against the exact integral (reference-env, 2 x 1024 samples a pixel), which each run
# renders again: 3 to 4 minutes a run on 2 shared cores, 23 minutes for the lesson.
set -eu
. scripts/lessons/common.sh
scene=assets/scenes/environment/bunny-interior.json
size="--width 480 --height 300 --threads 2"

nice -n 10 "$app" render "$scene" --technique reference-env $size -o "$images/reference.png" \
  > "$scratch/reference.log"

# render_image NAME TECHNIQUE [ARGS]: the image, shown, and its figures against reference-env
# in $scratch/NAME.json (the error map, a classification at V = 0.5, means little for
# radiance and stays in $scratch).
render_image() {
  name=$1 technique=$2
  shift 2
  render "$name" "$scene" "$technique" "$@"
  show "$name"
}

# The stages at N = 40 lights and sampling detail 1/16: the lights on the map, C, S, S'.
rm -rf "$scratch/debug"
render_image subtractive-40-1-16 env-subtractive --param lights=40 --param sampling-detail=1/16 \
  --debug-buffers "$scratch/debug"
for buffer in lights C S S-resampled sh-irradiance; do keep "env-subtractive-$buffer" "$buffer"; done

# Illumination detail N, additive against subtractive; then the sampling detail.
for n in 10 40; do
  render_image "additive-$n" env-additive --param lights=$n
  render_image "subtractive-$n" env-subtractive --param lights=$n
done
render_image subtractive-40-1-256 env-subtractive --param lights=40 --param sampling-detail=1/256

python3 - "$scratch" <<'PY'
import json, sys
runs = ["additive-10", "subtractive-10", "additive-40", "subtractive-40", "subtractive-40-1-16",
        "subtractive-40-1-256"]
print("| run | RMS of Y | RMS, display | mean abs | shadow fragments | clamped pixels |")
print("| --- | --- | --- | --- | --- | --- |")
for name in runs:
    j = json.load(open(f"{sys.argv[1]}/{name}.json"))
    e, s = j["errors"], j["stats"]
    print(f"| {name} | {e['rms']:.4f} | {e['rms_display']:.4f} | {e['mean_abs']:.4f} "
          f"| {s.get('shadow_fragments', 0):.0f} | {s.get('clamped_pixels', 0):.0f} |")
noise = [line.split()[1] for line in open(f"{sys.argv[1]}/reference.log") if "halves_rms" in line]
print("reference-env's own noise, from its two halves: RMS", noise[0], "W/(m^2 sr),", noise[1], "% of the mean")
PY
