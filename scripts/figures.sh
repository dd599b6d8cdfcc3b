#!/bin/sh
# Reproduces every speed and error figure in the README: the hard- and soft-shadow sweeps,
# the shadow map's bias-by-resolution grid and the eq. 8 scaling fit. Writes CSV, JSON and
# SVG under out/figures and prints the README's tables. Takes about an hour on 2 cores;
# run nothing else meanwhile (times are medians, but a busy machine still moves them).
# usage: scripts/figures.sh [hard|cases|bias|soft|scaling ...]   (default: all five)
set -eu
cd "$(dirname "$0")/.."
app=build/app/shadowlab
out=out/figures
table=scripts/sweep_table.py
mkdir -p "$out"
parts=${*:-hard cases bias soft scaling}

for part in $parts; do
  case $part in
  hard)
    for scene in sphere-box bunny; do
      $app sweep $scene --technique none,reference,shadow-map,izb,shadow-volume,planar \
        --threads 1,2 --runs 5 --out $out/hard
      python3 $table $out/hard/$scene-none+reference+shadow-map+izb+shadow-volume+planar.csv hard
    done
    # Cascades need a directional light: the sun over sphere-box.
    $app sweep scenes/hard/sun.json --technique shadow-map,csm --threads 1,2 --runs 5 --out $out/hard
    python3 $table $out/hard/sun-shadow-map+csm.csv hard
    ;;
  cases)
    # Misclassified % of each hard-shadow technique on every hard case, at its defaults.
    for scene in scenes/hard/*.json; do
      $app sweep $scene --technique shadow-map,izb,shadow-volume,planar --threads 2 --runs 1 --out $out/cases > /dev/null
    done
    $app sweep scenes/hard/sun.json --technique shadow-map --param warp=lispsm --threads 2 --runs 1 --out $out/cases/lispsm > /dev/null
    $app sweep scenes/hard/sun.json --technique csm --threads 2 --runs 1 --out $out/cases/csm > /dev/null
    python3 $table --matrix $out/cases/*.csv
    python3 $table $out/cases/lispsm/sun-shadow-map.csv hard
    python3 $table $out/cases/csm/sun-csm.csv hard
    ;;
  bias)
    # How acne (false shadow) and leaks (false light) move with resolution and slope bias.
    $app sweep sphere-box --technique shadow-map --param resolution=512,1024,2048,4096 \
      --param slope-factor=0,0.5,1.5,4 --threads 2 --runs 3 --out $out/bias
    python3 $table $out/bias/sphere-box-shadow-map.csv hard
    ;;
  soft)
    for scene in sphere-box bunny scenes/soft/large-light.json scenes/soft/tilted-receiver.json \
                 scenes/soft/two-boxes.json scenes/soft/sharp-corner.json scenes/soft/torus-over-plane.json; do
      $app sweep $scene --technique none,reference,pcss,vsm,esm,evsm,msm,multi-sample,fins,smoothies,penumbra-maps \
        --reference reference-soft --threads 1,2 --runs 5 --out $out/soft --plot-y rms
      name=$(basename $scene .json)
      python3 $table $out/soft/$name-none+reference+pcss+vsm+esm+evsm+msm+multi-sample+fins+smoothies+penumbra-maps.csv soft
    done
    ;;
  scaling)
    $app scaling scenes/scaling/*.json --technique fins --threads 1 --runs 5 --out $out/scaling
    ;;
  *) echo "figures.sh: unknown part '$part' (hard, cases, bias, soft, scaling)" >&2; exit 2 ;;
  esac
done
