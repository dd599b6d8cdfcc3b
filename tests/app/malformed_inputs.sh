#!/usr/bin/env bash
# The catalogue of malformed inputs: scene JSON, OBJ, PLY (ASCII and binary), EXR
# given to `compare`, and bad values of every command's options. Each case must exit
# non-zero within 10 s under a 4 GiB address-space limit, print exactly one stderr line
# "shadowlab: error: ..." holding the expected text, and leave no output file.
# The inputs are made here, in the scratch directory: truncated, empty, binary-garbage and
# wrong-type files, enormous declared counts, a symlink loop, directories given as files.
# Usage: malformed_inputs.sh PATH/TO/shadowlab SCRATCH_DIR
# SHADOWLAB_CATALOGUE_MEMORY: the address-space limit in KiB (default 4194304), or
# "unlimited" for a sanitizer build, whose shadow memory needs terabytes of address space
# (AddressSanitizer bounds each allocation itself).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/one_line_error.sh"

bin=${1:?usage: malformed_inputs.sh SHADOWLAB SCRATCH_DIR}
dir=${2:?usage: malformed_inputs.sh SHADOWLAB SCRATCH_DIR}
rm -rf "$dir"
mkdir -p "$dir"
cases=0
failed=0
out=$dir/out.png   # every render case names this output; none may leave it

# expect NAME EXPECTED ARGS...: the case described above.
expect() {
    local name=$1 expected=$2
    shift 2
    cases=$((cases + 1))
    rm -f "$out"
    # A subshell keeps the limits to this case: 4 GiB of address space (by default), 10 s.
    (ulimit -v "${SHADOWLAB_CATALOGUE_MEMORY:-4194304}"; exec timeout 10 "$bin" "$@") >"$dir/stdout" 2>"$dir/stderr"
    local rc=$? problem=""
    if [ "$rc" -eq 124 ]; then problem="did not finish in 10 s"   # timeout's status
    else problem=$(one_line_error_problem "$rc" "$dir/stderr")
    fi
    if [ -z "$problem" ] && ! grep -qF -- "$expected" "$dir/stderr"; then problem="the message lacks \"$expected\""
    elif [ -z "$problem" ] && [ -e "$out" ]; then problem="left $out behind"
    fi
    if [ -n "$problem" ]; then
        failed=$((failed + 1))
        echo "FAIL: $name: $problem; 'shadowlab $*' stderr:"
        head -c 400 "$dir/stderr" | sed 's/^/    /'
    fi
}

# ---- Inputs -----------------------------------------------------------------------------
# Binary garbage, the same 4096 bytes on every run (random bytes made the expected messages
# flaky: a garbage file starting with a newline moves the JSON error to line 2): a 16-byte
# pattern of high, control and NUL bytes in which no line starts with a letter.
garbage() { for _ in $(seq 256); do printf '\xff\xfe\x00\x9c\x01\x80 v\x7f\n\xc3\x28\x00\x10\xee\x1b'; done; }
scene() {   # scene FILE MESHES INSTANCES [CAMERA]: a scene file around the given parts
    local camera=${4:-'{"eye": [0, 3, 6], "target": [0, 0, 0], "fovy": 45, "width": 32, "height": 24}'}
    printf '{"meshes": %s, "materials": [{"name": "m"}], "instances": %s,\n "lights": [{"type": "point", "position": [0, 5, 0], "power": 10}],\n "camera": %s}\n' \
        "$2" "$3" "$camera" >"$dir/$1"
}
box='[{"name": "box", "procedural": "box", "min": [-1, 0, -1], "max": [1, 1, 1]}]'
onBox='[{"mesh": "box", "material": "m"}]'
meshFile() { echo "[{\"name\": \"f\", \"file\": \"$1\"}]"; }
onFile='[{"mesh": "f", "material": "m"}]'

