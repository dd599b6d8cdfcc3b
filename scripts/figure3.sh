#!/usr/bin/env bash
# DeCoro and Rusinkiewicz 2008, Figure 3, measured: the bunny (Phong 40) and the triceratops
# (Phong 500) under the interior and forest maps, env-additive and env-subtractive at
# N in {15, 20, 30, 40, 100} lights sampled by structured importance sampling (the paper's
# sampler; point lights, the paper's shading) and (subtractive) sampling detail in {1, 1/4,
# 1/16, 1/1024}, 1280 x 800: median ms at 1 and 2 threads and RMS of the luminance against the
# exact reference (reference-env, 1024 samples per strategy), then RMS against the paper's
# own reference (reference-env-lights: 1000 lights, exact visibility) from a second,
# untimed pass. Prints the markdown table of docs/subtractive-shadows.md.
# Usage: scripts/figure3.sh [OUT_DIR] [SCENE ...]   (all four scenes: about two hours on 2
# cores, most of it the exact references; THREADS=2 RUNS=1 for a quicker pass)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${1:-out/figure3}
app=build/app/shadowlab
grid=(--technique env-additive,env-subtractive --param lights=15,20,30,40,100 --param sampler=structured
      --param sampling-detail=1,1/4,1/16,1/1024)
scenes=("${@:2}")
[ ${#scenes[@]} -gt 0 ] || scenes=(bunny-interior bunny-forest triceratops-interior triceratops-forest)
for scene in "${scenes[@]}"; do
    $app sweep scenes/environment/$scene.json "${grid[@]}" --threads "${THREADS:-1,2}" --runs "${RUNS:-3}" --warmup 0 --plot-y rms \
        --out "$out/exact" > /dev/null
    $app sweep scenes/environment/$scene.json "${grid[@]}" --threads 2 --runs 1 --warmup 0 --plot-y rms \
        --reference reference-env-lights --out "$out/lights" > /dev/null
done
python3 scripts/figure3_table.py "$out/exact" "$out/lights"
