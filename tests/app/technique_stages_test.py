#!/usr/bin/env python3
"""docs/data/technique_stages.json against the techniques themselves: every technique of
`shadowlab techniques` is listed and no other; each technique, swept on a tiny view of its
test scene (one frame, one thread), reports exactly the stages the file classifies, but
for those it marks `when` (reported only in some frames: a directional light, cut-outs,
debug buffers), whose name must still be a stage some StageTimer laps in shadows/; and
every part's source file exists.

usage: technique_stages_test.py SHADOWLAB SCRATCH_DIR
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "docs", "data", "technique_stages.json")
TINY = ["--width", "40", "--height", "25", "--threads", "1", "--runs", "1", "--warmup", "0"]

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def registered_techniques(shadowlab):
    """The names `shadowlab techniques` lists, one a line, first word."""
    out = subprocess.run([shadowlab, "techniques"], check=True, capture_output=True, text=True).stdout
    return {line.split()[0] for line in out.splitlines() if line.strip() and not line.startswith(" ")}


def scene_argument(name):
    """A built-in scene's name as is, else the scene file under assets/scenes."""
    path = os.path.join(ROOT, "assets", "scenes", name + ".json")
    return path if "/" in name else name


def swept_stages(shadowlab, scene, techniques, out):
    """{technique: [stage, ...]} of one tiny sweep of the techniques."""
    command = [shadowlab, "sweep", scene_argument(scene), "--technique", ",".join(techniques), *TINY, "--out", out]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{' '.join(command)}: exit {result.returncode}: {result.stderr.strip()[-400:]}")
        return {}
    (path,) = glob.glob(os.path.join(out, "*.json"))
    with open(path) as f:
        rows = json.load(f)["rows"]
    return {r["technique"]: [name[:-3] for name in r["stats"] if name.endswith("_ms")] for r in rows}


def batches(names):
    """The names in runs whose joined length stays short: a sweep's output is named after
    its techniques, and all of them would make too long a file name."""
    batch = []
    for name in names:
        if batch and len("+".join(batch + [name])) > 120:
            yield batch
            batch = []
        batch.append(name)
    if batch:
        yield batch


def lapped_stages():
    """Every stage name a StageTimer laps as a literal in shadows/."""
    names = set()
    for path in glob.glob(os.path.join(ROOT, "shadows", "**", "*.*"), recursive=True):
        with open(path, errors="replace") as f:
            names.update(re.findall(r'\blap\("([a-z0-9_]+)"\)', f.read()))
    return names


def main():
    shadowlab, scratch = sys.argv[1], sys.argv[2]
    shutil.rmtree(scratch, ignore_errors=True)
    with open(DATA) as f:
        data = json.load(f)
    listed = {t["technique"]: t for t in data["techniques"]}

    registered = registered_techniques(shadowlab)
    for name in sorted(registered - set(listed)):
        fail(f"technique {name} is not in {DATA}")
    for name in sorted(set(listed) - registered):
        fail(f"{DATA} lists {name}, which is no technique")

    for name, part in data["parts"].items():
        if not os.path.isfile(os.path.join(ROOT, part["file"])):
            fail(f"part '{name}' cites {part['file']}, which is no file")

    lapped = lapped_stages()
    by_scene = {}
    for t in data["techniques"]:
        for stage, part in t["stages"].items():
            if part not in data["parts"]:
                fail(f"{t['technique']}'s stage {stage} names no part: '{part}'")
        for stage in t.get("when", {}):
            if stage not in t["stages"]:
                fail(f"{t['technique']}: `when` names {stage}, which is not among its stages")
            elif stage not in lapped:
                fail(f"{t['technique']}: no StageTimer in shadows/ laps a stage '{stage}'")
        if t["technique"] in registered:
            by_scene.setdefault(t["test_scene"], []).append(t["technique"])

    for scene, techniques in by_scene.items():
        reported = {}
        for k, batch in enumerate(batches(techniques)):
            reported.update(swept_stages(shadowlab, scene, batch, os.path.join(scratch, scene.replace("/", "-") + str(k))))
        for name in techniques:
            if name not in reported:
                fail(f"{name}: no row in the sweep of {scene}")
                continue
            classified = listed[name]["stages"]
            for stage in reported[name]:
                if stage not in classified:
                    fail(f"{name} on {scene} reports stage {stage}, which the data file does not classify")
            for stage in classified:
                if stage not in listed[name].get("when", {}) and stage not in reported[name]:
                    fail(f"the data file names stage {stage} of {name}, which it did not report on {scene}")
        print(f"{scene}: {len(techniques)} techniques checked")

    if failures:
        sys.exit(f"{len(failures)} failures")
    print("every technique's stages are classified")


if __name__ == "__main__":
    main()