: >"$dir/empty.json"
garbage >"$dir/garbage.json"
scene valid.json "$box" "$onBox"
head -c 100 "$dir/valid.json" >"$dir/truncated.json"
echo '[1, 2, 3]' >"$dir/array.json"
scene string-meshes.json '"box"' "$onBox"
scene overflow-number.json '[{"name": "box", "procedural": "box", "min": [-1e999, 0, -1], "max": [1, 1, 1]}]' "$onBox"
python3 -c "print('[' * 100000 + ']' * 100000)" >"$dir/deep.json"
scene repeat.json "$box" '[{"mesh": "box", "material": "m", "repeat": {"count": [1024, 1024, 1024], "offset": [1, 1, 1]}}]'
scene grid.json '[{"name": "g", "procedural": "grid", "size": [1, 1], "divisions": [16384, 16384]}]' '[{"mesh": "g", "material": "m"}]'
scene sphere.json '[{"name": "s", "procedural": "uv-sphere", "radius": 1, "slices": 16384, "stacks": 16384}]' '[{"mesh": "s", "material": "m"}]'
scene overflow.json "$box" '[{"mesh": "box", "material": "m", "translate": [9e5, 0, 0], "scale": 2e38}]'
scene wide.json "$box" "$onBox" '{"eye": [0, 3, 6], "target": [0, 0, 0], "fovy": 45, "width": 16384, "height": 24}'
scene parallel.json "$box" "$onBox" '{"eye": [0, 9, 0], "target": [0, 0, 0], "fovy": 45, "width": 32, "height": 24}'
scene typo.json "$box" '[{"mesh": "box", "material": "m", "transalte": [0, 1, 0]}]'
mkdir -p "$dir/folder.json" "$dir/folder.obj"
ln -sf loop-b.json "$dir/loop-a.json"
ln -sf loop-a.json "$dir/loop-b.json"
scene missing-mesh.json "$(meshFile none.obj)" "$onFile"
scene folder-mesh.json "$(meshFile folder.obj)" "$onFile"
ln -sf loop-b.obj "$dir/loop-a.obj"
ln -sf loop-a.obj "$dir/loop-b.obj"
scene loop-mesh.json "$(meshFile loop-a.obj)" "$onFile"
for name in no-faces garbage index nan short empty-ply header-ply truncated-ply huge-ply rows-ply text-ply \
            big-endian-ply list-ply; do
    ext=obj
    [[ $name == *-ply ]] && ext=ply
    scene "mesh-$name.json" "$(meshFile "$name.$ext")" "$onFile"
done
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' >"$dir/no-faces.obj"
garbage >"$dir/garbage.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$dir/index.obj"
printf 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n' >"$dir/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n' >"$dir/short.obj"
: >"$dir/empty-ply.ply"
printf 'ply\nformat ascii 1.0\nelement vertex 3\n' >"$dir/header-ply.ply"
plyBinary='ply\nformat binary_little_endian 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\nelement face %s\nproperty list uchar int vertex_indices\nend_header\n'
{ printf "$plyBinary" 3 1; head -c 20 /dev/zero; } >"$dir/truncated-ply.ply"
{ printf "$plyBinary" 4000000000 4000000000; head -c 64 /dev/zero; } >"$dir/huge-ply.ply"
printf 'ply\nformat ascii 1.0\nelement junk 18446744073709551615\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$dir/rows-ply.ply"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n' >"$dir/text-ply.ply"
printf 'ply\nformat binary_big_endian 1.0\nend_header\n' >"$dir/big-endian-ply.ply"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n'
  head -c 36 /dev/zero; printf '\xff\xff\xff\xff'; head -c 12 /dev/zero; } >"$dir/list-ply.ply"
