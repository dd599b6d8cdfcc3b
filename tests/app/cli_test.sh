#!/usr/bin/env bash
# End-to-end tests of the shadowlab command line (app/main.cpp, app/commands/): every
# command's help, one-line errors for bad input, output files written whole or not at all,
# and the progress line on stderr only.
# Usage: cli_test.sh PATH/TO/shadowlab SCRATCH_DIR
set -u
source "$(dirname "${BASH_SOURCE[0]}")/one_line_error.sh"

bin=${1:?usage: cli_test.sh SHADOWLAB SCRATCH_DIR}
scratch=${2:?usage: cli_test.sh SHADOWLAB SCRATCH_DIR}
rm -rf "$scratch"
mkdir -p "$scratch"
out=$scratch/stdout.txt
err=$scratch/stderr.txt
passed=0
failed=0

pass() { passed=$((passed + 1)); }
fail() {
    failed=$((failed + 1))
    echo "FAIL: $*"
}

# Runs shadowlab with the arguments, output into $out and $err; sets $rc.
run() {
    "$bin" "$@" >"$out" 2>"$err"
    rc=$?
}

# expect_usage ARGS...: exits 0 and prints a usage text.
expect_usage() {
    run "$@"
    if [ "$rc" -ne 0 ]; then
        fail "'shadowlab $*' exited $rc, expected 0 (stderr: $(head -c 300 "$err"))"
    elif ! grep -q "Usage:" "$out"; then
        fail "'shadowlab $*' printed no 'Usage:' on stdout"
    else
        pass
    fi
}

# expect_error WHAT ARGS...: exits non-zero with exactly one stderr line "shadowlab: error: ...".
expect_error() {
    local what=$1
    shift
    run "$@"
    local problem
    problem=$(one_line_error_problem "$rc" "$err")
    if [ -n "$problem" ]; then
        fail "$what: 'shadowlab $*' $problem; stderr:"
        sed 's/^/    /' "$err"
    else
        pass
    fi
}

# expect_no_file PATH: neither PATH nor a hidden temporary beside it (.sl-XXXXXXXX, write_file.h).
expect_no_file() {
    local path=$1 leftovers
    leftovers=$(find "$(dirname "$path")" -maxdepth 1 -name '.sl-*' | wc -l)
    if [ -e "$path" ]; then
        fail "$path exists after a failing command"
    elif [ "$leftovers" -ne 0 ]; then
        fail "$leftovers temporary file(s) of $path left behind"
    else
        pass
    fi
}

# expect_png PATH: the file starts with the 8-byte PNG signature 89 50 4E 47 0D 0A 1A 0A.
expect_png() {
    local signature
    signature=$(head -c 8 "$1" 2>/dev/null | od -An -tx1 | tr -d ' \n')
    if [ "$signature" = "89504e470d0a1a0a" ]; then
        pass
    else
        fail "$1 is not a PNG (first bytes: '$signature')"
    fi
}

# ---- Help ---------------------------------------------------------------------------------
expect_usage --help
for command in render sweep merge-sweep report compare bench scaling flythrough export-obj techniques environment \
               composite; do
    expect_usage "$command" --help
done
run techniques
if [ "$rc" -eq 0 ] && grep -q "^shadow-volume " "$out" && grep -q "resolution=" "$out"; then
    pass
else
    fail "'shadowlab techniques' exited $rc or did not list shadow-volume and its parameters"
fi

# ---- One-line errors ----------------------------------------------------------------------
tiny=(--width 64 --height 40)
# Every floating-point option of every command, as its help lists it (type FLOAT), refuses
# NaN and infinities by name before any work; each command gets what it requires besides.
declare -A required=([render]="sphere-box" [sweep]="sphere-box --technique none" [flythrough]="sphere-box --technique none"
                     [scaling]="sphere-box bunny --technique none" [composite]="room"
                     [environment]="$(dirname "${BASH_SOURCE[0]}")/../../assets/environments/pmndrs_sky.hdr")
