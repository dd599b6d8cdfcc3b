# Lesson 12: differential rendering, a synthetic bunny's shadows composited into a photograph of
# a room (Gibson et al. 2003) with `shadowlab composite`, at 480 x 300: frame 5 of the room's
# path at 1, 10 and all shadow passes, and the bunny on the floor (room-lift, frame 0) with the
# paper's source set (70% of the radiant power) and with every radiant patch a source.
# Run by scripts/lessons.sh, which sets $app, $images and $scratch. Needs rsvg-convert
# (librsvg) to turn the plan of the shafts into a PNG.
set -eu
size="--width 480 --height 300 --threads 2"

# composite NAME CASE [ARGS]: runs the case into $scratch/NAME (images, composite.json).
composite() {
  name=$1 case=$2
  shift 2
  nice -n 10 "$app" composite "$case" $size "$@" --out "$scratch/$name" > "$scratch/$name.log"
}
# keep RUN FILE SHOWN_NAME: copies one of a run's PNGs into the lesson's images.
keep() { cp "$scratch/$1/$2.png" "$images/$3.png"; }

rm -rf "$scratch/room" "$scratch/lift" "$scratch/lift-share-1"
composite room room --frames 5 --passes 1,10,0 --masks
keep room background photograph
for n in 1 10 all; do
  keep room "composite-f5-n$n" "composite-n$n"
  keep room "error-f5-n$n" "error-n$n"
done
keep room reference-f5 reference
keep room listed-f5-n10 listed-n10
keep room shadowing-f5-n10 shadowing-n10
for c in 0 1; do keep room "mask-f5-n10-c$c" "mask-n10-c$c"; done
keep room mask-f5-n1-c0 mask-n1-c0
rsvg-convert -w 480 -b white "$scratch/room/plan-f5-n10.svg" > "$images/plan-n10.png"

# The contact: the bunny on the floor, the brightest patches to 70% of the power as sources,
# then every radiant patch.
composite lift room-lift --frames 0 --passes 0
composite lift-share-1 room-lift --frames 0 --passes 0 --source-share 1
keep lift composite-f0-nall lift-composite
keep lift-share-1 composite-f0-nall lift-composite-share-1
keep lift reference-f0 lift-reference

python3 - "$scratch" <<'PY'
import json, sys
print("| run | frame | n | clusters | RMS | on the object | elsewhere | photograph as it is | deepest shadow "
      "| reference's deepest |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for run in ["room", "lift", "lift-share-1"]:
    j = json.load(open(f"{sys.argv[1]}/{run}/composite.json"))
    for f in j["frames"]:
        for p in f["passes"]:
            n = p["passes"] if p["passes"] else "all"
            print(f"| {run} | {f['frame']} | {n} | {p['stats']['clusters_count']:.0f} | {p['rms_radiance']:.5f} "
                  f"| {p['rms_object_radiance']:.5f} | {p['rms_receivers_radiance']:.5f} "
                  f"| {f['rms_background_radiance']:.5f} | {p['deepest_shadow_ratio']:.3f} "
                  f"| {f['reference_deepest_shadow_ratio']:.3f} |")
    pre = j["preprocess"]
    print(f"{run}: {pre['source_patches_count']:.0f} sources, {pre['receiver_patches_count']:.0f} receiver patches, "
          f"{pre['shaft_leaves_count']:.0f} shaft leaves")
PY
