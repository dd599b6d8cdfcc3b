#!/usr/bin/env python3
"""docs/scale.md's table: how many settings one node sweeps per hour on each built-in scene,
and what every shard repeats (loading the scene, rendering the references).

For each scene and each set of techniques (hard ones, soft ones), two sweeps at --runs 5
(warm-up 1) on --threads THREADS, timed from outside (wall time: the process's start, the
scene's loading and the files' writing included), alternated --repeat times so that a
change of the machine's load falls on both: the whole grid of S settings, W_S, and the
technique `none` alone, W_0: what a shard does besides its settings (start, load, the
hard reference, and a row that renders nothing). Their medians are printed, and a setting's
cost is the median of the rounds' differences over S. Both are scored against `reference`
(--reference), one ray a pixel, so that the soft reference's half minute, and its noise on
a busy machine, stays out of the difference: a setting costs (W_S - W_0) / S seconds on
average, and a node does 3600 over that settings per hour. Last, the set's own reference
timed as a technique's row (--runs 1, warm-up 0, once): what every shard of a sweep of that
set renders besides.

usage: scale_table.py [--app build/app/shadowlab] [--threads 2] [--repeat 3] [--out out/scale]   (scripts/figures.sh scale)
"""
import argparse
import json
import statistics
import subprocess
import time
from pathlib import Path

# (scene, set, its reference, techniques, axes): the shadow map's resolutions and the exact
# hard techniques; the filtered and the accurate soft techniques.
SWEEPS = [
    (scene, kind, reference, techniques, axes)
    for scene in ("sphere-box", "bunny", "throughput")
    for kind, reference, techniques, axes in (
        ("hard", "reference", "shadow-map,izb,shadow-volume", ["resolution=1024,2048,4096"]),
        ("soft", "reference-soft", "pcss,vsm,fins,backprojection", ["resolution=1024,2048"]),
    )
]


def sweep_command(args, scene, techniques, axes, out, runs=5, warmup=1):
    command = [args.app, "sweep", scene, "--technique", techniques, "--reference", "reference",
               "--threads", str(args.threads), "--runs", str(runs), "--warmup", str(warmup),
               "--out", str(out)]
    for axis in axes:
        command += ["--param", axis]
    return command


def wall_time(command):
    start = time.monotonic()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


def sweep_json(out, scene, techniques):
    return json.loads((out / f"{scene}-{techniques.replace(',', '+')}.json").read_text())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--app", default="build/app/shadowlab")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--out", type=Path, default=Path("out/scale"))
    args = parser.parse_args()
    print("| scene | set | settings | whole sweep, s | `none` alone, s | a setting, s "
          "| settings per hour | the set's reference, s |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for scene, kind, reference, techniques, axes in SWEEPS:
        whole_command = sweep_command(args, scene, techniques, axes, args.out / "whole")
        none_command = sweep_command(args, scene, "none", [], args.out / "none")
        wholes, nones = [], []
        for _ in range(args.repeat):   # alternated: A B A B ...
            wholes.append(wall_time(whole_command))
            nones.append(wall_time(none_command))
        settings = sweep_json(args.out / "whole", scene, techniques)["grid"]["settings"]
        subprocess.run(sweep_command(args, scene, reference, [], args.out / "reference", runs=1, warmup=0),
                       check=True, stdout=subprocess.DEVNULL)
        reference_s = sweep_json(args.out / "reference", scene, reference)["rows"][0]["median_ms"] / 1000
        setting = statistics.median(w - n for w, n in zip(wholes, nones)) / settings
        print(f"| {scene} | {kind} ({techniques.replace(',', ', ')}) | {settings} | {statistics.median(wholes):.1f} "
              f"| {statistics.median(nones):.1f} | {setting:.2f} | {3600 / setting:.0f} | {reference_s:.2f} |", flush=True)


if __name__ == "__main__":
    main()