float_options=0
for command in render sweep merge-sweep report compare bench scaling flythrough export-obj techniques environment \
               composite; do
    for option in $("$bin" "$command" --help | grep -oE '^ +--[a-z-]+ (\[?FLOAT|FLOAT)' | grep -oE -- '--[a-z-]+'); do
        float_options=$((float_options + 1))
        for value in nan inf -inf; do
            # shellcheck disable=SC2086 # the required arguments are a word list
            expect_error "$command $option $value" "$command" ${required[$command]:-} "$option" "$value"
            # An option with a range may refuse an infinity by its range first; NaN passes any range.
            refusal="must be a finite number"
            [ "$value" = nan ] || refusal+="|not in range"
            grep -qE "$refusal" "$err" ||
                fail "$command $option $value: not refused as not finite: $(head -c 300 "$err")"
        done
    done
done
# render's three, sweep's light radius, flythrough's tolerance, environment's five, composite's
# two: twelve today, so a help format the pattern misses fails here.
[ "$float_options" -ge 12 ] && pass || fail "only $float_options floating-point options found in the commands' help"
printf '{"name": "broken", "camera": {"eye": [0, 1, 5],\n' >"$scratch/broken.json"
expect_error "no command"
expect_error "unknown command" frobnicate
if grep -q "unknown command 'frobnicate' (known: render, " "$err"; then pass; else fail "the unknown command is not named: $(cat "$err")"; fi
expect_error "unknown scene" render no-such-scene "${tiny[@]}" -o "$scratch/x.png"
expect_error "unknown technique" render sphere-box --technique no-such-technique "${tiny[@]}" -o "$scratch/x.png"
expect_error "bad --param value" render sphere-box --technique shadow-map --param resolution=abc "${tiny[@]}" -o "$scratch/x.png"
expect_error "unknown --param name" render sphere-box --technique shadow-map --param no-such=1 "${tiny[@]}" -o "$scratch/x.png"
expect_error "--caster-lod out of range" render sphere-box --technique shadow-map --caster-lod 0 "${tiny[@]}" -o "$scratch/x.png"
expect_error "--frames out of range" render sphere-box --technique shadow-map --frames 0 "${tiny[@]}" -o "$scratch/x.png"
# An empty or malformed level of detail is an error, not the option left out.
expect_error "empty --caster-lod" render sphere-box --technique shadow-map --caster-lod '' "${tiny[@]}" -o "$scratch/x.png"
expect_no_file "$scratch/x.png"
expect_error "empty --caster-lod list" sweep sphere-box --technique shadow-map --caster-lod '' "${tiny[@]}" --runs 1 --warmup 0 --out "$scratch/lod"
expect_error "malformed --caster-lod list" sweep sphere-box --technique shadow-map --caster-lod '0.5,,0.25' "${tiny[@]}" --runs 1 --warmup 0 --out "$scratch/lod"
if grep -q "caster-lod" "$err"; then pass; else fail "the caster LOD's error does not name it: $(cat "$err")"; fi
expect_error "--caster-lod of a reference" render sphere-box --technique reference --caster-lod 0.5 "${tiny[@]}" -o "$scratch/x.png"
expect_error "--caster-lod given twice in a sweep" sweep sphere-box --technique shadow-map --caster-lod 1,0.5 \
    --param caster-lod=0.25 --out "$scratch/sw"
