#!/usr/bin/env bash
# One table of shadowlab against its peers on this machine (docs/peers.md): Mesa's llvmpipe
# (build/bench/peers/shadowlab_peers) and Embree (shadowlab bench's reference rays), all
# measured in this one run at the same thread count.
#
#   scripts/bench_peers.sh [--scenes a,b] [--threads N] [--runs N] [--json FILE]
#                          [--peers PATH] [--shadowlab PATH]
#
# Runs, in order: shadowlab_peers, `shadowlab bench`, and per scene `shadowlab sweep
# --technique shadow-map,shadow-volume,izb --param filter=nearest,grid --param mode=zfail`;
# scripts/peers_table.py merges their JSON into the table (and --json).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scenes="sphere-box,throughput"
threads=2
runs=15
json=""
peers="$root/build/bench/peers/shadowlab_peers"
shadowlab="$root/build/app/shadowlab"
while [ $# -gt 0 ]; do
    case "$1" in
        --scenes) scenes="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --runs) runs="$2"; shift 2 ;;
        --json) json="$2"; shift 2 ;;
        --peers) peers="$2"; shift 2 ;;
        --shadowlab) shadowlab="$2"; shift 2 ;;
        -h|--help) sed -n 2,12p "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "bench_peers.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
    esac
done
for program in "$peers" "$shadowlab"; do
    if [ ! -x "$program" ]; then
        echo "bench_peers.sh: $program not found; build first (the peer needs libegl-dev libgl-dev libgl1-mesa-dri)" >&2
        exit 1
    fi
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "llvmpipe peer ($threads threads) ..." >&2
"$peers" --scenes "$scenes" --threads "$threads" --runs "$runs" --json "$work/peers.json" > /dev/null
echo "shadowlab bench ($threads threads) ..." >&2
"$shadowlab" bench --scenes "$scenes" --threads "$threads" --runs "$runs" --parts passes,rays --json "$work/bench.json" > /dev/null
IFS=',' read -r -a scene_list <<< "$scenes"
for scene in "${scene_list[@]}"; do
    echo "shadowlab sweep $scene ($threads threads) ..." >&2
    mkdir -p "$work/sweep-$scene"
    "$shadowlab" sweep "$scene" --technique shadow-map,shadow-volume,izb --param filter=nearest,grid --param mode=zfail \
        --threads "$threads" --runs "$runs" --out "$work/sweep-$scene" > /dev/null
done
args=(--peers "$work/peers.json" --bench "$work/bench.json" --threads "$threads")
for scene in "${scene_list[@]}"; do
    args+=(--sweep "$(ls "$work/sweep-$scene"/*.json)")
done
[ -z "$json" ] || args+=(--json "$json")
python3 "$root/scripts/peers_table.py" "${args[@]}"
