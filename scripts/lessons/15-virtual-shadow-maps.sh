#!/bin/sh
# Pictures and figures of docs/lessons/15-virtual-shadow-maps.md: the virtual shadow map's
# stages on assets/scenes/hard/sun.json seen low and close (lesson 5's view, 480 x 300, 2
# threads): each pixel's level, the page table, the pool, the shadow, beside lesson 5's
# budget; the pages kept along two paths; the cliff of a pool too small; then shadow-map ray
# tracing under a sized sun (soft/sun-disk) and a disk light (soft/two-heights).
# Run by scripts/lessons.sh, which sets $app, $images and $scratch.
set -eu
. scripts/lessons/common.sh
need_convert
scene=assets/scenes/hard/sun.json
view="--eye -3.2,1.1,1.8 --target 0,0.2,-1 --fovy 55"

# shot NAME SCENE TECHNIQUE [RENDER ARGS...]: image, error map, figures and buffers into $scratch/NAME*
shot() {
  name=$1; file=$2; technique=$3; shift 3
  "$app" render "$file" --technique "$technique" "$@" --threads 2 \
    -o "$scratch/$name.png" --error-map "$scratch/$name-error.png" --json "$scratch/$name.json" \
    --debug-buffers "$scratch/$name-buffers" > "$scratch/$name.log"
}
# buffer NAME BUFFER SHOWN: one of the virtual map's debug buffers into the lesson's images.
buffer() { cp "$scratch/$1-buffers/virtual-shadow-map-$2.png" "$images/$3.png"; }

# The stages, at the defaults: 16384-texel levels in pages of 128.
shot vsm "$scene" virtual-shadow-map $view --width 480 --height 300
cp "$scratch/vsm.png" "$images/vsm.png"
cp "$scratch/vsm-error.png" "$images/vsm-error.png"
buffer vsm level level
buffer vsm texels-per-pixel texels-per-pixel
# The page table stacks the 13 levels' tables, 128 x 128 pages each, one pixel a page: the
# view reads levels 5 to 8 (squares 7 to 10 from the top), a few pages round each window's
# centre. Shown: 16 x 16 pages round the centre of each, a page 12 pixels wide.
for square in 7 8 9 10; do
  $convert "$scratch/vsm-buffers/virtual-shadow-map-page-table.png" -crop 16x16+56+$((square * 128 + 56)) +repage \
    -sample 1200% "$scratch/page-table-$square.png"
done
$convert "$scratch"/page-table-7.png "$scratch"/page-table-8.png "$scratch"/page-table-9.png \
  "$scratch"/page-table-10.png -bordercolor white -border 4 +append "$images/page-table.png"
# The pool: 9 x 9 pages of 128^2 texels, shown at half size.
$convert "$scratch/vsm-buffers/virtual-shadow-map-pool.png" -resize 50% "$images/pool.png"
python3 -c 'import json, sys
stats = json.load(open(sys.argv[1]))["stats"]
print("pages requested: %d, pool in use: %.2f MiB" % (stats["requested_pages"], stats["cache_pool_bytes"] / 2**20))' \
  "$scratch/vsm.json"

# Lesson 5's budget: one map of 512^2, four cascades of 256^2; and the maps at 2048.
shot map512 "$scene" shadow-map $view --width 480 --height 300 --param resolution=512
shot csm256 "$scene" csm $view --width 480 --height 300 --param resolution=256
shot map2048 "$scene" shadow-map $view --width 480 --height 300
echo "the sun case, lesson 5's view (480 x 300):"
$figures "shadow-map, 512 (1 MiB)=$scratch/map512.json" \
  "csm, 4 x 256 (1 MiB)=$scratch/csm256.json" "shadow-map, 2048 (16 MiB)=$scratch/map2048.json" \
  "virtual-shadow-map (the pages in use)=$scratch/vsm.json"

# Pages kept across frames: a sliding sphere under a still sun, then under a turning sun.
for path in sliding-sphere-still-sun sliding-sphere-sun; do
  "$app" flythrough "assets/scenes/flythrough/$path.json" --technique virtual-shadow-map --frames 8 \
    --width 480 --height 300 --threads 2 --runs 1 --warmup 0 --out "$scratch/fly" > /dev/null
  echo "$path: frame, pages requested, drawn, cache hits %"
  python3 -c 'import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    print("%s %d %d %.0f" % (row["frame"], float(row["requested_pages"]), float(row["cache_drawn_pages"]),
                             float(row["cache_hit_percent"])))' \
    "$scratch/fly/$path-flythrough-virtual-shadow-map.csv"
done

# The failure: a pool too small for the pages the view needs.
for pool in 16 32 48; do
  shot "pool-$pool" "$scene" virtual-shadow-map $view --width 480 --height 300 --param pool-pages="$pool"
done
cp "$scratch/pool-32-error.png" "$images/pool-32-error.png"
echo "virtual-shadow-map, pool-pages:"
$figures --stats cache_overflowed_pages,cache_missing_pixels "16=$scratch/pool-16.json" "32=$scratch/pool-32.json" \
  "48=$scratch/pool-48.json" "1024 (default)=$scratch/vsm.json"

# Soft shadows: shadow-map ray tracing under a sun of 2.5 degrees, then a disk light.
sun=assets/scenes/soft/sun-disk.json
for rays in 0 4 16; do
  shot "sun-rays-$rays" "$sun" virtual-shadow-map --width 320 --height 200 --param smrt-rays="$rays" \
    --reference reference-soft
done
"$app" render "$sun" --technique reference-soft --width 320 --height 200 --threads 2 -o "$scratch/sun-reference.png" \
  > /dev/null
cp "$scratch/sun-reference.png" "$images/sun-reference.png"
for rays in 0 16; do cp "$scratch/sun-rays-$rays.png" "$images/sun-rays-$rays.png"; done
buffer sun-rays-16 smrt-escaped sun-escaped
echo "sun-disk (320 x 200), smrt-rays:"
$figures --stats lookup_ms "0 (the hard lookup)=$scratch/sun-rays-0.json" "4=$scratch/sun-rays-4.json" \
  "16=$scratch/sun-rays-16.json"

disk=assets/scenes/soft/two-heights.json
shot disk-rays-16 "$disk" virtual-shadow-map --width 320 --height 200 --param smrt-rays=16 --reference reference-soft
shot disk-pcss "$disk" pcss --width 320 --height 200 --reference reference-soft
for name in disk-rays-16 disk-pcss; do cp "$scratch/$name-error.png" "$images/$name-error.png"; done
echo "two-heights (320 x 200):"
$figures "virtual-shadow-map, 16 rays=$scratch/disk-rays-16.json" "pcss=$scratch/disk-pcss.json"