expect_error "malformed scene JSON" render "$scratch/broken.json" "${tiny[@]}" -o "$scratch/x.png"
expect_error "bad --simd" render sphere-box --simd bogus "${tiny[@]}" -o "$scratch/x.png"
expect_error "render without output" render sphere-box "${tiny[@]}"
expect_error "render without scene" render -o "$scratch/x.png"
expect_error "bad --width" render sphere-box --width 0 -o "$scratch/x.png"
expect_error "LiSPSM without a sun" render sphere-box --technique shadow-map --param warp=lispsm "${tiny[@]}" -o "$scratch/x.png"
# csm cascades a sun only; sphere-box's disk gets shadow-map's frame (docs/shadow-maps.md).
run render sphere-box --technique csm "${tiny[@]}" -o "$scratch/csm.png"
csm_rc=$rc
run render sphere-box --technique shadow-map "${tiny[@]}" -o "$scratch/map.png"
if [ "$csm_rc" -eq 0 ] && [ "$rc" -eq 0 ] && cmp -s "$scratch/csm.png" "$scratch/map.png"; then pass
else fail "csm under sphere-box's disk light is not shadow-map's image (rc $csm_rc, $rc)"; fi
expect_error "--light-pos of a sun" render "$(dirname "${BASH_SOURCE[0]}")/../../assets/scenes/hard/sun.json" --light-pos 1,2,3 "${tiny[@]}" -o "$scratch/x.png"
expect_error "--light-pos beyond the world's bound (Embree aborted)" render sphere-box --technique reference --light-pos 1.9e18,5,0 "${tiny[@]}" -o "$scratch/x.png"
expect_error "--eye beyond the world's bound" render sphere-box --eye 0,2e6,0 "${tiny[@]}" -o "$scratch/x.png"
# A glTF file is a scene (docs/scene-format.md, "glTF files"), overrides and all; a broken one is one line.
gltf=$(dirname "${BASH_SOURCE[0]}")/../fuzz/corpus/gltf_file
run render "$gltf/lit_mask.glb" --technique shadow-map --eye 0.3,0.5,3 --target 0,0.5,0 "${tiny[@]}" -o "$scratch/gltf.png"
expect_png "$scratch/gltf.png"
head -c 40 "$gltf/lit_mask.glb" > "$scratch/short.glb"
expect_error "a .glb whose chunk lengths lie" render "$scratch/short.glb" "${tiny[@]}" -o "$scratch/x.png"
# Many lights (docs/many-lights.md): --light N past the scene's lights is named; --light 0 of
# a one-light scene writes the same bytes; a three-light frame writes V per light.
three=$(dirname "${BASH_SOURCE[0]}")/../../assets/scenes/many-lights/three-lights.json
expect_error "--light past the lights" render "$three" --light 3 "${tiny[@]}" -o "$scratch/x.png"
grep -q -- "--light 3: the scene has 3 lights (indices 0..2)" "$err" || fail "--light 3's error does not name the lights: $(cat "$err")"
expect_error "--light of a one-light scene" sweep sphere-box --technique none --light 1 --out "$scratch/sw"
expect_error "flythrough of three lights" flythrough "$three" --technique shadow-map --out "$scratch/fly"
run render sphere-box --technique shadow-map "${tiny[@]}" -o "$scratch/one.png" --aov "$scratch/one.exr"
run render sphere-box --technique shadow-map --light 0 "${tiny[@]}" -o "$scratch/zero.png" --aov "$scratch/zero.exr"
if [ "$rc" -eq 0 ] && cmp -s "$scratch/one.exr" "$scratch/zero.exr" && cmp -s "$scratch/one.png" "$scratch/zero.png"; then pass
else fail "--light 0 of a one-light scene changed its files (rc $rc)"; fi
run render "$three" --technique shadow-map "${tiny[@]}" --aov "$scratch/three.exr" --error-map "$scratch/three-err.png"
if [ "$rc" -eq 0 ] && grep -q "light2_technique_ms" "$out" && grep -q "^light 2: rms" "$out"; then pass
else fail "a three-light render printed no per-light time or figures (rc $rc): $(head -c 300 "$out")"; fi
run compare "$scratch/three.exr" "$scratch/three.exr" --channel light2.V
if [ "$rc" -eq 0 ]; then pass; else fail "the three-light EXR has no light2.V: $(cat "$err")"; fi
# Both EXRs have R, G, B: compare prints FLIP of the shaded images too, 0 for a file against itself.
if grep -Eq "^  FLIP mean +0$" "$out"; then pass
else fail "compare of an EXR against itself printed no FLIP mean of 0: $(cat "$out")"; fi
# Its sweep: each light's figures in the JSON are render --json's, for the same technique
# and settings (a coarse map, which errs); the CSV has each light's columns.
run render "$three" --technique shadow-map --param resolution=64 "${tiny[@]}" --error-map "$scratch/three64.png" \
    --json "$scratch/three64.json"
