#!/usr/bin/env python3
"""Sweep one parameter of a shadow technique and plot its speed against its error.

    python3 examples/python/speed_against_error.py [--scene sphere-box] [--technique shadow-map[,pcss...]]
        [--param resolution=256,512,1024,2048] [--size 640 400] [--runs 5] [--out out/python]
        [--svg]

One sweep (shadowlab.sweep, the library's `shadowlab sweep`) times every setting (the median
of --runs frames after a warm-up frame) and scores it against the exact reference. Writes
OUT/speed-against-error.csv (the command's CSV) and the plot: with matplotlib,
OUT/speed-against-error.png; without it (or with --svg), the library's own SVG plot,
OUT/speed-against-error.svg. Prints one line per setting.
"""
import argparse
import importlib.util
import os
import sys

import shadowlab


def parse_axis(text):
    """"name=v1,v2" -> {name: [v1, v2]}; the values stay text, as the command's --param."""
    name, equals, values = text.partition("=")
    if not equals or not values:
        raise argparse.ArgumentTypeError(f"--param {text}: expected NAME=V1,V2,...")
    return {name: values.split(",")}


def error_axis(results):
    """The figure the command's plot draws by default (--plot-y auto): misclassified pixels (%)
    if any row is scored against the hard reference, else the RMS (of V, or of the luminance
    of a shaded image), as (name, label)."""
    if any(row.reference == "reference" for row in results.rows):
        return "misclassified_percent", "misclassified pixels, %"
    return "rms", "RMS error"


def plot_with_matplotlib(results, path):
    import matplotlib
    matplotlib.use("Agg")   # no display needed
    import matplotlib.pyplot as plt

    figure_name, label = error_axis(results)
    figure, axes = plt.subplots(figsize=(7, 4.5))
    for technique in results.techniques:
        rows = [row for row in results.rows if row.technique == technique]
        errors = [getattr(row.errors, figure_name) for row in rows]
        axes.plot([row.median_ms for row in rows], errors, "o-", label=technique)
        for row, error in zip(rows, errors):
            axes.annotate(row.settings_label, (row.median_ms, error), fontsize=8, textcoords="offset points",
                          xytext=(4, 4))
    times = [row.median_ms for row in results.rows]
    if max(times) > 10 * min(times):   # a log axis only where the times span a decade or more
        axes.set_xscale("log")
    axes.set_xlabel("technique time, median ms")
    axes.set_ylabel(label)
    axes.set_title(f"{results.scene}: speed against error")
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="sphere-box")
    parser.add_argument("--technique", default="shadow-map", help="techniques, comma-separated")
    parser.add_argument("--param", type=parse_axis, default={"resolution": ["256", "512", "1024", "2048"]})
    parser.add_argument("--size", type=int, nargs=2, default=(640, 400), metavar=("W", "H"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=None, help="worker threads (default: all cores)")
    parser.add_argument("--out", default="out/python")
    parser.add_argument("--svg", action="store_true", help="draw the library's SVG plot even if matplotlib is there")
    args = parser.parse_args()

    results = shadowlab.sweep(args.scene, args.technique.split(","), args.param, runs=args.runs,
                              threads=args.threads, width=args.size[0], height=args.size[1])
    os.makedirs(args.out, exist_ok=True)
    stem = os.path.join(args.out, "speed-against-error")
    with open(stem + ".csv", "w") as csv:
        csv.write(results.to_csv())
    figure_name, _ = error_axis(results)
    for row in results.rows:
        print(f"{row.technique} {row.settings_label}: {row.median_ms:.3f} ms, "
              f"{figure_name} {getattr(row.errors, figure_name):.5f}")

    if not args.svg and importlib.util.find_spec("matplotlib"):
        plot_with_matplotlib(results, stem + ".png")
        print(f"wrote {stem}.csv and {stem}.png")
        return
    if not args.svg:
        print("matplotlib is not installed: writing the library's SVG plot instead", file=sys.stderr)
    with open(stem + ".svg", "w") as svg:
        svg.write(results.to_svg())
    print(f"wrote {stem}.csv and {stem}.svg")


if __name__ == "__main__":
    main()
