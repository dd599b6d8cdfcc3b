#!/usr/bin/env bash
# DeCoro and Rusinkiewicz 2008, Figure 3, measured: the bunny (Phong 40) and the triceratops
# (Phong 500) under the interior and forest maps, env-additive and env-subtractive at
# N in {15, 20, 30, 40, 100} lights sampled by structured importance sampling (the paper's
# sampler; point lights, the paper's shading) and (subtractive) sampling detail in {1, 1/4,
# 1/16, 1/1024}, 1280 x 800. Two passes: the errors against the exact reference
# (reference-env, 1024 samples per strategy; the RMS of the luminance and of the displayed
# luminance), one untimed frame each at 2 threads; then the times, median ms at 1 and 2
# threads, in a pass scored against the paper's own reference (reference-env-lights: 1000
# lights, exact visibility), whose RMS it also gives. Errors are the same bytes on any
# machine and thread count (docs/determinism.md); only the timed pass needs a quiet
# machine. Prints the markdown table of docs/subtractive-shadows.md.
# Usage: scripts/figure3.sh [OUT_DIR] [SCENE ...]   (all four scenes: about two hours on 2
# cores, most of it the exact references; PASSES=errors or PASSES=times for one pass
# alone; THREADS=2 RUNS=1 for a quicker timed pass)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${1:-out/figure3}
app=build/app/shadowlab
grid=(--technique env-additive,env-subtractive --param lights=15,20,30,40,100 --param sampler=structured
      --param sampling-detail=1,1/4,1/16,1/1024)
scenes=("${@:2}")
[ ${#scenes[@]} -gt 0 ] || scenes=(bunny-interior bunny-forest triceratops-interior triceratops-forest)
passes=" ${PASSES:-errors times} "
for scene in "${scenes[@]}"; do
    if [[ $passes == *" errors "* ]]; then
        $app sweep assets/scenes/environment/$scene.json "${grid[@]}" --threads 2 --runs 1 --warmup 0 --plot-y rms \
            --out "$out/exact" > /dev/null
    fi
    if [[ $passes == *" times "* ]]; then
        $app sweep assets/scenes/environment/$scene.json "${grid[@]}" --threads "${THREADS:-1,2}" --runs "${RUNS:-3}" \
            --warmup 1 --plot-y rms --reference reference-env-lights --out "$out/lights" > /dev/null
    fi
done
plot=triceratops-forest-env-additive+env-subtractive.svg   # docs' speed-against-error plot (one frame, 2 threads)
if [ -f "$out/exact/$plot" ]; then cp "$out/exact/$plot" docs/images/figure3-triceratops-forest.svg; fi
python3 scripts/figure3_table.py "$out/exact" "$out/lights"