[ "$rc" -eq 0 ] || fail "render --json of three lights exited $rc: $(cat "$err")"
run sweep "$three" --technique shadow-map --param resolution=64 "${tiny[@]}" --threads 1 --runs 1 --warmup 0 \
    --out "$scratch/three-sweep"
[ "$rc" -eq 0 ] || fail "sweep of three lights exited $rc: $(cat "$err")"
if python3 - "$scratch/three64.json" "$scratch/three-sweep/three-lights-shadow-map.json" <<'PY'
import json, sys
render, sweep = (json.load(open(f)) for f in sys.argv[1:])
row = sweep["rows"][0]
lights = [light["errors"] for light in render["lights"]]
assert len(lights) == 3 and [light["errors"] for light in row["lights"]] == lights, "the lights' figures differ"
assert row["errors"] == render["errors"], "the overall figures differ"
assert row["errors"]["misclassified"] == sum(l["misclassified"] for l in lights) > 0, "no sum, or no error to compare"
PY
then pass; else fail "the sweep's per-light figures are not render's"; fi
if head -1 "$scratch/three-sweep/three-lights-shadow-map.csv" | grep -q ",reference,flip_mean,light0_misclassified_percent,light0_rms,"; then pass
else fail "the three-light sweep's CSV has no per-light columns: $(head -c 400 "$scratch/three-sweep/three-lights-shadow-map.csv")"; fi
expect_error "compare of missing files" compare "$scratch/none1.exr" "$scratch/none2.exr"
maps=$(dirname "${BASH_SOURCE[0]}")/../../assets/environments
expect_error "environment of a missing map" environment "$scratch/none.hdr"
expect_error "environment with no lights" environment "$maps/pmndrs_sky.hdr" --lights 0 --out "$scratch/env"
expect_error "environment with a bad SH window" environment "$maps/pmndrs_sky.hdr" --sh-window 1 --out "$scratch/env"
expect_error "environment with a lobe too sharp for the map" environment "$maps/pmndrs_sky.hdr" --phong 8 --phong 5000 --out "$scratch/env"
printf 'P6 2 1 255\n......' >"$scratch/ldr.hdr"
expect_error "environment of an 8-bit image" environment "$scratch/ldr.hdr" --out "$scratch/env"
if grep -q "neither OpenEXR nor Radiance HDR" "$err"; then pass; else fail "the 8-bit map's error does not say why: $(cat "$err")"; fi
run environment "$maps/pmndrs_sky.hdr" --lights 8 --rotation 30 --phong 8 --ggx 0.5 --out "$scratch/env"
if [ "$rc" -eq 0 ] && grep -q "8 median-cut and structured lights" "$out"; then pass; else fail "environment exited $rc: $(cat "$err")"; fi
for image in environment sh-radiance sh-irradiance lights structured-lights prefiltered-phong-8 prefiltered-ggx-0.5 split-sum; do expect_png "$scratch/env/$image.png"; done
expect_error "flythrough of a scene without a path" flythrough "$maps/../scenes/hard/spot.json" --technique shadow-map \
    --out "$scratch/fly"
if grep -q 'has no "flythrough" path' "$err"; then pass; else fail "the missing path is not named: $(cat "$err")"; fi
printf 'time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n1,0,4,9,0,0,0\n0,0,4,8,0,0,0\n' >"$scratch/back.csv"
expect_error "flythrough of keyframes going back in time" flythrough sphere-box --path "$scratch/back.csv" \
    --technique shadow-map --out "$scratch/fly"
if grep -q "back.csv: line 3: times must increase" "$err"; then pass; else fail "the bad keyframe is unnamed: $(cat "$err")"; fi
expect_error "flythrough of a radiance technique" flythrough sphere-box --technique env-additive --out "$scratch/fly"
run flythrough sphere-box --technique shadow-map --frames 3 --runs 1 --warmup 0 "${tiny[@]}" --out "$scratch/fly"
if [ "$rc" -eq 0 ] && [ "$(wc -l <"$scratch/fly/sphere-box-flythrough-shadow-map.csv")" -eq 4 ] &&
   grep -q "<polyline" "$scratch/fly/sphere-box-flythrough-shadow-map-time.svg" &&
   grep -q '"flicker": null' "$scratch/fly/sphere-box-flythrough-shadow-map.json"; then
    pass
