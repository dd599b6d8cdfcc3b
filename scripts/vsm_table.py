#!/usr/bin/env python3
"""Prints the equal-memory tables of docs/virtual-shadow-maps.md (Markdown): the virtual map
beside shadow-map and csm at the depth memory each reserves (its budget) and holds.

usage: scripts/vsm_table.py sweep SWEEP.csv [FIRST.csv]
           one row per technique and settings of a still view, by budget: median ms (a still
           view's steady state: the virtual map's pages kept from the warm-up frame),
           misclassified %, RMS, the virtual map's pages and the times of marking and lookup,
           and its first frame from FIRST.csv (a sweep with --warmup 0: every page drawn)
       scripts/vsm_table.py flythrough FLYTHROUGH.json [...]
           one table per path: one row per series with its first frame and the frames after,
           pages drawn and cache hits along the path"""
import csv
import json
import statistics
import sys

MIB = 1024.0 * 1024.0
DEPTH_BYTES = 4          # a float depth per texel
DEFAULTS = {"resolution": 2048, "cascades": 4, "pool-pages": 1024, "page-texels": 128}


def settings_of(text):
    return {} if text in ("", "defaults") else dict(item.split("=", 1) for item in text.split())


def budget_mib(technique, settings):
    """The depth memory a setting reserves: the maps it draws, or the virtual map's pool."""
    value = lambda name: int(settings.get(name, DEFAULTS[name]))
    if technique == "virtual-shadow-map":
        return value("pool-pages") * value("page-texels") ** 2 * DEPTH_BYTES / MIB
    if technique == "csm":
        return value("cascades") * value("resolution") ** 2 * DEPTH_BYTES / MIB
    if technique == "shadow-map":
        return value("resolution") ** 2 * DEPTH_BYTES / MIB
    return None


def held_mib(stats):
    """What it held: the virtual map's pool in use (cache_pool_bytes), else its maps' texels
    (a virtual map without a sun draws shadow-map's frame and reports its maps)."""
    number = lambda name: float(stats[name]) if stats.get(name) not in (None, "") else None
    if number("cache_pool_bytes") is not None and number("virtual_map_flag"):
        return number("cache_pool_bytes") / MIB
    texels = number("resolution_texels")
    maps = number("cascades_count") or number("maps_count")
    return maps * texels ** 2 * DEPTH_BYTES / MIB if texels and maps else None


def fallback(stats):
    """A sun's technique under a light that is not a sun draws shadow-map's frame (its stats say so)."""
    if stats["technique"] == "csm":
        return float(stats.get("cascades_count") or 0) == 0
    if stats["technique"] == "virtual-shadow-map":
        return float(stats.get("virtual_map_flag") or 0) == 0
    return False


def cell(value, digits):
    return "" if value is None or value == "" else f"{float(value):.{digits}f}"


def sweep(path, first_path=None):
    rows = list(csv.DictReader(open(path)))
    first = {}
    if first_path:
        first = {(r["technique"], r["settings"]): r for r in csv.DictReader(open(first_path))}
    keyed = []
    for r in rows:
        budget = budget_mib(r["technique"], settings_of(r["settings"]))
        keyed.append((budget if budget is not None else -1.0, r))
    print("| budget MiB | technique | settings | held MiB | ms | misclassified % | RMS | pages "
          "| marking / lookup ms | first frame: ms, of it drawing pages |")
    print("| ---: | --- | --- | ---: | ---: | ---: | ---: | --- | --- | --- |")
    for budget, r in sorted(keyed, key=lambda k: k[0]):
        virtual = r["technique"] == "virtual-shadow-map" and not fallback(r)
        cold = first.get((r["technique"], r["settings"]), {})
        pages = stages = drawn = ""
        if virtual:
            pages = r["requested_pages"]
            if float(r.get("cache_overflowed_pages") or 0) > 0:
                pages += f" ({cell(r['cache_overflowed_pages'], 0)} without memory)"
            stages = f"{cell(r['marking_ms'], 1)} / {cell(r['lookup_ms'], 1)}"
            if cold:
                drawn = f"{cell(cold['median_ms'], 1)}, {cell(cold['pages_ms'], 1)}"
        label = r["technique"] + (" (shadow-map's frame)" if fallback(r) else "")
        print(f"| {cell(budget, 0) if budget >= 0 else ''} | {label} | {r['settings']} | {cell(held_mib(r), 1)} "
              f"| {cell(r['median_ms'], 1)} | {cell(r['misclassified_percent'], 3)} | {cell(r['rms'], 4)} "
              f"| {pages} | {stages} | {drawn} |")


def stat_values(series, name, frames):
    values = [f["stats"][name] for f in frames if name in f["stats"]]
    return values if values else None


def flythrough(paths):
    for path in paths:
        run = json.load(open(path))
        where = run["scene"] if run["path"] == "scene" else run["scene"] + " (" + run["path"].split("/")[-1] + ")"
        print(f"**{where}**, {run['frames']} frames\n")
        print("| budget MiB | series | held MiB | ms, frame 0 | ms, later (median) | misclassified % | RMS "
              "| pages drawn, frame 0 | pages drawn later: median (max) | cache hits later % | flicker mean |")
        print("| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: |")
        keyed = []
        for s in run["series"]:
            budget = budget_mib(s["technique"], s["settings"])
            keyed.append((budget if budget is not None else -1.0, s))
        for budget, s in sorted(keyed, key=lambda k: k[0]):
            frames, p = s["frames"], s["path_figures"]
            label = " ".join([s["technique"]] + [k + "=" + v for k, v in s["settings"].items()])
            held = max((held_mib(f["stats"]) or 0.0) for f in frames)
            later = frames[1:]
            drawn = stat_values(s, "cache_drawn_pages", later)
            hits = stat_values(s, "cache_hit_percent", later)
            first_drawn = frames[0]["stats"].get("cache_drawn_pages")
            print(f"| {cell(budget, 0) if budget >= 0 else ''} | {label} | {cell(held, 1)} "
                  f"| {cell(frames[0]['median_ms'], 1)} | {cell(statistics.median(f['median_ms'] for f in later), 1)} "
                  f"| {cell(p['mean_misclassified_percent'], 3)} | {cell(p['mean_rms'], 4)} | {cell(first_drawn, 0)} "
                  f"| {cell(statistics.median(drawn), 0) + ' (' + cell(max(drawn), 0) + ')' if drawn else ''} "
                  f"| {cell(statistics.mean(hits), 1) if hits else ''} | {p['flicker_mean']:.2g} |")
        print()


def main(args):
    if len(args) >= 2 and args[0] == "sweep" and len(args) <= 3:
        sweep(*args[1:])
    elif len(args) >= 2 and args[0] == "flythrough":
        flythrough(args[1:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
