#!/usr/bin/env python3
"""Prints the flicker table of docs/performance.md and docs/flythrough.md (Markdown) from `shadowlab flythrough` JSON files:
one row per series with its path's median time, mean RMS and misclassified share, and
its flicker mean and 99th percentile (docs/conventions.md, "Flicker"). With --settle (the
tables of docs/temporal.md), also the mean FLIP and, on a path that ends still, the frames
to settle and the ghosting (docs/flythrough.md).
usage: scripts/flythrough_table.py [--settle] FLYTHROUGH.json [...]"""
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
               p["flicker_mean"], p["flicker_p99"], p.get("mean_flip"), settle_text(p),
               p.get("ghosting_rms_frames"))


def settle_text(p):
    """Frames to settle; "13+" where still converging at the path's end; None off a path that ends still."""
    frames = p.get("settle_frames")
    if frames is None:
        return None
    return str(frames) + ("" if p.get("settled") else "+")


def figure(x, form):
    return "-" if x is None else format(x, form)


def main(args):
    settle = "--settle" in args
    files = [a for a in args if a != "--settle"]
    if not files:
        sys.exit(__doc__)
    more = " mean FLIP | settle frames | ghosting |" if settle else ""
    print("| path | frames | technique | median ms | mean RMS | misclassified % | flicker mean | flicker p99 |" + more)
    print("| --- " * (11 if settle else 8) + "|")
    for path in files:
        for where, frames, label, ms, rms, miscl, mean, p99, flip, frames_to_settle, ghosting in rows(path):
            line = f"| {where} | {frames} | {label} | {ms:.3g} | {rms:.4f} | {miscl:.3f} | {mean:.2g} | {p99:.3g} |"
            if settle:
                line += f" {figure(flip, '.4f')} | {frames_to_settle or '-'} | {figure(ghosting, '.3f')} |"
            print(line)


if __name__ == "__main__":
    main(sys.argv[1:])