else
    fail "flythrough exited $rc or wrote no table, plot or JSON: $(cat "$err")"
fi
expect_error "composite of an unknown case" composite no-such-room --width 32 --height 20 --out "$scratch/comp"
expect_error "composite of a frame past the path" composite room --frames 99 --width 32 --height 20 --out "$scratch/comp"
expect_error "composite with negative passes" composite room --passes -1 --width 32 --height 20 --out "$scratch/comp"
run composite room-lift --width 48 --height 30 --frames 0,3 --passes 2,0 --ldr-error --out "$scratch/comp"
if [ "$rc" -eq 0 ] && grep -q '"rms_radiance"' "$scratch/comp/composite.json" && grep -q "frame 3, n = all" "$out"; then
    pass
else
    fail "composite exited $rc or wrote no figures: $(cat "$err")"
fi
for image in background reference-f3 composite-f3-n2 composite-f3-nall listed-f3-n2 shadowing-f3-nall error-f0-n2; do expect_png "$scratch/comp/$image.png"; done
for plot in time-rms shadow-depth ldr-error; do
    if grep -q "<polyline" "$scratch/comp/$plot.svg"; then pass; else fail "$plot.svg has no series"; fi
done
if grep -q "leaf shafts touched" "$scratch/comp/plan-f3-n2.svg" && grep -q "<line" "$scratch/comp/plan-f3-n2.svg"; then
    pass
else
    fail "plan-f3-n2.svg shows no shaft"
fi

# ---- Whole or nothing -------------------------------------------------------------------
# Every failure above named -o x.png: none may have left it, or a temporary of it.
expect_no_file "$scratch/x.png"
# A later output that cannot be written fails the render before the PNG is written.
expect_error "--aov into a missing directory" render sphere-box "${tiny[@]}" -o "$scratch/x.png" --aov "$scratch/missing/x.exr"
expect_no_file "$scratch/x.png"
expect_error "--error-map into a missing directory" render sphere-box "${tiny[@]}" -o "$scratch/x.png" --error-map "$scratch/missing/e.png"
expect_no_file "$scratch/x.png"
expect_error "--json into a missing directory" render sphere-box "${tiny[@]}" -o "$scratch/x.png" --error-map "$scratch/e.png" \
    --json "$scratch/missing/e.json"
expect_no_file "$scratch/x.png"
expect_no_file "$scratch/e.png"

run render sphere-box --technique none "${tiny[@]}" -o "$scratch/ok.png" --aov "$scratch/ok.exr"
if [ "$rc" -eq 0 ]; then pass; else fail "tiny render exited $rc: $(cat "$err")"; fi
expect_png "$scratch/ok.png"
# compare too: its JSON cannot be written, so the heat map is not written either.
expect_error "compare --json into a missing directory" compare "$scratch/ok.exr" "$scratch/ok.exr" \
    --heatmap "$scratch/h.png" --json "$scratch/missing/h.json"
expect_no_file "$scratch/h.png"
# A legal name of 251 bytes: its temporary was longer than the 255 a folder holds.
long=$scratch/$(head -c 247 /dev/zero | tr '\0' a).png
run render sphere-box --technique none "${tiny[@]}" -o "$long"
if [ "$rc" -eq 0 ]; then pass; else fail "a 251-byte output name: exited $rc: $(cat "$err")"; fi
expect_png "$long"
rm -f "$long"
leftovers=$(find "$scratch" -maxdepth 1 -name '.sl-*' | wc -l)
if [ "$leftovers" -eq 0 ]; then pass; else fail "$leftovers temporary file(s) left in $scratch"; fi

