#!/usr/bin/env python3
"""The Figure 3 table of docs/subtractive-shadows.md from scripts/figure3.sh's sweeps: one
row per scene, technique, N and sampling detail; median ms at 1 and 2 threads (from the
timed pass, scored against the 1000-light reference); RMS of the luminance against the
exact reference (linear, and as displayed after tone mapping where the sweep recorded it)
and against the 1000-light reference.

usage: scripts/figure3_table.py EXACT_DIR LIGHTS_DIR"""
import json
import pathlib
import sys


def rows(directory):
    """{(scene, technique, settings, threads): row} of every sweep JSON in the directory."""
    found = {}
    for path in sorted(pathlib.Path(directory).glob("*.json")):
        sweep = json.loads(path.read_text())
        for r in sweep["rows"]:
            settings = " ".join(f"{k}={v}" for k, v in sorted(r["settings"].items()) if k != "sampler")
            found[(sweep["scene"], r["technique"], settings, r["threads"])] = r
    return found


def display(errors):
    """The RMS of the displayed luminance, where the sweep recorded it."""
    return f"{errors['rms_display']:.4f}" if "rms_display" in errors else ""


def main(exact_dir, lights_dir):
    exact, lights = rows(exact_dir), rows(lights_dir)
    print("| scene | technique | N | detail | ms, 1 thr. | ms, 2 thr. | RMS vs exact | displayed | RMS vs 1000 lights |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    keys = sorted({k[:3] for k in exact}, key=lambda k: (k[0], k[1], int(dict(s.split("=") for s in k[2].split())["lights"]), k[2]))
    for scene, technique, settings in keys:
        values = dict(s.split("=") for s in settings.split())
        errors = next(exact[k]["errors"] for k in exact if k[:3] == (scene, technique, settings))
        one, two = lights.get((scene, technique, settings, 1)), lights.get((scene, technique, settings, 2))
        cells = [scene, technique, values["lights"], values.get("sampling-detail", ""),
                 f"{one['median_ms']:.0f}" if one else "", f"{two['median_ms']:.0f}" if two else "",
                 f"{errors['rms']:.4f}", display(errors),
                 f"{(one or two)['errors']['rms']:.4f}" if one or two else ""]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
