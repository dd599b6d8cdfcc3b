#!/usr/bin/env python3
"""Prints the flicker table of docs/performance.md and docs/flythrough.md (Markdown) from `shadowlab flythrough` JSON files:
one row per series with its path's median time, mean RMS and misclassified share, and
its flicker mean and 99th percentile (docs/conventions.md, "Flicker").
usage: scripts/flythrough_table.py FLYTHROUGH.json [...]"""
import json
import sys


def rows(path):
    with open(path) as f:
        run = json.load(f)
    where = run["scene"] if run["path"] == "scene" else run["scene"] + " (" + run["path"].split("/")[-1] + ")"
    for s in run["series"]:
        label = " ".join([s["technique"]] + [k + "=" + v for k, v in s["settings"].items()])
        p = s["path_figures"]
        yield (where, run["frames"], label, p["median_ms"], p["mean_rms"], p["mean_misclassified_percent"],
               p["flicker_mean"], p["flicker_p99"])


def main(files):
    if not files:
        sys.exit(__doc__)
    print("| path | frames | technique | median ms | mean RMS | misclassified % | flicker mean | flicker p99 |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for path in files:
        for where, frames, label, ms, rms, miscl, mean, p99 in rows(path):
            print(f"| {where} | {frames} | {label} | {ms:.3g} | {rms:.4f} | {miscl:.3f} | {mean:.2g} | {p99:.3g} |")


if __name__ == "__main__":
    main(sys.argv[1:])