# ---- Sharded sweeps -------------------------------------------------------------------------
# A sweep of 7 settings at 2 thread counts on a 96 x 60 view of the sun case, run whole and
# as 3 shards into one directory, then merged: the same CSV, JSON and SVG but for the times.
tools=$(dirname "${BASH_SOURCE[0]}")
sed 's/"width": 640, "height": 400/"width": 96, "height": 60/' "$tools/../../assets/scenes/hard/sun.json" >"$scratch/tiny-sun.json"
if grep -q '"width": 96, "height": 60' "$scratch/tiny-sun.json"; then pass; else fail "could not shrink sun.json's camera"; fi
grid=(sweep "$scratch/tiny-sun.json" --technique none,shadow-map --param resolution=64,256,1024
      --param slope-factor=0.5,1.5 --threads 1,2 --runs 1 --warmup 0)
stem=tiny-sun-none+shadow-map  # a scene without a name is named after its file
run "${grid[@]}" --out "$scratch/whole"
if [ "$rc" -eq 0 ]; then pass; else fail "the whole sweep exited $rc: $(cat "$err")"; fi
for i in 1 2 3; do
    run "${grid[@]}" --shard "$i/3" --out "$scratch/shards"
    if [ "$rc" -eq 0 ] && grep -q "^tiny-sun, shard $i/3$" "$out"; then pass; else fail "shard $i/3 exited $rc: $(cat "$err")"; fi
done
for i in 1 2 3; do
    for ext in csv json svg; do
        if [ -s "$scratch/shards/$stem-shard-$i-of-3.$ext" ]; then pass; else fail "shard $i/3 wrote no $stem-shard-$i-of-3.$ext"; fi
    done
done
run merge-sweep "$scratch/shards/$stem-shard-"{3,1,2}"-of-3.json" --out "$scratch/merged"
if [ "$rc" -eq 0 ] && grep -q "wrote $scratch/merged/$stem.svg" "$out"; then pass; else fail "merge-sweep exited $rc: $(cat "$err")"; fi
# The CSV and JSON with every measured time (median_ms, min_ms, stats *_ms) blanked, and the
# JSON with the times set alike (blank_times.py), merged again: its SVG is then laid out
# from the same numbers as the whole run's.
same_when_blanked() {   # same_when_blanked WHAT A B
    if cmp -s <(python3 "$tools/blank_times.py" "$2") <(python3 "$tools/blank_times.py" "$3"); then
        pass
    else
        fail "$1 differs from the whole run's with the times blanked: $(diff <(python3 "$tools/blank_times.py" "$2") \
            <(python3 "$tools/blank_times.py" "$3") | head -5)"
    fi
}
same_when_blanked "the merged CSV" "$scratch/whole/$stem.csv" "$scratch/merged/$stem.csv"
same_when_blanked "the merged JSON" "$scratch/whole/$stem.json" "$scratch/merged/$stem.json"
mkdir -p "$scratch/blanked"
python3 "$tools/blank_times.py" "$scratch/whole/$stem.json" >"$scratch/blanked/whole.json"
for i in 1 2 3; do python3 "$tools/blank_times.py" "$scratch/shards/$stem-shard-$i-of-3.json" >"$scratch/blanked/$i.json"; done
run merge-sweep "$scratch/blanked/whole.json" --out "$scratch/blanked/from-whole"
run merge-sweep "$scratch/blanked/"{1,2,3}.json --out "$scratch/blanked/from-shards"
for ext in csv json svg; do
    if cmp -s "$scratch/blanked/from-whole/$stem.$ext" "$scratch/blanked/from-shards/$stem.$ext"; then
        pass
    else
        fail "with the times set alike, the merged $ext differs from the whole run's"
    fi
done
# Shards that do not make up the sweep: each a one-line error, and nothing written. The
# other sweep's grid has 2048 for 1024.
run "${grid[@]/1024/2048}" --shard 2/3 --out "$scratch/other"
if [ "$rc" -eq 0 ]; then pass; else fail "the other sweep's shard exited $rc: $(cat "$err")"; fi
merge_error() {   # merge_error WHAT EXPECTED FILES...
    local what=$1 expected=$2
    shift 2
    expect_error "$what" merge-sweep "$@" --out "$scratch/refused"
    if grep -qF -- "$expected" "$err"; then pass; else fail "$what: the error lacks \"$expected\": $(cat "$err")"; fi
}
shard() { echo "$scratch/shards/$stem-shard-$1-of-3.json"; }
merge_error "a missing shard" "missing shard(s) 2/3 of the sweep of $(shard 1)" "$(shard 1)" "$(shard 3)"
merge_error "a duplicate shard" "shard 2/3 is given twice" "$(shard 1)" "$(shard 2)" "$(shard 2)" "$(shard 3)"
merge_error "a shard of another sweep" "not a shard of the same sweep as $(shard 1) (axes: " \
    "$(shard 1)" "$scratch/other/$stem-shard-2-of-3.json" "$(shard 3)"