garbage >"$dir/garbage.exr"
: >"$dir/empty.exr"
mkdir -p "$dir/folder.exr"
# Magic number, version 2, then one attribute: "x" of type "blob" declaring 2^31 - 1 bytes;
# and a "dataWindow" box2i of (0, 0) - (0, 2^31 - 2).
printf 'v/1\x01\x02\x00\x00\x00x\x00blob\x00\xff\xff\xff\x7f' >"$dir/huge-attribute.exr"
{ printf 'v/1\x01\x02\x00\x00\x00dataWindow\x00box2i\x00\x10\x00\x00\x00'
  head -c 12 /dev/zero; printf '\xfe\xff\xff\x7f\x00'; } >"$dir/tall-window.exr"

# ---- Scene files --------------------------------------------------------------------------
expect "empty scene file" "invalid JSON: [json.exception.parse_error.101] parse error at line 1, column 1: syntax error while parsing value - unexpected end of input" render "$dir/empty.json" -o "$out"
expect "binary garbage as a scene" "garbage.json: invalid JSON: [json.exception.parse_error.101] parse error at line 1" render "$dir/garbage.json" -o "$out"
expect "truncated scene" "invalid JSON: [json.exception.parse_error.101] parse error at line 1, column 101" render "$dir/truncated.json" -o "$out"
expect "an array, not an object" "array.json: must be an object, got [1,2,3]" render "$dir/array.json" -o "$out"
expect "meshes as a string" "meshes: must be an array" render "$dir/string-meshes.json" -o "$out"
expect "a number beyond double" "meshes[0].min[0]: invalid JSON: [json.exception.out_of_range.406] number overflow parsing '-1e999'" render "$dir/overflow-number.json" -o "$out"
expect "JSON nested 100000 deep" "nested deeper than 64 levels" render "$dir/deep.json" -o "$out"
expect "a repeat of 1024^3 copies" "makes 1073741824 copies; a scene holds at most 65536 instances" render "$dir/repeat.json" -o "$out"
expect "a 16384^2 grid" "makes 536870912 triangles, more than a scene may hold" render "$dir/grid.json" -o "$out"
expect "a 16384^2 sphere" "makes 536838144 triangles, more than a scene may hold" render "$dir/sphere.json" -o "$out"
expect "a transform placing vertices beyond the world" "lands outside the world" render "$dir/overflow.json" -o "$out"
expect "a 16384-pixel camera" "camera.width: must be in [1, 8192], got 16384" render "$dir/wide.json" -o "$out"
expect "a view parallel to up" "up must not be zero or parallel to the viewing direction" render "$dir/parallel.json" -o "$out"
expect "a misspelt key" "unknown key \"transalte\"" render "$dir/typo.json" -o "$out"
expect "a directory as the scene" "is a directory, not a file" render "$dir/folder.json" -o "$out"
expect "a symlink loop as the scene" "cannot open" render "$dir/loop-a.json" -o "$out"
expect "a missing scene" "cannot open" render "$dir/none.json" -o "$out"
expect "a missing mesh file" "none.obj: cannot open" render "$dir/missing-mesh.json" -o "$out"
expect "a directory as the mesh" "folder.obj: is a directory, not a file" render "$dir/folder-mesh.json" -o "$out"
expect "a symlink loop as the mesh" "loop-a.obj: cannot open" render "$dir/loop-mesh.json" -o "$out"

# ---- OBJ ------------------------------------------------------------------------------------
expect "an OBJ without faces" "the scene has no triangles" render "$dir/mesh-no-faces.json" -o "$out"
expect "binary garbage as OBJ" "garbage.obj: holds no vertices and no faces (not an OBJ file?)" render "$dir/mesh-garbage.json" -o "$out"
expect "an OBJ index out of range" "vertex index 9 (1-based) is out of range" render "$dir/mesh-index.json" -o "$out"
expect "an OBJ NaN vertex" "vertex x \"nan\"" render "$dir/mesh-nan.json" -o "$out"
expect "an OBJ face of two corners" "short.obj: 1 face(s) with fewer than 3 vertices" render "$dir/mesh-short.json" -o "$out"

