#!/bin/sh
# Reproduces every speed and error figure in docs/performance.md: the hard- and soft-shadow sweeps,
# every hard case, the shadow map's bias-by-resolution grid, Figure 7's torus and the eq. 8
# scaling fit, the environment techniques' images and buffers, and speed against error by
# caster level of detail, differential rendering into photographs, and every technique's
# stages to one standard (the Figure 3 table is scripts/figure3.sh, about an hour on its own),
# and the virtual shadow map against cascades and shadow maps at equal memory
# (docs/virtual-shadow-maps.md), and the settings a node sweeps per hour (docs/scale.md).
# Writes CSV, JSON and SVG under out/figures, copies the plots and images the docs show into
# docs/images, and prints docs/performance.md's tables. Takes about 10 minutes on 2 cores,
# more for the sweeps' pictures (docs/report.md), ten minutes for the fly-throughs, about
# fifteen for the technique-standard sweeps and twelve for the virtual map's; run nothing
# else meanwhile (times are medians, but a busy machine still moves them).
# Last, the HTML report of every sweep (each run with --images): out/report/index.html.
# usage: scripts/figures.sh [hard|cases|bias|models|soft|torus|views|scaling|bench|environment|lod|differential|screen|volumetric|cutouts|flythrough|temporal|lights|suite|standard|virtual|scale|report ...]
#        (default: all twenty-three, report last; suite needs the packages scripts/suite_models.sh installs)
set -eu
cd "$(dirname "$0")/.."
app=build/app/shadowlab
out=out/figures
table=scripts/sweep_table.py
mkdir -p "$out"
parts=${*:-hard cases bias models soft torus views scaling bench environment lod differential screen volumetric cutouts flythrough temporal lights suite standard virtual scale report}