merge_error "a missing file" "$scratch/none.json: cannot open" "$(shard 1)" "$scratch/none.json"
merge_error "a directory" "$scratch/shards: is a directory, not a file" "$scratch/shards"
head -c 200 "$(shard 2)" >"$scratch/cut.json"
merge_error "a file cut short" "$scratch/cut.json: invalid JSON: " "$scratch/cut.json"
merge_error "a scene file" "sun.json: not the JSON of a sweep: " "$scratch/tiny-sun.json"
if [ ! -e "$scratch/refused" ]; then pass; else fail "a refused merge-sweep created $scratch/refused"; fi
expect_error "--plot-y rms-display of techniques scored on V" "${grid[@]}" --plot-y rms-display --out "$scratch/bad-axis"
if grep -qF "rms-display: none is scored on V" "$err" && [ ! -e "$scratch/bad-axis" ]; then pass; else fail "rms-display: $(cat "$err")"; fi
for bad in 0/3 4/3 1/0 garbage; do
    expect_error "--shard $bad" "${grid[@]}" --shard "$bad" --out "$scratch/bad-shard"
    if grep -qF "expected I/N with 1 <= I <= N" "$err"; then pass; else fail "--shard $bad: $(cat "$err")"; fi
done
expect_error "more shards than settings" "${grid[@]}" --shard 8/8 --out "$scratch/bad-shard"
if grep -qF "the sweep has only 7 settings" "$err"; then pass; else fail "--shard 8/8: $(cat "$err")"; fi

# ---- Pictures and the report -----------------------------------------------------------------
# Two shards with --images, merged into another directory (the pictures' paths rebased onto
# it), and the report of the merged JSON: every setting's page with its pictures copied.
pictures=(sweep "$scratch/tiny-sun.json" --technique shadow-map --param resolution=64,256 --threads 1 --runs 1
          --warmup 0 --images --out "$scratch/pictures/shards")
for i in 1 2; do
    run "${pictures[@]}" --shard "$i/2"
    if [ "$rc" -eq 0 ]; then pass; else fail "sweep --images --shard $i/2 exited $rc: $(cat "$err")"; fi
done
run merge-sweep "$scratch/pictures/shards/"*.json --out "$scratch/pictures/merged"
if [ "$rc" -eq 0 ]; then pass; else fail "merge-sweep of shards with pictures exited $rc: $(cat "$err")"; fi
run report "$scratch/pictures/merged/tiny-sun-shadow-map.json" --out "$scratch/pictures/site"
if [ "$rc" -eq 0 ] && grep -q "wrote 4 pages: $scratch/pictures/site/index.html" "$out"; then
    pass
else
    fail "report of the merged sweep exited $rc: $(cat "$out" "$err")"
fi
for setting in 0 1; do
    page="$scratch/pictures/site/tiny-sun-shadow-map-setting-$setting.html"
    src=$(grep -o 'src="[^"]*setting-'"$setting"'-error-map.png"' "$page" | head -1 | sed 's/^src="//; s/"$//')
    if [ -n "$src" ] && [ -s "$scratch/pictures/site/$src" ]; then pass; else fail "setting $setting: no error map in the site"; fi
done

