#!/usr/bin/env python3
"""Turns the CSV rows of `shadowlab sweep` into docs/performance.md's markdown table: one row per
technique and settings, the median ms at each thread count side by side, and the error
figures (the same at every thread count; the first row's are shown).

usage: scripts/sweep_table.py SWEEP.csv [hard|hard+max|soft|radiance|volumetric]
       scripts/sweep_table.py --matrix SWEEP.csv ...   (one row per scene: misclassified %
                                                       of each technique)
       scripts/sweep_table.py --grid ROW COLUMN SWEEP.csv  (false shadow / false light % of
                                                       a two-parameter sweep, ROW by COLUMN)"""
import csv
import sys

HARD = [("misclassified %", "misclassified_percent", 3), ("false shadow %", "false_shadow_percent", 3),
        ("false light %", "false_light_percent", 3), ("RMS", "rms", 4)]
SOFT = [("RMS", "rms", 4), ("max", "max_abs", 2), ("umbra lit %", "umbra_lit_percent", 3),
        ("umbra lit 0.02 %", "full_umbra_lit_percent", 3), ("umbra over %", "umbra_over_percent", 3),
        ("lit shadowed %", "lit_shadowed_percent", 3)]
RADIANCE = [("RMS", "rms", 4), ("RMS displayed", "rms_display", 4)]
# Casters that are not opaque: V is a transmittance, so RMS and max, and the bytes a
# volumetric map keeps per texel (empty for the others).
VOLUMETRIC = [("RMS", "rms", 4), ("max", "max_abs", 2), ("bytes per texel", "storage_per_texel_bytes", 1)]
KINDS = {"hard": HARD, "hard+max": HARD + [("max", "max_abs", 2)], "soft": SOFT, "radiance": RADIANCE,
         "volumetric": VOLUMETRIC}
# A caster level of detail's triangles, where the sweep varied it.
CASTERS = ("caster triangles", "caster_lod_triangles", 0)


def main(path, kind):
    rows = list(csv.DictReader(open(path)))
    threads = sorted({int(r["threads"]) for r in rows})
    keyed = {}
    for r in rows:
        keyed.setdefault((r["technique"], r["settings"]), {})[int(r["threads"])] = r
    columns = list(KINDS[kind])
    if any("caster-lod=" in r["settings"] for r in rows):
        columns.insert(0, CASTERS)
    show_settings = any(s != "defaults" for _, s in keyed)
    head = ["technique"] + (["settings"] if show_settings else []) + [f"ms, {t} thr." for t in threads]
    head += [c[0] for c in columns]
    print("| " + " | ".join(head) + " |")
    print("| --- " * (1 + show_settings) + "| ---: " * (len(head) - 1 - show_settings) + "|")
    for (technique, settings), by_threads in keyed.items():
        first = by_threads[min(by_threads)]
        cells = [technique] + ([settings] if show_settings else [])
        cells += [f"{float(by_threads[t]['median_ms']):.1f}" if t in by_threads else "" for t in threads]
        # A figure a technique does not report (a map's bytes per texel) is left empty.
        cells += [f"{float(first[key]):.{digits}f}" if first.get(key) else "" for _, key, digits in columns]
        print("| " + " | ".join(cells) + " |")


def matrix(paths):
    table, techniques = {}, []
    for path in paths:
        scene = path.rsplit("/", 1)[-1].split("-shadow-map")[0]
        for r in csv.DictReader(open(path)):
            technique = r["technique"] + ("" if r["settings"] == "defaults" else " " + r["settings"])
            if technique not in techniques:
                techniques.append(technique)
            table.setdefault(scene, {})[technique] = float(r["misclassified_percent"])
    print("| scene | " + " | ".join(techniques) + " |")
    print("| --- " + "| ---: " * len(techniques) + "|")
    for scene, row in table.items():
        print(f"| {scene} | " + " | ".join(f"{row[t]:.3f}" if t in row else "" for t in techniques) + " |")


def grid(row, column, path):
    cells, rows, columns, ms = {}, [], [], {}
    for r in csv.DictReader(open(path)):
        settings = dict(item.split("=", 1) for item in r["settings"].split())
        key = (settings[row], settings[column])
        if key[0] not in rows:
            rows.append(key[0])
        if key[1] not in columns:
            columns.append(key[1])
        cells[key] = f"{float(r['false_shadow_percent']):.3f} / {float(r['false_light_percent']):.3f}"
        ms.setdefault(key[0], []).append(float(r["median_ms"]))
    print(f"| {row} | " + " | ".join(f"{column} {c}" for c in columns) + " | median ms |")
    print("| ---: " * (len(columns) + 2) + "|")
    for v in rows:
        times = sorted(ms[v])
        print(f"| {v} | " + " | ".join(cells.get((v, c), "") for c in columns) + f" | {times[len(times) // 2]:.1f} |")


if __name__ == "__main__":
    if sys.argv[1] == "--matrix":
        matrix(sys.argv[2:])
    elif sys.argv[1] == "--grid":
        grid(sys.argv[2], sys.argv[3], sys.argv[4])
    else:
        main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "hard")
