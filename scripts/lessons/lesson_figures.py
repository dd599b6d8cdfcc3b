#!/usr/bin/env python3
"""Prints the figures a lesson page quotes, as a Markdown table, from `render --json` or
`compare --json` files.

usage: lesson_figures.py [--stats NAME,NAME...] LABEL=FILE.json ...

One row per file, in the order given: the label (the setting the row shows), then the error
figures against the technique's exact reference over the hit pixels (conventions.md,
"Figures and errors"): misclassified, false shadow and false light in % of the pixels and
RMS when every row is a hard (binary) V; else RMS and mean |error| of V and the umbra-lit
and lit-shadowed shares. --stats adds columns of the technique's own stats (architecture.md,
"Stat names"). The lesson scripts (scripts/lessons/NAME.sh) call it; it reads nothing else.
"""
import json
import sys

HARD = [("misclassified %", "misclassified_percent"), ("false shadow %", "false_shadow_percent"),
        ("false light %", "false_light_percent"), ("RMS", "rms")]
SOFT = [("RMS", "rms"), ("mean abs", "mean_abs"), ("umbra lit %", "umbra_lit_percent"),
        ("lit shadowed %", "lit_shadowed_percent")]


def number(value):
    """Four significant figures; integers (counts) whole."""
    if float(value).is_integer() and abs(value) >= 1:
        return str(int(value))
    return f"{value:.4g}"


def errorsOf(figures):
    """render --json nests the error figures under "errors"; compare --json is them alone."""
    return figures.get("errors", figures)


def main(argv):
    stats = []
    if len(argv) >= 2 and argv[0] == "--stats":
        stats = argv[1].split(",")
        argv = argv[2:]
    if not argv or any("=" not in a for a in argv):
        sys.exit("lesson_figures.py: usage: lesson_figures.py [--stats A,B] LABEL=FILE.json ...")
    loaded = []
    for arg in argv:
        label, path = arg.rsplit("=", 1)   # labels may hold "=", paths do not
        try:
            with open(path) as f:
                loaded.append((label, path, json.load(f)))
        except (OSError, ValueError) as error:
            sys.exit(f"lesson_figures.py: {path}: {error}")
    # Hard figures only when every row is binary; a filtered (fractional) V beside a hard
    # one is compared on the soft columns, which binary rows have too.
    columns = HARD if all(errorsOf(figures)["binary"] for _, _, figures in loaded) else SOFT
    print("| setting | " + " | ".join([name for name, _ in columns] + stats) + " |")
    print("| --- " * (len(columns) + len(stats) + 1) + "|")
    for label, path, figures in loaded:
        missing = [s for s in stats if s not in figures.get("stats", {})]
        if missing:
            sys.exit(f"lesson_figures.py: {path} has no stat {', '.join(missing)}")
        values = [number(errorsOf(figures)[key]) for _, key in columns]
        values += [number(figures["stats"][s]) for s in stats]
        print(f"| {label} | " + " | ".join(values) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
