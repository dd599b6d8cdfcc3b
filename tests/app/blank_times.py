#!/usr/bin/env python3
"""The measured times of a `shadowlab sweep` output set alike, for cli_test.sh to compare a
merged sweep with an unsharded one: in a CSV, every column of a time (median_ms, min_ms and
the stats' *_ms) emptied; in a JSON, each row's median_ms set to 1 + setting + threads / 4,
min_ms to half of it and the stats' *_ms to 0, as tests/app/test_sweep_shards.cpp does, so
that `merge-sweep` of the result plots from the same numbers. Writes to stdout.

usage: blank_times.py FILE.csv|FILE.json
"""
import csv
import json
import sys


def blank_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    times = [k for k, name in enumerate(rows[0]) if name.endswith("_ms")]
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(rows[0])
    for row in rows[1:]:
        out.writerow(["" if k in times else field for k, field in enumerate(row)])


def blank_json(path):
    with open(path) as f:
        sweep = json.load(f)
    for row in sweep["rows"]:
        row["median_ms"] = 1.0 + row["setting"] + 0.25 * row["threads"]
        row["min_ms"] = row["median_ms"] / 2
        for name in row["stats"]:
            if name.endswith("_ms"):
                row["stats"][name] = 0.0
    json.dump(sweep, sys.stdout, indent=2)
    sys.stdout.write("\n")


if __name__ == "__main__":
    if len(sys.argv) != 2 or not sys.argv[1].endswith((".csv", ".json")):
        sys.exit(__doc__.strip().splitlines()[-1])
    (blank_csv if sys.argv[1].endswith(".csv") else blank_json)(sys.argv[1])