# ---- Whole or nothing, for every command that writes a folder ----------------------------------
# A folder in the way of one of a command's later files fails the command, which leaves
# nothing else in its --out folder (it stages every file and moves them in at the end,
# app/common/staged_outputs.h): environment, composite, flythrough, merge-sweep and report each left
# the files written before the one that failed.
blocked() {   # blocked WHAT NAME COMMAND...: NAME a folder in --out $scratch/blocked-WHAT
    local what=$1 name=$2
    shift 2
    local dir=$scratch/blocked-$what left
    rm -rf "$dir"
    mkdir -p "$dir/$name"
    expect_error "$what with a folder in the way of $name" "$@" --out "$dir"
    if grep -qF "a folder is in the way" "$err"; then pass; else fail "$what: the error does not say why: $(cat "$err")"; fi
    left=$(cd "$dir" && find . -mindepth 1 ! -path "./$name" | head -3)
    if [ -z "$left" ]; then pass; else fail "$what left files beside the folder in the way: $left"; fi
}
blocked environment sh-irradiance.png environment "$maps/pmndrs_sky.hdr" --lights 4
blocked composite background.png composite room --width 32 --height 20 --frames 0 --passes 2 --no-reference
blocked flythrough sphere-box-flythrough-shadow-map-error.svg flythrough sphere-box --technique shadow-map --frames 3 \
    --runs 1 --warmup 0 "${tiny[@]}"
blocked sweep "$stem-shard-1-of-3.svg" "${grid[@]}" --shard 1/3
blocked merge-sweep tiny-sun-shadow-map.svg merge-sweep "$scratch/pictures/shards/"*.json
blocked report index.html report "$scratch/pictures/merged/tiny-sun-shadow-map.json"
# A report into a folder holding another report's pages leaves none of them.
run report "$scratch/whole/$stem.json" --out "$scratch/pictures/site"
stale=$(find "$scratch/pictures/site" -name 'tiny-sun-shadow-map-*' | head -3)
if [ "$rc" -eq 0 ] && [ -z "$stale" ]; then pass; else fail "report exited $rc or left the last report's pages: $stale"; fi

# ---- Progress ------------------------------------------------------------------------------
# The soft reference at this size takes about 3 s on one thread, past the 2 s after which
# the progress line is drawn: on stderr, only if it is a terminal (not here) or --progress
# asks for it, and never on stdout or in the image.
slow=(render sphere-box --technique reference-soft --threads 1 --width 384 --height 240)
run "${slow[@]}" -o "$scratch/quiet.png"
if [ "$rc" -eq 0 ] && [ ! -s "$err" ]; then pass; else fail "without a terminal or --progress, rc $rc, stderr: $(head -c 300 "$err")"; fi
# Times differ from run to run: the "in N ms" line and the stage-time stats (NAME_ms).
mask_times() { sed -E 's/[0-9.]+ ms/N ms/; s/(_ms +)[0-9.e+-]+/\1N/' "$1"; }
mask_times "$out" >"$scratch/quiet.txt"
start_ns=$(date +%s%N)
run "${slow[@]}" -o "$scratch/progress.png" --progress
elapsed_ms=$((($(date +%s%N) - start_ns) / 1000000))
if [ "$rc" -eq 0 ]; then pass; else fail "render --progress exited $rc: $(head -c 300 "$err")"; fi
if mask_times "$out" | cmp -s - "$scratch/quiet.txt"; then pass; else fail "--progress changed stdout: $(cat "$out")"; fi
if cmp -s "$scratch/quiet.png" "$scratch/progress.png"; then pass; else fail "--progress changed the image"; fi
# Every redraw, split at '\r', is a progress line; the last is complete and ends the line.
if tr '\r' '\n' <"$err" | grep -v -e '^$' -e '^reference rays: row [0-9]*/240 ' -q; then
    fail "stderr holds more than progress lines: $(head -c 300 "$err" | tr '\r' '|')"
elif [ "$elapsed_ms" -lt 2500 ]; then
    echo "note: the slow render took only $elapsed_ms ms, too little to be sure of a progress line"
elif [ "$(tail -c 1 "$err" | od -An -c | tr -d ' ')" != '\n' ]; then
    fail "the progress line does not end with a newline: $(tail -c 200 "$err" | tr '\r' '|')"
elif ! tr '\r' '\n' <"$err" | grep -Eq '^reference rays: row 240/240 \(100%\), [0-9]+:[0-9]{2} elapsed *$'; then
    fail "no final progress line: $(tail -c 200 "$err" | tr '\r' '|')"
else
    pass
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
