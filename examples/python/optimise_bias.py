#!/usr/bin/env python3
"""Optimise a shadow map's depth bias for the lowest error within a time budget.

    python3 examples/python/optimise_bias.py [--scene sphere-box] [--budget-ms 16]
        [--resolutions 512,1024,2048] [--bias slope-factor] [--range 0.05 50]
        [--size 640 400] [--runs 5] [--evaluations 16] [--out out/python]

Too little bias and a shadow map shadows its own surfaces (acne, false shadow); too much and
shadows come loose from their casters (peter-panning, false light): RTR 7.4.1. The error
against the exact reference is lowest in between, at a value that depends on the map's
resolution, the scene and the view. The bias costs no time; the resolution does.

1. One sweep (shadowlab.sweep) times shadow-map at each resolution (median of --runs frames);
   those over --budget-ms are dropped.
2. For each resolution left, the bias parameter is searched on a log scale, scoring frames
   with render() and score() against the reference rendered once: a coarse scan over the
   range, then a golden-section search in the bracket around the scan's best (the error is
   piecewise constant in the bias on a small image, so the scan comes first).
3. The lowest error wins (the faster on a tie). Printed, and written to
   OUT/optimise-bias.json with every resolution's default-bias error and best bias.
Exit status 2 if no resolution fits the budget.
"""
import argparse
import json
import math
import os
import sys

import shadowlab

GOLDEN = (math.sqrt(5) - 1) / 2
TECHNIQUE = "shadow-map"


def error_of(figures):
    """Misclassified pixels (%) against the hard reference: acne and leaks both count."""
    return figures.misclassified_percent


class Objective:
    """The error of one resolution's map as a function of log10(bias), each value scored once."""

    def __init__(self, prepared, reference, resolution, bias_param, threads):
        self.prepared, self.reference, self.resolution = prepared, reference, resolution
        self.bias_param, self.threads = bias_param, threads
        self.scored = {}

    def __call__(self, log_bias):
        if log_bias not in self.scored:
            params = {"resolution": self.resolution, self.bias_param: 10.0 ** log_bias}
            frame = shadowlab.render(self.prepared, TECHNIQUE, params, threads=self.threads)
            self.scored[log_bias] = error_of(shadowlab.score(self.reference, frame))
        return self.scored[log_bias]


def minimise(objective, low, high, evaluations):
    """A coarse scan of half the evaluations over [low, high], then golden-section search in
    the bracket of the scan's best. Returns (x, f(x)) of the best value seen."""
    scan = max(3, evaluations // 2)
    xs = [low + (high - low) * k / (scan - 1) for k in range(scan)]
    best = min(range(scan), key=lambda k: (objective(xs[k]), k))
    a, b = xs[max(best - 1, 0)], xs[min(best + 1, scan - 1)]
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    for _ in range(max(evaluations - scan - 1, 0)):   # the first step scores c and d, each next one more
        if objective(c) <= objective(d):
            b, d = d, c
            c = b - GOLDEN * (b - a)
        else:
            a, c = c, d
            d = a + GOLDEN * (b - a)
    x = min(objective.scored, key=lambda v: (objective.scored[v], v))
    return x, objective.scored[x]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="sphere-box")
    parser.add_argument("--budget-ms", type=float, default=16.0,
                        help="the technique's time per frame, median ms (default: a 60 Hz frame's, on this CPU)")
    parser.add_argument("--resolutions", default="512,1024,2048", help="map sizes to try, comma-separated")
    parser.add_argument("--bias", default="slope-factor",
                        help="the bias parameter (slope-factor with bias=slope-scaled, the default mode)")
    parser.add_argument("--range", type=float, nargs=2, default=(0.05, 50.0), metavar=("LOW", "HIGH"))
    parser.add_argument("--size", type=int, nargs=2, default=(640, 400), metavar=("W", "H"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=0, help="worker threads (0: all cores)")
    parser.add_argument("--evaluations", type=int, default=16, help="frames scored per resolution")
    parser.add_argument("--out", default="out/python")
    args = parser.parse_args()
    resolutions = [int(r) for r in args.resolutions.split(",")]
    threads = args.threads or None
    width, height = args.size

    timed = shadowlab.sweep(args.scene, TECHNIQUE, {"resolution": resolutions}, runs=args.runs, threads=threads,
                            width=width, height=height)
    times = {int(row.settings["resolution"]): row.median_ms for row in timed.rows}
    fitting = [r for r in resolutions if times[r] <= args.budget_ms]
    for r in resolutions:
        print(f"resolution {r}: {times[r]:.3f} ms" + ("" if r in fitting else " (over the budget)"))
    if not fitting:
        print(f"no resolution fits the budget of {args.budget_ms} ms", file=sys.stderr)
        sys.exit(2)

    scene = shadowlab.load_scene(args.scene)
    scene.apply_overrides(width=width, height=height)
    prepared = shadowlab.prepare(scene)
    reference = shadowlab.reference(prepared, shadowlab.technique(TECHNIQUE).reference, threads=args.threads)
    default_bias = float(next(p.default for p in shadowlab.technique(TECHNIQUE).params if p.name == args.bias))
    candidates = []
    for r in fitting:
        objective = Objective(prepared, reference, r, args.bias, args.threads)
        log_bias, error = minimise(objective, math.log10(args.range[0]), math.log10(args.range[1]), args.evaluations)
        default_error = error_of(shadowlab.score(reference, shadowlab.render(
            prepared, TECHNIQUE, {"resolution": r, args.bias: default_bias}, threads=args.threads)))
        candidates.append({"resolution": r, "median_ms": times[r], "default_bias": default_bias,
                           "default_error": default_error, "best_bias": 10.0 ** log_bias, "best_error": error,
                           "evaluations": len(objective.scored)})
        print(f"resolution {r}: {args.bias} {10.0 ** log_bias:.4g} misclassifies {error:.4f} % of the pixels "
              f"({default_bias:g}, the default: {default_error:.4f} %)")
    best = min(candidates, key=lambda c: (c["best_error"], c["median_ms"]))
    print(f"best within {args.budget_ms} ms: resolution {best['resolution']}, {args.bias} {best['best_bias']:.4g}: "
          f"{best['best_error']:.4f} % misclassified at {best['median_ms']:.3f} ms")

    os.makedirs(args.out, exist_ok=True)
    summary = {"scene": timed.scene, "technique": TECHNIQUE, "bias": args.bias, "budget_ms": args.budget_ms,
               "error": "misclassified_percent", "candidates": candidates, "best": best}
    with open(os.path.join(args.out, "optimise-bias.json"), "w") as out:
        json.dump(summary, out, indent=2)


if __name__ == "__main__":
    main()