# ---- PLY ------------------------------------------------------------------------------------
expect "an empty PLY" "the file ends before \"end_header\"" render "$dir/mesh-empty-ply.json" -o "$out"
expect "a PLY header without end" "the file ends before \"end_header\"" render "$dir/mesh-header-ply.json" -o "$out"
expect "a truncated binary PLY" "element vertex 1: truncated" render "$dir/mesh-truncated-ply.json" -o "$out"
expect "a PLY declaring 4e9 vertices" "truncated" render "$dir/mesh-huge-ply.json" -o "$out"
expect "a PLY element of 2^64 - 1 empty rows" "has 18446744073709551615 rows but no properties" render "$dir/mesh-rows-ply.json" -o "$out"
expect "a word in an ASCII PLY" "\"zero\" is not a valid float" render "$dir/mesh-text-ply.json" -o "$out"
expect "a big-endian PLY" "binary_big_endian PLY is not supported" render "$dir/mesh-big-endian-ply.json" -o "$out"
expect "a PLY list of 2^32 - 1 items" "truncated" render "$dir/mesh-list-ply.json" -o "$out"

# ---- EXR given to compare ---------------------------------------------------------------------
"$bin" render sphere-box --width 32 --height 20 --aov "$dir/ok.exr" -o "$dir/ok.png" >/dev/null 2>&1 ||
    { echo "FAIL: could not render the valid EXR the compare cases use"; failed=$((failed + 1)); }
expect "binary garbage as EXR" "EXR file '$dir/garbage.exr': not an EXR file (no magic number)" compare "$dir/garbage.exr" "$dir/ok.exr" --heatmap "$out"
expect "an empty EXR" "empty.exr': Early end of file: read 0 out of 4 requested bytes." compare "$dir/ok.exr" "$dir/empty.exr" --heatmap "$out"
expect "a directory as EXR" "reference: File is actually a directory: $dir/folder.exr" compare "$dir/folder.exr" "$dir/ok.exr" --heatmap "$out"
expect "an EXR attribute of 2^31 - 1 bytes in 24" "header attribute 'x' declares 2147483647 bytes, more than the 0 left in the file" compare "$dir/ok.exr" "$dir/huge-attribute.exr" --heatmap "$out"
expect "an EXR data window of 2^31 - 1 rows" "data window is 1 x 2147483647 pixels; images must be 1..8192 on a side" compare "$dir/tall-window.exr" "$dir/ok.exr" --heatmap "$out"
expect "a channel the EXR lacks" "has no channel 'Q'" compare "$dir/ok.exr" "$dir/ok.exr" --channel Q --heatmap "$out"

# ---- Quoted text stays on one line ----------------------------------------------------------
# A newline or an escape character in a JSON key, a name or a file name split the message.
printf '{"meshes": [], "materials": [], "instances": [], "camera": {}, "bad\\nkey\\u001b[31m": 1}\n' >"$dir/key-newline.json"
scene name-newline.json "$box" '[{"mesh": "bo\nx", "material": "m"}]'
expect "a JSON key holding a newline" 'unknown key "bad\nkey\x1b[31m"' render "$dir/key-newline.json" -o "$out"
expect "a mesh name holding a newline" 'no mesh is named "bo\nx"' render "$dir/name-newline.json" -o "$out"
expect "a file name holding a newline" 'two\nlines.json: cannot open' render "$dir/two
lines.json" -o "$out"

