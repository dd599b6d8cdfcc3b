#!/usr/bin/env python3
"""A/B of two shadowlab builds on one scene: runs `shadowlab sweep` with build A, then build
B, alternately, ROUNDS times each in one session (the VM's speed drifts over minutes, so
alternating spreads the drift over both), and prints a markdown table per technique: the
median over the rounds of each build's median technique ms, B / A, and both builds' RMS
against the same reference (equal RMS: the same error). Extra arguments go to both sweeps.

usage: scripts/ab_sweep.py A_SHADOWLAB B_SHADOWLAB SCENE TECHNIQUES [--rounds N] [--out DIR]
                           [-- sweep arguments ...]
example: scripts/ab_sweep.py old/build/app/shadowlab build/app/shadowlab sphere-box pcss,fins \\
             --rounds 2 -- --threads 2 --runs 5 --reference reference-soft"""
import argparse
import json
import pathlib
import shutil
import statistics
import subprocess
import sys


def settingsName(settings):
    return " ".join(f"{k}={v}" for k, v in sorted(settings.items())) or "defaults"


def sweep(binary, scene, techniques, out, extra):
    shutil.rmtree(out, ignore_errors=True)   # one result per directory: never an earlier run's
    out.mkdir(parents=True)
    subprocess.run([binary, "sweep", scene, "--technique", techniques, "--out", str(out), *extra], check=True,
                   stdout=subprocess.DEVNULL)
    (result,) = out.glob("*.json")
    rows = json.loads(result.read_text())["rows"]
    return {(r["technique"], settingsName(r["settings"]), r["threads"]): r for r in rows}


def parse_ab(parser, default_out):
    """The two builds, --rounds and --out added to `parser`, parsed from the arguments before
    '--'; the ones after it are returned apart, for the measured command."""
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--out", default=default_out)
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    return parser.parse_args(argv[:split]), argv[split + 1:]


def alternate(args, measure):
    """{'a': [...], 'b': [...]}: measure(binary, side, round) for build A, then B, args.rounds
    times, so the machine's drift falls on both."""
    runs = {"a": [], "b": []}
    for round_ in range(args.rounds):
        for side in ("a", "b"):
            runs[side].append(measure(getattr(args, side), side, round_))
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("scene")
    parser.add_argument("techniques")
    args, extra = parse_ab(parser, "out/ab")
    runs = alternate(args, lambda binary, side, round_: sweep(
        binary, args.scene, args.techniques, pathlib.Path(args.out) / f"{side}{round_}", extra))
    print("| technique | settings | threads | A ms | B ms | B / A | A RMS | B RMS |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for key in runs["a"][0]:
        if key not in runs["b"][0]:
            continue
        a = statistics.median(r[key]["median_ms"] for r in runs["a"])
        b = statistics.median(r[key]["median_ms"] for r in runs["b"])
        # With --reference none the sweep scores nothing: no RMS to show.
        rms = [runs[side][0][key].get("errors", {}).get("rms") for side in ("a", "b")]
        rms = ["-" if e is None else f"{e:.4f}" for e in rms]
        technique, settings, threads = key
        print(f"| `{technique}` | {settings} | {threads} | {a:.1f} | {b:.1f} | {b / a:.2f} | {rms[0]} | {rms[1]} |")


if __name__ == "__main__":
    sys.exit(main())
