#!/usr/bin/env python3
"""The technique-standard table (docs/performance.md, "Every technique to one standard"):
docs/data/technique_stages.json, which says what each technique's stages are, joined with
the stage times of `shadowlab sweep` runs, printed as Markdown on stdout: technique, stage,
kernel kind, parallel, allocation per frame, status, and each scene's time in ms per
million camera pixels (the stage's <stage>_ms over width * height / 1e6).

usage: technique_standard.py [--data FILE] [--threads N] SCENE=SWEEP.json[,SWEEP.json...] ...

Each SCENE=... names a column and the sweep JSON files (`shadowlab sweep SCENE --technique
LIST --threads N --runs R --out DIR`, the .json file in DIR) whose rows fill it. A sweep's
stage times are medians over its R measured frames; a technique in several files takes the
median of their figures (its first row at the thread count, the only one or --threads); a
technique may be swept apart (reference-soft, with fewer runs). The
camera's size is the sweep's --width and --height, else the scene file's camera
(assets/scenes/SCENE.json). A stage a technique reported that the data file does not
classify is an error, as is a technique it does not list (tests/app/technique_stages_test.py
checks both on tiny views).
"""
import argparse
import json
import os
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_DATA = os.path.join(ROOT, "docs", "data", "technique_stages.json")


def load_data(path):
    with open(path) as f:
        data = json.load(f)
    for t in data["techniques"]:
        for stage, part in t["stages"].items():
            if part not in data["parts"]:
                sys.exit(f"{path}: {t['technique']}'s stage {stage} names no part: '{part}'")
    return data


def stage_times(stats):
    """The stage times of a row's stats, in the order reported: {stage: ms}."""
    return {name[:-3]: ms for name, ms in stats.items() if name.endswith("_ms") and ms is not None}


def camera_pixels(sweep):
    """Width * height of the sweep's camera: its overrides, else the scene file's camera."""
    overrides = sweep["grid"].get("overrides", {})
    scene = os.path.join(ROOT, "assets", "scenes", sweep["scene"] + ".json")
    camera = {}
    if os.path.exists(scene):
        with open(scene) as f:
            camera = json.load(f).get("camera", {})
    width, height = overrides.get("width", camera.get("width")), overrides.get("height", camera.get("height"))
    if width is None or height is None:
        sys.exit(f"scene '{sweep['scene']}': no camera size; sweep it with --width and --height")
    return width * height


def scene_column(files, threads):
    """{technique: {stage: ms per Mpixel}} from the rows of the files at the thread count: each
    stage's median over the files that hold the technique (its first setting in each)."""
    times = {}
    for path in files:
        with open(path) as f:
            sweep = json.load(f)
        mpixels = camera_pixels(sweep) / 1e6
        seen = set()
        for row in sweep["rows"]:
            if (threads is not None and row["threads"] != threads) or row["technique"] in seen:
                continue
            seen.add(row["technique"])
            stages = times.setdefault(row["technique"], {})
            for stage, ms in stage_times(row["stats"]).items():
                stages.setdefault(stage, []).append(ms / mpixels)
    return {t: {stage: statistics.median(v) for stage, v in stages.items()} for t, stages in times.items()}


def check_classified(data, columns):
    known = {t["technique"]: t["stages"] for t in data["techniques"]}
    for scene, column in columns.items():
        for technique, stages in column.items():
            if technique not in known:
                sys.exit(f"{scene}: technique '{technique}' is not in the data file")
            missing = [s for s in stages if s not in known[technique]]
            if missing:
                sys.exit(f"{scene}: {technique} reports stages the data file does not classify: {', '.join(missing)}")


def cell(text):
    return str(text).replace("|", "\\|")


def table(data, columns):
    scenes = list(columns)
    header = ["technique", "stage", "kernel kind", "parallel", "allocates per frame", "status"]
    header += [f"{s} ms/Mpixel" for s in scenes]
    lines = ["| " + " | ".join(header) + " |", "|" + " --- |" * 6 + " ---: |" * len(scenes)]
    for t in data["techniques"]:
        name = t["technique"]
        if not any(name in columns[s] for s in scenes):
            continue
        if not t["stages"]:
            lines.append(f"| {name} | (no stages) | | | | |" + " |" * len(scenes))
        for stage, part_name in t["stages"].items():
            reported = [columns[s].get(name, {}).get(stage) for s in scenes]
            if all(ms is None for ms in reported) and stage in t.get("when", {}):
                continue   # a stage of other frames: not in these runs
            part = data["parts"][part_name]
            times = ["" if ms is None else f"{ms:.1f}" for ms in reported]
            row = [name, stage, part["kernel"], part["parallel"], part["allocates"], part["status"]] + times
            lines.append("| " + " | ".join(cell(c) for c in row) + " |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", default=DEFAULT_DATA, help="the stage classification (docs/data/technique_stages.json)")
    parser.add_argument("--threads", type=int, help="the rows at this thread count (default: the first row of each technique)")
    parser.add_argument("columns", nargs="+", metavar="SCENE=SWEEP.json[,SWEEP.json...]")
    args = parser.parse_args()
    data = load_data(args.data)
    columns = {}
    for spec in args.columns:
        scene, sep, files = spec.partition("=")
        if not sep or not files:
            parser.error(f"expected SCENE=SWEEP.json[,...], got '{spec}'")
        columns[scene] = scene_column(files.split(","), args.threads)
    check_classified(data, columns)
    print(table(data, columns))


if __name__ == "__main__":
    main()