# ---- Images and special files ----------------------------------------------------------------
# Every reader checks a file's type before opening it (a FIFO blocked every one of them) and
# reads no more than the file's size (/dev/zero as a calibration read 2 GB); every 8-bit
# image goes through one checked decoder that accepts PNG (and JPEG for photographs).
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tiny=(--width 32 --height 20)
mkfifo "$dir/fifo"
# A run-length Radiance HDR cut short (stb_image 2.27 spun for ever on it), a TGA and a PPM
# whose headers promise 64 x 64 pixels the file does not hold, a PNG cut in half.
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 64 +X 64\n\x02\x02\x00\x40\x80' >"$dir/short.hdr"
printf '\x00\x00\x02\x00\x00\x00\x00\x00\x00\x00\x00\x00\x40\x00\x40\x00\x18\x00\x80\x80' >"$dir/short.tga"
printf 'P6\n64 64\n255\n\x80\x80' >"$dir/short.ppm"
blinds=$src/assets/textures/blinds.png
head -c "$(($(stat -c %s "$blinds") / 2))" "$blinds" >"$dir/half.png"
for image in short.hdr short.tga short.ppm half.png fifo; do
    sed "s|../../textures/blinds.png|$dir/$image|" "$src/assets/scenes/cookies/spot-cookie.json" >"$dir/cookie-$image.json"
done
expect "a truncated run-length HDR as a cookie" "short.hdr: is a Radiance HDR image; here only PNG is read" render "$dir/cookie-short.hdr.json" "${tiny[@]}" -o "$out"
expect "a short TGA as a cookie" "short.tga: is not an image this program reads" render "$dir/cookie-short.tga.json" "${tiny[@]}" -o "$out"
expect "a short PPM as a cookie" "short.ppm: is a PNM image; here only PNG is read" render "$dir/cookie-short.ppm.json" "${tiny[@]}" -o "$out"
expect "half a PNG as a cookie" "half.png: is truncated: a PNG file ends with its IEND chunk" render "$dir/cookie-half.png.json" "${tiny[@]}" -o "$out"
expect "a FIFO as a cookie" "fifo: is a FIFO (named pipe), not a file" render "$dir/cookie-fifo.json" "${tiny[@]}" -o "$out"
sed "s|../../environments/pmndrs_sky.exr|$dir/fifo|" "$src/assets/scenes/environment/sphere-sky.json" >"$dir/sky-fifo.json"
expect "a FIFO as a scene's environment map" "environment.map: $dir/fifo: is a FIFO (named pipe), not a file" render "$dir/sky-fifo.json" "${tiny[@]}" -o "$out"
expect "a FIFO as an environment map" "fifo: is a FIFO (named pipe), not a file" environment "$dir/fifo" --out "$dir/env"
# A path of 10^7 rows (300 MB) was read whole, twice, before row 65,538 was refused.
truncate -s 100M "$dir/huge.csv"
expect "a camera path past its size bound" "huge.csv: 104857600 bytes, more than the 67108864 such a file may have" flythrough sphere-box --technique shadow-map --path "$dir/huge.csv" --out "$dir/fly"
expect "a FIFO as a camera path" "fifo: is a FIFO (named pipe), not a file" flythrough sphere-box --technique shadow-map --path "$dir/fifo" --out "$dir/fly"
expect "a FIFO as a sweep's shard" "fifo: is a FIFO (named pipe), not a file" merge-sweep "$dir/fifo" --out "$dir/merged"
expect "a FIFO as a report's input" "fifo: is a FIFO (named pipe), not a file" report "$dir/fifo" --out "$dir/report"
expect "a FIFO as an EXR to compare" "fifo: is a FIFO (named pipe), not a file" compare "$dir/fifo" "$dir/ok.exr" --heatmap "$out"
compositing() {   # compositing NAME FROM TO: the shipped chessboard file with FROM replaced by TO
    sed -e "s|\"\.\./\.\./|\"$src/assets/|g" -e "s|$2|$3|" "$src/assets/scenes/compositing/chessboard.json" >"$dir/$1.json"
}
compositing photo-fifo "$src/assets/photos/chessboard_left05_undistorted.png" "$dir/fifo"
compositing calibration-zero "$src/assets/photos/chessboard_left05_camera.txt" /dev/zero
compositing photo-half "$src/assets/photos/chessboard_left05_undistorted.png" "$dir/half.png"
expect "a FIFO as a compositing file's photograph" "fifo: is a FIFO (named pipe), not a file" composite "$dir/photo-fifo.json" --no-reference --frames 0
expect "/dev/zero as a calibration" "/dev/zero: is a character device, not a file" composite "$dir/calibration-zero.json" --no-reference --frames 0
expect "half a PNG as a photograph" "half.png: is truncated" composite "$dir/photo-half.json" --no-reference --frames 0

