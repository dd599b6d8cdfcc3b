#!/usr/bin/env python3
"""Prints docs/performance.md's and docs/differential-rendering.md's tables from the composite.json
files `scripts/figures.sh differential` writes (shadowlab composite): per case and number
of passes n, the mean over the frames of the median ms per frame at 1 and 2 threads and of
the RMS against the reference; the preprocessing figures; the deepest shadow along a path.

usage: composite_table.py DIR   (DIR holds room-t2/, room-t1/, ... each with composite.json)
"""
import json
import os
import sys


def load(path):
    with open(path) as f:
        return json.load(f)


def by_passes(run):
    """{n: [row of each frame]}"""
    rows = {}
    for frame in run["frames"]:
        for row in frame["passes"]:
            rows.setdefault(row["passes"], []).append(row)
    return rows


def mean(values):
    values = list(values)
    return sum(values) / len(values) if values else float("nan")


def passes_table(name, two, one):
    print(f"\n{name}: {two['width']} x {two['height']}, {len(two['frames'])} frames, source share {two['source_share']}, "
          f"significance {two['significance']}; means over the frames")
    print("| n | clusters | ms, 1 thread | ms, 2 threads | RMS | RMS on the object | RMS elsewhere |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    rows2, rows1 = by_passes(two), by_passes(one) if one else {}
    for n, rows in rows2.items():
        label = "all" if n == 0 else str(n)
        clusters = mean(r["stats"]["clusters_count"] for r in rows)
        ms1 = f"{mean(r['median_ms'] for r in rows1[n]):.1f}" if n in rows1 else "-"
        print(f"| {label} | {clusters:.1f} | {ms1} | {mean(r['median_ms'] for r in rows):.1f} | "
              f"{mean(r['rms_radiance'] for r in rows):.5f} | {mean(r['rms_object_radiance'] for r in rows):.5f} | "
              f"{mean(r['rms_receivers_radiance'] for r in rows):.5f} |")
    untouched = mean(f["rms_background_radiance"] for f in two["frames"])
    print(f"| photograph as it is | | | | | | {untouched:.5f} |")


def preprocess_table(runs):
    print("\nPreprocessing (2 threads)")
    print("| case | sources | receiver patches | shaft nodes | shaft leaves | transfers | shafts | radiance ms | "
          "photograph ms | transfers ms | hierarchy ms | total ms |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for name, run in runs:
        p = run["preprocess"]
        print(f"| {name} | {p['source_patches_count']:.0f} | {p['receiver_patches_count']:.0f} | {p['shaft_nodes_count']:.0f} | "
              f"{p['shaft_leaves_count']:.0f} | {p['transfers_bytes'] / 1024:.0f} KiB | {p['shafts_bytes'] / 1024:.0f} KiB | "
              f"{p['radiance_ms']:.0f} | {p['background_ms']:.0f} | {p['transfers_ms']:.0f} | {p['hierarchy_ms']:.1f} | "
              f"{run['preprocess_ms']:.0f} |")


def depth_table(name, run):
    print(f"\n{name}: the deepest shadow (largest share of a pixel's light taken), per frame")
    passes = [row["passes"] for row in run["frames"][0]["passes"]]
    print("| frame | " + " | ".join("n = " + ("all" if n == 0 else str(n)) for n in passes) + " | reference |")
    print("| --- |" + " --- |" * (len(passes) + 1))
    for frame in run["frames"]:
        cells = " | ".join(f"{row['deepest_shadow_ratio']:.3f}" for row in frame["passes"])
        print(f"| {frame['frame']} | {cells} | {frame.get('reference_deepest_shadow_ratio', float('nan')):.3f} |")


def main():
    d = sys.argv[1]
    runs = {}
    for name in sorted(os.listdir(d)):
        path = os.path.join(d, name, "composite.json")
        if os.path.exists(path):
            runs[name] = load(path)
    for case in ["room", "room-share1", "outdoor", "outdoor-sig0.005"]:
        if case + "-t2" in runs:
            passes_table(case, runs[case + "-t2"], runs.get(case + "-t1"))
    preprocess_table([(n, r) for n, r in runs.items() if n.endswith("-t2")])
    if "room-lift" in runs:
        depth_table("room-lift", runs["room-lift"])
    if "room-buffers" in runs:
        for frame in runs["room-buffers"]["frames"]:
            if "reference_convergence_rms_radiance" in frame:
                print(f"\nreference convergence, frame {frame['frame']}: RMS {frame['reference_convergence_rms_radiance']:.6f} "
                      f"between strata {runs['room-buffers']['reference_strata']} and twice as many per side")


main()
