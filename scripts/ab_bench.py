#!/usr/bin/env python3
"""A/B of two shadowlab builds' `shadowlab bench`: runs build A, then build B, alternately,
ROUNDS times each in one session (the VM's speed drifts over minutes, so alternating spreads
the drift over both), and prints a markdown table of every row both builds measured (the
passes and the front-end table): the median over the rounds of each build's median ms, and
B / A. Extra arguments go to both benches.

usage: scripts/ab_bench.py A_SHADOWLAB B_SHADOWLAB [--rounds N] [--out DIR] [-- bench arguments ...]
example: scripts/ab_bench.py old/build/app/shadowlab build/app/shadowlab --rounds 2 -- \\
             --scenes sphere-box,throughput --threads 1,2 --parts passes,front-end --runs 5"""
import argparse
import json
import pathlib
import statistics
import subprocess

from ab_sweep import alternate, parse_ab


def bench(binary, out, extra):
    subprocess.run([binary, "bench", "--json", str(out), *extra], check=True, stdout=subprocess.DEVNULL)
    result = json.loads(out.read_text())
    rows = {(r["scene"], r["pass"], r["threads"]): r["median_ms"] for r in result["passes"]}
    rows.update({(r["scene"], "front end: " + r["stage"], r["threads"]): r["median_ms"] for r in result.get("front_end", [])})
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("a")
    parser.add_argument("b")
    args, extra = parse_ab(parser, "out/ab_bench")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    runs = alternate(args, lambda binary, side, round_: bench(binary, out / f"{side}{round_}.json", extra))
    print("| scene | row | threads | A ms | B ms | B / A |")
    print("| --- | --- | ---: | ---: | ---: | ---: |")
    for key in runs["a"][0]:
        if key not in runs["b"][0]:
            continue
        a = statistics.median(r[key] for r in runs["a"])
        b = statistics.median(r[key] for r in runs["b"])
        print(f"| {key[0]} | {key[1]} | {key[2]} | {a:.2f} | {b:.2f} | {b / a:.2f} |")


if __name__ == "__main__":
    main()