# ---- Command-line values --------------------------------------------------------------------
expect "render --threads 100000" "--threads: Value 100000 not in range 0 to 1024" render sphere-box --threads 100000 -o "$out"
expect "render --width 0" "--width: Value 0 not in range 1 to 8192" render sphere-box --width 0 -o "$out"
expect "render --width 9000" "--width: Value 9000 not in range 1 to 8192" render sphere-box --width 9000 -o "$out"
expect "render --fovy 0" "--fovy must be in (0, 180) degrees" render sphere-box --fovy 0 "${tiny[@]}" -o "$out"
expect "render --eye nan" "--eye: expected three numbers as x,y,z, got 'nan,0,0'" render sphere-box --eye nan,0,0 "${tiny[@]}" -o "$out"
expect "render --eye above the target" "parallel to the camera's up" render sphere-box --eye 0,9,0 --target 0,0,0 "${tiny[@]}" -o "$out"
expect "render --light-radius -1" "--light-radius must be a finite number > 0" render sphere-box --light-radius -1 "${tiny[@]}" -o "$out"
expect "render --simd bogus" "unknown SIMD level 'bogus'" render sphere-box --simd bogus "${tiny[@]}" -o "$out"
expect "render --param resolution=abc" "shadow-map: parameter resolution=abc: must be an integer in 16..8192" render sphere-box --technique shadow-map --param resolution=abc "${tiny[@]}" -o "$out"
expect "sweep --threads 0" "--threads: Value 0 not in range 1 to 1024" sweep sphere-box --technique shadow-map --threads 0 --out "$dir/sweep"
expect "sweep --runs 0" "--runs: Value 0 not in range 1 to 10000" sweep sphere-box --technique shadow-map --runs 0 --out "$dir/sweep"
expect "scaling with one scene" "scaling: give at least two scenes" scaling sphere-box --technique shadow-map --out "$dir/scaling"
expect "bench --threads 100000" "--threads: Value 100000 not in range 1 to 1024" bench --scenes sphere-box --threads 100000
expect "bench --json into a missing directory" "cannot write '$dir/missing/b.json': no directory '$dir/missing'" bench --scenes throughput --runs 1000 --json "$dir/missing/b.json"
expect "binary garbage as a sweep's shard" "garbage.json: invalid JSON: [json.exception.parse_error.101]" merge-sweep "$dir/garbage.json" --out "$dir/merged"
expect "a shard nested 100000 deep" "deep.json: nested deeper than 64 levels" merge-sweep "$dir/deep.json" --out "$dir/merged"
expect "a scene file as a shard" "valid.json: not the JSON of a sweep: " merge-sweep "$dir/valid.json" --out "$dir/merged"
expect "binary garbage as a report's input" "garbage.json: invalid JSON: [json.exception.parse_error.101]" \
    report "$dir/garbage.json" --out "$dir/report"
expect "a shard nested 100000 deep as a report's input" "deep.json: nested deeper than 64 levels" \
    report "$dir/deep.json" --out "$dir/report"
expect "a scene file as a report's input" "valid.json: neither a sweep's JSON (with grid and rows) nor that of render" \
    report "$dir/valid.json" --out "$dir/report"
expect "export-obj into a missing directory" "cannot write '$dir/missing/x.obj': cannot make a temporary file: No such file or directory" export-obj sphere-box "$dir/missing/x.obj"

echo "$cases cases, $failed failed"
[ "$cases" -ge 40 ] || { echo "FAIL: the catalogue holds only $cases cases"; exit 1; }
[ "$failed" -eq 0 ]