for part in $parts; do
  case $part in
  hard)
    for scene in sphere-box bunny; do
      $app sweep $scene --images --technique none,reference,shadow-map,izb,shadow-volume,planar \
        --threads 1,2 --runs 5 --out $out/hard
      python3 $table $out/hard/$scene-none+reference+shadow-map+izb+shadow-volume+planar.csv hard
      cp $out/hard/$scene-none+reference+shadow-map+izb+shadow-volume+planar.svg docs/images/hard-$scene.svg
    done
    # Cascades need a directional light: the sun over sphere-box.
    $app sweep assets/scenes/hard/sun.json --images --technique shadow-map,csm --threads 1,2 --runs 5 --out $out/hard
    python3 $table $out/hard/sun-shadow-map+csm.csv hard
    ;;
  cases)
    # Misclassified % of each hard-shadow technique on every hard case, at its defaults.
    for scene in assets/scenes/hard/*.json; do
      $app sweep $scene --images --technique shadow-map,izb,shadow-volume,planar --threads 2 --runs 1 --out $out/cases > /dev/null
    done
    $app sweep assets/scenes/hard/sun.json --images --technique shadow-map --param warp=lispsm --threads 2 --runs 1 --out $out/cases/lispsm > /dev/null
    $app sweep assets/scenes/hard/sun.json --images --technique csm --threads 2 --runs 1 --out $out/cases/csm > /dev/null
    python3 $table --matrix $out/cases/*.csv
    python3 $table $out/cases/lispsm/sun-shadow-map.csv hard
    python3 $table $out/cases/csm/sun-csm.csv hard
    ;;
  bias)
    # How acne (false shadow) and leaks (false light) move with resolution and slope bias.
    $app sweep sphere-box --images --technique shadow-map --param resolution=512,1024,2048,4096 \
      --param slope-factor=0,0.5,1.5,4 --threads 2 --runs 3 --out $out/bias
    python3 $table --grid resolution slope-factor $out/bias/sphere-box-shadow-map.csv
    ;;
  models)
    # The bias models and depth layers of docs/shadow-maps.md ("Why the default bias").
    for scene in sphere-box bunny; do
      $app sweep $scene --images --technique shadow-map --param bias=slope-scaled,receiver-plane,constant,normal-offset \
        --threads 2 --runs 1 --out $out/models/bias > /dev/null
      $app sweep $scene --images --technique shadow-map --param layer=second,midpoint --threads 2 --runs 1 \
        --out $out/models/layer > /dev/null
      echo "$scene"
      python3 $table $out/models/bias/$scene-shadow-map.csv hard
      python3 $table $out/models/layer/$scene-shadow-map.csv hard
    done
    ;;
  soft)
    # Every soft technique on every soft case: sphere-box, the bunny, the five cases of Cai
    # et al. and two occluders at very different heights; then the min/max hierarchy's
    # speed-up (the same V) for pcss and backprojection on three of them.
    soft=none,reference,pcss,chs,vsm,esm,evsm,msm,multi-sample,backprojection,soft-shadow-volumes,fins,smoothies,penumbra-maps
    for scene in sphere-box bunny assets/scenes/soft/large-light.json assets/scenes/soft/tilted-receiver.json \
                 assets/scenes/soft/two-boxes.json assets/scenes/soft/sharp-corner.json assets/scenes/soft/torus-over-plane.json \
                 assets/scenes/soft/two-heights.json; do
      $app sweep $scene --images --technique $soft --reference reference-soft --threads 1,2 --runs 5 --out $out/soft --plot-y rms
      name=$(basename $scene .json)
      python3 $table $out/soft/$name-$(echo $soft | tr , +).csv soft
      cp $out/soft/$name-$(echo $soft | tr , +).svg docs/images/soft-$name.svg
    done
    for scene in sphere-box bunny assets/scenes/soft/two-heights.json; do
      $app sweep $scene --images --technique pcss,backprojection --param min-max-hierarchy=off,on --reference reference-soft \
        --threads 1,2 --runs 5 --out $out/hierarchy --plot-y rms
      python3 $table $out/hierarchy/$(basename $scene .json)-pcss+backprojection.csv soft
    done
    ;;
  torus)
    # Figure 7 of Cai et al.: single-layer against 16-layer fins on the two-holed torus over
    # a slab, each with the diff heat map against the soft reference.
    torus=assets/scenes/soft/torus-over-plane.json
    $app render $torus --technique reference-soft --width 640 --height 400 -o docs/images/torus-reference-soft.png --aov $out/torus-reference-soft.exr
    for layers in 1 16; do
      $app render $torus --technique fins --param layers=$layers --width 640 --height 400 \
        -o docs/images/torus-fins-$layers.png --aov $out/torus-fins-$layers.exr
      $app compare $out/torus-reference-soft.exr $out/torus-fins-$layers.exr --heatmap docs/images/torus-fins-$layers-diff.png
    done
    ;;
  scaling)
    for technique in fins smoothies pcss; do
      $app scaling assets/scenes/scaling/*.json --technique $technique --threads 1 --runs 11 --warmup 2 --out $out/scaling
    done
    cp $out/scaling/scaling-fins.svg docs/images/scaling-fins.svg
    ;;
  views)
    # The views of docs/hard-shadows.md: an error map and the intermediate buffers.
    mkdir -p $out/views
    small="--width 640 --height 400 -o $out/views/render.png"
    # A coarse map with too small a constant bias: acne (red) on every lit surface, leaks (blue).
    $app render sphere-box --technique shadow-map $small --param resolution=256 --param bias=constant \
      --param constant-bias=0.02 --error-map docs/images/view-error-map.png
    $app render sphere-box --technique shadow-map $small --param resolution=512 --debug-buffers $out/views
    $app render assets/scenes/hard/sun.json --technique csm $small --debug-buffers $out/views
    $app render bunny --technique shadow-volume $small --debug-buffers $out/views
    $app render sphere-box --technique izb $small --debug-buffers $out/views
    for view in shadow-map-texel-density csm-cascades shadow-volume-stencil shadow-volume-fill izb-list-length; do
      cp $out/views/$view.png docs/images/view-$view.png
    done
    ;;
  bench)
    # Depth-only passes and reference rays on the built-in scenes (docs/performance.md, "Performance").
    $app bench --runs 21 --json $out/bench.json
    build/bench/bench_stages --benchmark_filter=BM_RasterTiles --benchmark_repetitions=5 \
      --benchmark_report_aggregates_only=true
    ;;
  environment)
    # docs/subtractive-shadows.md: the glossy bunny under the interior map, the exact
    # reference beside additive and subtractive shadows at N = 40, subtractive at lower
    # sampling detail and with region lobes, and the buffers of the subtractive frame.
    bunny=assets/scenes/environment/bunny-interior.json
    small="--width 480 --height 300"
    $app render $bunny --technique reference-env $small -o docs/images/env-reference.png --aov $out/env-reference.exr
    $app render $bunny --technique env-additive $small -o docs/images/env-additive-40.png
    for detail in 1 1/16 1/1024; do
      $app render $bunny --technique env-subtractive $small --param sampling-detail=$detail \
        -o docs/images/env-subtractive-40-$(echo $detail | tr / -).png
    done
    $app render $bunny --technique env-additive $small --param light-lobes=region -o docs/images/env-additive-40-region.png
    $app render $bunny --technique env-subtractive $small --param light-lobes=region --param sampling-detail=1/16 \
      --debug-buffers $out/env -o docs/images/env-subtractive-40-region.png
    for buffer in C S S-resampled lights sh-irradiance; do
      cp $out/env/env-subtractive-$buffer.png docs/images/env-buffer-$buffer.png
    done
    ;;
  lod)
    # Caster level of detail (docs/performance.md, "Shadow level of detail: simplified
    # casters"): the casters simplified to a share of their triangles, the receivers whole;
    # speed against error per ratio, for hard, soft and environment shadows, and the bunny's
    # shadow at three ratios.
    ratios=1,0.5,0.25,0.1,0.05,0.02,0.01
    $app sweep bunny --images --technique shadow-map,izb,shadow-volume --caster-lod $ratios --threads 2 --runs 11 --out $out/lod
    python3 $table $out/lod/bunny-shadow-map+izb+shadow-volume.csv hard
    cp $out/lod/bunny-shadow-map+izb+shadow-volume.svg docs/images/lod-bunny-hard.svg
    $app sweep bunny --images --technique pcss,fins --caster-lod $ratios --threads 2 --runs 11 --out $out/lod
    python3 $table $out/lod/bunny-pcss+fins.csv soft
    cp $out/lod/bunny-pcss+fins.svg docs/images/lod-bunny-soft.svg
    $app sweep assets/scenes/environment/bunny-interior.json --images --technique env-additive,env-subtractive --param lights=20,40 \
      --caster-lod 1,0.25,0.05,0.01 --reference reference-env-lights --threads 2 --runs 3 --plot-y rms-display \
      --out $out/lod
    python3 $table $out/lod/bunny-interior-env-additive+env-subtractive.csv radiance
    cp $out/lod/bunny-interior-env-additive+env-subtractive.svg docs/images/lod-bunny-interior.svg
    for ratio in 1 0.05 0.01; do
      $app render bunny --technique shadow-volume --caster-lod $ratio --width 640 --height 400 \
        --error-map docs/images/lod-shadow-volume-$ratio.png > /dev/null
    done
    ;;
  differential)
    # Differential rendering into photographs (docs/differential-rendering.md; Gibson et al.
    # 2003): each case's frames at n = 10, 20, 50 and all, timed at 2 and 1 threads (median
    # of 5 after a warm-up), scored against the exact reference; the room with every
    # radiant patch a source; the preprocessing figures; Figure 7 (lift); Figure 3 (8-bit
    # error); the reference's convergence; the intermediate buffers and the images.
    d=$out/differential
    $app composite room --threads 2 --runs 5 --warmup 1 --out $d/room-t2 > /dev/null
    $app composite room --threads 1 --runs 5 --warmup 1 --no-reference --out $d/room-t1 > /dev/null
    $app composite room --source-share 1 --threads 2 --runs 5 --warmup 1 --out $d/room-share1-t2 > /dev/null
    $app composite room-lift --threads 2 --runs 3 --warmup 1 --out $d/room-lift > /dev/null
    $app composite outdoor --frames 0,5,10 --threads 2 --runs 5 --warmup 1 --out $d/outdoor-t2 > /dev/null
    $app composite outdoor --frames 0,5,10 --threads 1 --runs 5 --warmup 1 --no-reference --out $d/outdoor-t1 > /dev/null
    # The same at 0.5%: kept per vertex, the 2% rule already leaves little out under the sky.
    $app composite outdoor --frames 0,5,10 --significance 0.005 --threads 2 --runs 5 --warmup 1 --out $d/outdoor-sig0.005-t2 > /dev/null
    $app composite outdoor --frames 0,5,10 --significance 0.005 --threads 1 --runs 5 --warmup 1 --no-reference \
      --out $d/outdoor-sig0.005-t1 > /dev/null
    $app composite room --frames 5 --passes 10 --masks --ldr-error --reference-convergence --out $d/room-buffers > /dev/null
    $app composite room --frames 5 --passes 20 --ldr --no-reference --out $d/room-ldr > /dev/null
    $app composite chessboard --frames 0,2,4 --passes 20 --ldr --no-reference --out $d/chessboard > /dev/null
    python3 scripts/composite_table.py $d
    mkdir -p docs/images/differential
    for f in background reference-f5 composite-f5-n10 composite-f5-n20 composite-f5-nall error-f5-n10 error-f5-nall \
             listed-f5-n10 shadowing-f5-n10 shadowing-f5-nall; do cp $d/room-t2/$f.png docs/images/differential/room-$f.png; done
    cp $d/room-t2/time-rms.svg docs/images/differential/room-time-rms.svg
    cp $d/room-t2/shadow-depth.svg docs/images/differential/room-shadow-depth.svg
    cp $d/room-lift/shadow-depth.svg docs/images/differential/room-lift-shadow-depth.svg
    for f in composite-f0-nall reference-f0 composite-f6-nall reference-f6; do cp $d/room-lift/$f.png docs/images/differential/room-lift-$f.png; done
    cp $d/room-buffers/ldr-error.svg docs/images/differential/ldr-error.svg
    for c in 0 1 2 3; do cp $d/room-buffers/mask-f5-n10-c$c.png docs/images/differential/room-mask-c$c.png; done
    cp $d/room-buffers/plan-f5-n10.svg docs/images/differential/room-plan-f5-n10.svg
    cp $d/room-ldr/composite-ldr-f5-n20.png docs/images/differential/room-composite-ldr-f5-n20.png
    for f in background reference-f5 composite-f5-nall error-f5-nall; do cp $d/outdoor-t2/$f.png docs/images/differential/outdoor-$f.png; done
    cp $d/chessboard/background.png docs/images/differential/chessboard-background.png
    cp $d/chessboard/composite-ldr-f2-n20.png docs/images/differential/chessboard-f2.png
    ;;
  cutouts)
    # docs/cut-outs.md: every family on the two cut-out cases against its reference (the hard
    # ones on foliage-cards and mask-card, the soft ones on the foliage under a disk light),
    # shadow-volume's three cut-out rules, izb on the foliage with its cards made solid (the
    # cost of the alpha test), and the images beside the reference's.
    c=$out/cutouts
    hard=shadow-map,izb,shadow-volume,planar
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    for scene in foliage-cards mask-card; do
      $app sweep assets/scenes/volumetric/$scene.json --technique $hard --threads 1,2 --runs 5 --out $c > /dev/null
      echo "$scene:"
      python3 $table $c/$scene-shadow-map+izb+shadow-volume+planar.csv hard
      $app sweep assets/scenes/volumetric/$scene.json --technique shadow-volume --param cut-outs=coverage,solid,none \
        --threads 2 --runs 5 --out $c/volumes > /dev/null
      python3 $table $c/volumes/$scene-shadow-volume.csv hard
    done
    mkdir -p $c/solid
    # The same scene without the alpha texture (the cards solid).
    python3 - assets/scenes/volumetric/foliage-cards.json $c/solid/foliage-cards-solid.json <<'EOF'
import json, sys
scene = json.load(open(sys.argv[1]))
for material in scene["materials"]:
    for key in ("alpha-texture", "alpha-cutoff"):
        material.pop(key, None)
json.dump(scene, open(sys.argv[2], "w"), indent=2)
EOF
    $app sweep $c/solid/foliage-cards-solid.json --technique izb --threads 1,2 --runs 5 --out $c/solid > /dev/null
    echo "foliage-cards, cards solid:"
    python3 $table $c/solid/foliage-cards-solid-izb.csv hard
    soft=pcss,izb-pcss,fins,smoothies,penumbra-maps,soft-shadow-volumes
    $app sweep assets/scenes/volumetric/foliage-cards-disk.json --technique $soft --threads 1,2 --runs 5 --out $c > /dev/null
    echo "foliage-cards-disk:"
    python3 $table $c/foliage-cards-disk-pcss+izb-pcss+fins+smoothies+penumbra-maps+soft-shadow-volumes.csv soft
    # mask-card under the disk light of the glTF MASK test (tests/shadows/test_cut_outs.cpp):
    # the fins' families on its outline.
    mkdir -p $c/disk
    python3 - assets/scenes/volumetric/mask-card.json $c/disk/mask-card-disk.json <<'EOF'
import json, math, os, sys
scene = json.load(open(sys.argv[1]))
folder = os.path.dirname(os.path.abspath(sys.argv[1]))
for mesh in scene["meshes"]:
    if "file" in mesh:
        mesh["file"] = os.path.join(folder, mesh["file"])
for material in scene["materials"]:
    if "alpha-texture" in material:
        material["alpha-texture"] = os.path.join(folder, material["alpha-texture"])
towards = [-1.5, -5.0, -2.0]
length = math.sqrt(sum(x * x for x in towards))
scene["lights"] = [{"type": "disk", "position": [1.5, 5.0, 2.0], "normal": [x / length for x in towards],
                    "radius": 0.4, "color": [1, 1, 1], "power": 380}]
json.dump(scene, open(sys.argv[2], "w"), indent=2)
EOF
    $app sweep $c/disk/mask-card-disk.json --technique fins,smoothies,penumbra-maps --threads 1,2 --runs 5 --out $c/disk > /dev/null
    echo "mask-card under a disk:"
    python3 $table $c/disk/mask-card-disk-fins+smoothies+penumbra-maps.csv soft
    for technique in reference izb shadow-volume planar; do
      $app render assets/scenes/volumetric/foliage-cards.json --technique $technique -o docs/images/cutouts-foliage-$technique.png > /dev/null
      $app render assets/scenes/volumetric/mask-card.json --technique $technique -o docs/images/cutouts-mask-$technique.png > /dev/null
    done
    for technique in reference-soft fins; do
      $app render assets/scenes/volumetric/foliage-cards-disk.json --technique $technique \
        -o docs/images/cutouts-foliage-disk-$technique.png > /dev/null
    done
    ;;
  volumetric)
    # docs/volumetric-shadows.md: every volumetric map beside the plain shadow map on the four
    # cases at 1 and 2 threads; the sweeps of slices, tolerance and nodes; the buffers.
    v=$out/volumetric
    maps=shadow-map,coloured-shadow-map,opacity-shadow-maps,deep-shadow-maps,adaptive-volumetric-shadow-maps
    stem=shadow-map+coloured-shadow-map+opacity-shadow-maps+deep-shadow-maps+adaptive-volumetric-shadow-maps
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    for scene in hair-over-plane stacked-sheets tinted-glass smoke-over-plane foliage-cards; do
      $app sweep assets/scenes/volumetric/$scene.json --images --technique $maps --threads 1,2 --runs 5 --out $v --plot-y rms > /dev/null
      echo "$scene:"
      python3 $table $v/$scene-$stem.csv volumetric
    done
    # The sweeps on the staircase of sheets, whose receivers sit inside the medium.
    glass=assets/scenes/volumetric/tinted-glass.json
    hair=assets/scenes/volumetric/hair-over-plane.json
    sheets=assets/scenes/volumetric/stacked-sheets.json
    $app sweep $sheets --images --technique opacity-shadow-maps --param slices=2,4,8,16,32,64,128 --threads 2 --runs 3 \
      --out $v/slices --plot-y rms > /dev/null
    python3 $table $v/slices/stacked-sheets-opacity-shadow-maps.csv volumetric
    $app sweep $sheets --images --technique deep-shadow-maps --param tolerance=0,0.01,0.05,0.1,0.2 --param max-vertices=4,16 \
      --threads 2 --runs 3 --out $v/tolerance --plot-y rms > /dev/null
    python3 $table $v/tolerance/stacked-sheets-deep-shadow-maps.csv volumetric
    $app sweep $sheets --images --technique adaptive-volumetric-shadow-maps --param nodes=2,4,8,16,32 \
      --threads 2 --runs 3 --out $v/nodes --plot-y rms > /dev/null
    python3 $table $v/nodes/stacked-sheets-adaptive-volumetric-shadow-maps.csv volumetric
    cp $v/slices/stacked-sheets-opacity-shadow-maps.svg docs/images/volumetric-slices.svg
    cp $v/tolerance/stacked-sheets-deep-shadow-maps.svg docs/images/volumetric-tolerance.svg
    cp $v/nodes/stacked-sheets-adaptive-volumetric-shadow-maps.svg docs/images/volumetric-nodes.svg
    for scene in hair-over-plane stacked-sheets tinted-glass smoke-over-plane foliage-cards; do
      $app render assets/scenes/volumetric/$scene.json --technique reference -o docs/images/volumetric-$scene-reference.png \
        > /dev/null
      $app render assets/scenes/volumetric/$scene.json --technique deep-shadow-maps -o docs/images/volumetric-$scene-deep.png \
        > /dev/null
    done
    $app render $glass --technique coloured-shadow-map -o docs/images/volumetric-tinted-glass-coloured.png \
      --debug-buffers $v/glass > /dev/null
    cp $v/glass/coloured-shadow-map-colour.png docs/images/volumetric-coloured-colour.png
    for technique in opacity-shadow-maps deep-shadow-maps adaptive-volumetric-shadow-maps; do
      $app render $hair --technique $technique -o $v/render.png --debug-buffers $v/hair > /dev/null
    done
    cp $v/hair/deep-shadow-maps-events-per-texel.png docs/images/volumetric-events-per-texel.png
    cp $v/hair/deep-shadow-maps-vertices-per-texel.png docs/images/volumetric-vertices-per-texel.png
    cp $v/hair/adaptive-volumetric-shadow-maps-nodes-per-texel.png docs/images/volumetric-nodes-per-texel.png
    cp $v/hair/opacity-shadow-maps-slice-4.png docs/images/volumetric-slice-4.png
    cp $v/hair/opacity-shadow-maps-slice-12.png docs/images/volumetric-slice-12.png
    for technique in opacity-shadow-maps deep-shadow-maps adaptive-volumetric-shadow-maps; do
      $app render $sheets --technique $technique -o $v/render.png --debug-buffers $v/sheets > /dev/null
      cp "$(ls $v/sheets/$technique-curve-*.svg | head -1)" docs/images/volumetric-curve-$technique.svg
    done
    ;;
  screen)
    # docs/screen-and-hybrid-shadows.md: contact shadows on box-contact and the IZB/PCSS
    # hybrid on branch-over-crate, each timed at 1 and 2 threads against its reference
    # (hard: the map alone beside it; soft: PCSS and IZB alone), and the stages' buffers.
    s=$out/screen
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    $app sweep assets/scenes/hard/box-contact.json --images --technique shadow-map,contact-shadows --threads 1,2 --runs 5 --out $s
    python3 $table $s/box-contact-shadow-map+contact-shadows.csv hard+max
    $app sweep assets/scenes/soft/branch-over-crate.json --images --technique pcss,izb,izb-pcss --reference reference-soft \
      --threads 1,2 --runs 5 --out $s
    python3 $table $s/branch-over-crate-pcss+izb+izb-pcss.csv soft
    box=assets/scenes/hard/box-contact.json
    branch=assets/scenes/soft/branch-over-crate.json
    $app render $box --technique reference -o docs/images/screen-box-contact-reference.png > /dev/null
    for technique in shadow-map contact-shadows; do
      $app render $box --technique $technique -o $s/render.png \
        --error-map docs/images/screen-box-contact-$technique-error.png > /dev/null
    done
    # The march of a ground pixel at the box's foot, in the map's strip of light.
    $app render $box --technique contact-shadows -o $s/render.png --param plot-x=330 --param plot-y=290 \
      --debug-buffers $s/box > /dev/null
    cp $s/box/contact-shadows-march-mask.png docs/images/screen-march-mask.png
    cp $s/box/contact-shadows-march-path.png docs/images/screen-march-path.png
    cp $s/box/contact-shadows-march.svg docs/images/screen-march-plot.svg
    $app render $branch --technique reference-soft -o docs/images/hybrid-branch-reference-soft.png > /dev/null
    $app render $branch --technique izb-pcss -o docs/images/hybrid-branch-izb-pcss.png --debug-buffers $s/branch \
      > /dev/null
    for buffer in blend-weight izb pcss blocker-distance; do
      cp $s/branch/izb-pcss-$buffer.png docs/images/hybrid-branch-$buffer.png
    done
    ;;
  temporal)
    # Shadows over time (docs/temporal.md): temporal accumulation, confidence reprojection,
    # ray-traced shadows raw and denoised, cached maps, along a moving sphere that stops, a
    # turning sun that stops and sphere-box's camera arc, at 320 x 200, one run per frame.
    # The tables: scripts/flythrough_table.py --settle out/figures/temporal/*.json
    # out/figures/temporal/cached/*.json out/figures/temporal/accumulated/*.json.
    f=$out/temporal
    fly="$app flythrough --width 320 --height 200 --runs 1 --warmup 0 --threads 2 --out $f"
    cached="$app flythrough --width 320 --height 200 --runs 1 --warmup 0 --threads 2 --out $f/cached"
    accumulated="$app flythrough --width 320 --height 200 --runs 1 --warmup 0 --threads 2 --out $f/accumulated"
    for path in assets/scenes/flythrough/sphere-stops.json sphere-box; do
      $fly $path --technique shadow-map --param filter=poisson --param poisson-rotation=ign --param temporal=off,on > /dev/null
      $fly $path --technique pcss --param rotation=ign --param temporal=off,on > /dev/null
      $fly $path --technique confidence-reprojection --param resolution=512 > /dev/null
      $fly $path --technique ray-traced --param rays=1,4 --param denoiser=none,svgf,tiled,penumbra > /dev/null
      $accumulated $path --technique ray-traced --param rays=1 --param temporal=on > /dev/null
    done
    $cached assets/scenes/flythrough/sphere-stops.json --technique shadow-map --param cache=off,static \
      --param fit=receivers,scene > /dev/null
    $fly assets/scenes/flythrough/sun-turns-stops.json --technique shadow-map --param filter=poisson \
      --param poisson-rotation=ign --param temporal=off,on > /dev/null
    $fly assets/scenes/flythrough/sun-turns-stops.json --technique confidence-reprojection --param resolution=512 > /dev/null
    $fly assets/scenes/flythrough/sun-turns-stops.json --technique csm --param update-every=1,4 > /dev/null
    ;;
  flythrough)
    # Shadows in motion (docs/flythrough.md): per-frame time, error and flicker along the
    # built-in paths, at 640 x 400 and 2 threads; the flicker table of
    # docs/performance.md and docs/flythrough.md.
    f=$out/flythrough
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    for move in dolly slide; do
      $app flythrough assets/scenes/hard/sun.json --path assets/scenes/flythrough/sun-$move.csv --frames 48 --technique csm \
        --param snap=off,on --threads 2 --out $f/$move > /dev/null
    done
    $app flythrough assets/scenes/flythrough/avenue.json --technique csm --param snap=off,on --threads 2 --out $f > /dev/null
    $app flythrough assets/scenes/hard/sun.json --technique shadow-map,csm --threads 2 --out $f > /dev/null
    $app flythrough sphere-box --technique shadow-map --param resolution=512,1024,2048,4096 --width 640 --height 400 \
      --threads 2 --out $f > /dev/null
    soft=pcss,chs,vsm,esm,evsm,msm,multi-sample,backprojection,soft-shadow-volumes,fins,smoothies,penumbra-maps
    $app flythrough sphere-box --technique $soft --width 640 --height 400 --threads 2 --out $f > /dev/null
    python3 scripts/flythrough_table.py $f/dolly/sun-flythrough-csm.json $f/slide/sun-flythrough-csm.json \
      $f/avenue-flythrough-csm.json \
      $f/sun-flythrough-shadow-map+csm.json $f/sphere-box-flythrough-shadow-map.json \
      $f/sphere-box-flythrough-$(echo $soft | tr , +).json
    for plot in .svg -time.svg -error.svg; do
      cp $f/avenue-flythrough-csm$plot docs/images/flythrough-avenue-csm$plot
      cp $f/sphere-box-flythrough-$(echo $soft | tr , +)$plot docs/images/flythrough-sphere-box-soft$plot
    done
    ;;
  lights)
    # docs/many-lights.md: a frame of three lights, each light's time; then its point light
    # alone through six cube faces at four positions, the faces no visible receiver lies in
    # culled (cube-faces=visible) and drawn (all).
    scene=assets/scenes/many-lights/three-lights.json
    l=$out/lights
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    $app sweep $scene --images --technique shadow-map,izb,shadow-volume,reference --threads 2 --runs 9 --warmup 2 --out $l > /dev/null
    python3 $table $l/three-lights-shadow-map+izb+shadow-volume+reference.csv hard
    python3 -c 'import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    print(r["technique"], *("light%d %.1f ms" % (k, float(r["light%d_technique_ms" % k])) for k in range(3)))' \
      $l/three-lights-shadow-map+izb+shadow-volume+reference.csv
    $app render $scene --technique reference -o docs/images/many-lights-three-lights.png > /dev/null
    $app render $scene --technique reference --light 0 -o docs/images/many-lights-point-light.png > /dev/null
    for position in -1.2,0.9,1.4 0.5,3,3.5 0,2,12 0,0.5,-4; do
      $app sweep $scene --technique shadow-map --light 0 --light-pos $position --param cube=always \
        --param cube-faces=visible,all --threads 2 --runs 15 --warmup 3 --out $l/cube-$position > /dev/null
      python3 -c 'import csv, sys
visible, every = csv.DictReader(open(sys.argv[1]))
print(sys.argv[2], visible["maps_count"], "faces, %.1f ms culled, %.1f ms all six," % (float(visible["median_ms"]), float(every["median_ms"])),
      "same V" if visible["rms"] == every["rms"] else "V DIFFERS")' $l/cube-$position/three-lights-shadow-map.csv $position
    done
    ;;
  suite)
    # Real models (docs/performance.md, "Real models"): the main techniques on the suite's
    # scenes of models no one here made, read through the glTF path from their Debian
    # packages (scripts/suite_models.sh installs them and converts the house). Hard
    # techniques on every scene (csm where a light is a sun), soft ones under the
    # engine's disk light; medians of 3 at 2 threads. Then each scene's reference and shadow
    # map as the docs show them.
    scripts/suite_models.sh
    s=$out/suite
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    for scene in engine house grove dungeon; do
      hard=reference,shadow-map,csm,izb,shadow-volume
      # The engine's light is a disk, which csm shadows as shadow-map does: no csm row.
      [ $scene = engine ] && hard=reference,shadow-map,izb,shadow-volume
      $app sweep assets/scenes/suite/$scene.json --images --technique $hard --threads 2 --runs 3 --out $s > /dev/null
      echo "$scene:"
      python3 $table $s/$scene-$(echo $hard | tr , +).csv hard
      $app render assets/scenes/suite/$scene.json --technique reference --width 640 --height 400 -o docs/images/suite-$scene-reference.png > /dev/null
      $app render assets/scenes/suite/$scene.json --technique shadow-map --width 640 --height 400 -o $s/$scene-shadow-map.png > /dev/null
    done
    # The grove's cut-outs as the shadow volumes cast them: whole cards or none (here none,
    # by the coverage rule), so the leaves' shadow is false light (docs/cut-outs.md).
    $app render assets/scenes/suite/grove.json --technique shadow-volume --width 640 --height 400 -o $s/render.png \
      --error-map docs/images/suite-grove-shadow-volume-error.png > /dev/null
    soft=reference-soft,pcss,backprojection,soft-shadow-volumes,fins
    $app sweep assets/scenes/suite/engine.json --images --technique $soft --reference reference-soft --threads 2 --runs 3 \
      --out $s --plot-y rms > /dev/null
    python3 $table $s/engine-$(echo $soft | tr , +).csv soft
    ;;
  standard)
    # docs/performance.md, "Every technique to one standard": docs/data/technique_stages.json
    # joined with every technique's stage times on sphere-box and the bunny at 2 threads: the
    # medians of five frames after a warm-up; reference-soft's one frame (a minute or more)
    # apart. Under out/standard, not $out: these are no sweeps for the report. The environment
    # techniques need scenes of their own and are not here.
    std=out/standard
    all="none,reference,shadow-map,csm,izb,contact-shadows,shadow-volume,planar,projected-texture,pcss,chs,izb-pcss"
    all="$all,vsm,esm,evsm,msm,multi-sample,backprojection,fins,smoothies,penumbra-maps,soft-shadow-volumes"
    all="$all,coloured-shadow-map,opacity-shadow-maps,deep-shadow-maps,adaptive-volumetric-shadow-maps"
    columns=""
    for scene in sphere-box bunny; do
      $app sweep $scene --technique $all --reference reference --threads 2 --runs 5 --out $std/$scene > /dev/null
      $app sweep $scene --technique reference-soft --reference reference --threads 2 --runs 1 --warmup 0 \
        --out $std/$scene-soft > /dev/null
      columns="$columns $scene=$(ls $std/$scene/*.json $std/$scene-soft/*.json | paste -sd, -)"
    done
    # A sun's techniques under a sun (hard/sun.json at its 640 x 400): the virtual map draws
    # only for directional lights, and csm's cascades run.
    $app sweep assets/scenes/hard/sun.json --technique shadow-map,csm,virtual-shadow-map --reference reference --width 640 --height 400 \
      --threads 2 --runs 5 --out $std/sun > /dev/null
    columns="$columns sun=$(ls $std/sun/*.json | paste -sd, -)"
    python3 scripts/technique_standard.py $columns
    ;;
  virtual)
    # docs/virtual-shadow-maps.md, "At equal memory": the virtual map beside shadow-map and csm
    # (near/far bounds from the camera, and from the samples: SDSM) at the depth memory each
    # reserves: 4, 16, 64 and 256 MiB (one map of 1024, 2048, 4096 texels; four cascades of
    # 1024, 2048, 4096; a pool of 64, 256, 1024 pages of 128^2 texels, of which it holds only
    # the pages in use; on still views also at levels one finer than the pixels' footprint,
    # lod-bias=-1). Still views: speed against error (the virtual map's pages kept from
    # the warm-up frame), and its first frame alone (--warmup 0: every page drawn); the suite's
    # scenes under a sun (the engine's light is a disk: left out; the dungeon's sun alone).
    # Then four paths, per-frame ms, error, pages drawn and cache hits; the buffers of the sun
    # case. Errors and pages are exact, times want a quiet machine. About 12 minutes on 2 cores.
    v=$out/virtual
    maps=shadow-map,csm,virtual-shadow-map
    stem=reference+shadow-map+csm+virtual-shadow-map
    grid="--param resolution=1024,2048,4096 --param bounds=camera,samples --param pool-pages=64,256,1024"
    # The virtual map's levels one finer than the pixels' footprint too (four times the pages).
    finer="--param lod-bias=0,-1"
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    scripts/suite_models.sh > /dev/null
    # sphere-box's light is a disk: the virtual map reads its six faces' mip chains.
    for scene in sphere-box assets/scenes/hard/sun.json assets/scenes/virtual/small-casters.json \
                 assets/scenes/suite/house.json assets/scenes/suite/grove.json assets/scenes/suite/dungeon.json; do
      name=$(basename $scene .json)
      light=""
      [ $name = dungeon ] && light="--light 0"
      $app sweep $scene $light --technique reference,$maps $grid $finer --threads 2 --runs 3 --warmup 1 --out $v > /dev/null
      $app sweep $scene $light --technique virtual-shadow-map --param pool-pages=64,256,1024 $finer --threads 2 --runs 3 \
        --warmup 0 --out $v/first > /dev/null
      echo "$name:"
      python3 scripts/vsm_table.py sweep $v/$name-$stem.csv $v/first/$name-virtual-shadow-map.csv
      cp $v/$name-$stem.svg docs/images/virtual-$name.svg
    done
    # Soft lookups against the soft reference, on a sun with an angular size (soft/sun-disk,
    # 2.5 degrees): the virtual map hard and with PCF beside shadow-map's same filters, then
    # with shadow-map ray tracing (smrt-rays; 0 rays = the hard lookup).
    soft=assets/scenes/soft/sun-disk.json
    $app sweep $soft --technique virtual-shadow-map,shadow-map --param filter=nearest,bilinear,poisson \
      --reference reference-soft --threads 2 --runs 3 --warmup 1 --out $v/soft --plot-y rms > /dev/null
    $app sweep $soft --technique virtual-shadow-map --param smrt-rays=4,16 --reference reference-soft \
      --threads 2 --runs 3 --warmup 1 --out $v/soft/rays --plot-y rms > /dev/null
    echo "sun-disk, soft:"
    python3 $table $v/soft/sun-disk-virtual-shadow-map+shadow-map.csv soft
    python3 $table $v/soft/rays/sun-disk-virtual-shadow-map.csv soft
    cp $v/soft/sun-disk-virtual-shadow-map+shadow-map.svg docs/images/virtual-soft-sun-disk.svg
    # The same towards local area lights (soft/'s rectangle and disks, each at its own size):
    # the virtual map hard and with 4 and 16 rays beside shadow-map and PCSS, with the
    # speed-against-error plot; then both maps' 3 x 3 PCF (the rays refuse a filter beside
    # them). docs/virtual-shadow-maps.md, "Towards a local light's area".
    # ball-near-disk is where the rays lose: an occluder 2 cm from a wide light.
    for scene in assets/scenes/soft/square-over-plane.json assets/scenes/soft/two-heights.json \
                 assets/scenes/soft/large-light.json assets/scenes/soft/branch-over-crate.json \
                 assets/scenes/virtual/ball-near-disk.json; do
      name=$(basename $scene .json)
      # PCSS's one light view refuses receivers beside the light (the ball's).
      techniques=virtual-shadow-map,shadow-map,pcss
      [ $name = ball-near-disk ] && techniques=virtual-shadow-map,shadow-map
      $app sweep $scene --technique $techniques --param smrt-rays=0,4,16 \
        --reference reference-soft --threads 2 --runs 3 --warmup 1 --out $v/local-soft --plot-y rms > /dev/null
      $app sweep $scene --technique virtual-shadow-map,shadow-map --param filter=grid \
        --reference reference-soft --threads 2 --runs 3 --warmup 1 --out $v/local-soft/pcf > /dev/null
      echo "$name, soft:"
      python3 $table $v/local-soft/$name-$(echo $techniques | tr , +).csv soft
      python3 $table $v/local-soft/pcf/$name-virtual-shadow-map+shadow-map.csv soft
      cp $v/local-soft/$name-$(echo $techniques | tr , +).svg docs/images/virtual-soft-$name.svg
    done
    fly="--technique $maps $grid --threads 2 --runs 3 --warmup 1"
    $app flythrough assets/scenes/flythrough/avenue.json $fly --out $v/fly > /dev/null
    $app flythrough assets/scenes/flythrough/sliding-sphere-still-sun.json $fly --out $v/fly > /dev/null
    $app flythrough assets/scenes/flythrough/sliding-sphere-sun.json $fly --out $v/fly > /dev/null
    $app flythrough assets/scenes/hard/sun.json --path assets/scenes/flythrough/sun-dolly.csv --frames 48 $fly \
      --out $v/fly/dolly > /dev/null
    python3 scripts/vsm_table.py flythrough $v/fly/dolly/sun-flythrough-$(echo $maps | tr , +).json \
      $v/fly/*-flythrough-$(echo $maps | tr , +).json
    for path in avenue sliding-sphere-still-sun sliding-sphere-sun; do
      for plot in -time -error -pages -hits; do
        cp $v/fly/$path-flythrough-$(echo $maps | tr , +)$plot.svg docs/images/virtual-flythrough-$path$plot.svg
      done
    done
    $app render assets/scenes/hard/sun.json --technique virtual-shadow-map --width 640 --height 400 -o $v/sun.png \
      --debug-buffers $v/buffers > /dev/null
    for buffer in level texels-per-pixel page-table pool; do
      cp $v/buffers/virtual-shadow-map-$buffer.png docs/images/virtual-buffer-$buffer.png
    done
    ;;
  scale)
    # docs/scale.md's settings per node per hour and each set's reference, built-in scenes
    # on 2 threads (8 minutes on the quiet 2-core VM). Into out/scale: timings for a table, not the report's.
    python3 scripts/scale_table.py --app $app --threads 2 --out out/scale
    ;;
  report)
    # Every sweep's JSON under out/figures (the files with a grid of reference fingerprints;
    # bench and composite JSON are not sweeps) as one site: a page per scene and per setting.
    sweeps=$(find $out -name '*.json' | sort | xargs grep -l '"reference_fingerprints"')
    $app report $sweeps --out out/report
    ;;
  *) echo "figures.sh: unknown part '$part' (hard, cases, bias, models, soft, torus, views, scaling, bench," \
       "environment, lod, differential, screen, volumetric, cutouts, flythrough, lights, suite, standard, virtual, scale, report)" >&2; exit 2 ;;
  esac
done
