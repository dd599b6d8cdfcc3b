#!/usr/bin/env python3
"""Merges the JSON of shadowlab_peers, `shadowlab bench` and `shadowlab sweep` into one
table of shadowlab against its peers (docs/peers.md defines every row). Run by
scripts/bench_peers.sh; prints the table and, with --json, writes it."""
import argparse
import json
import platform
import sys
import time


def median_of(rows, **match):
    found = [r for r in rows if all(r.get(k) == v for k, v in match.items())]
    if len(found) != 1:
        sys.exit(f"peers_table.py: expected one row with {match}, found {len(found)}")
    return found[0]["median_ms"]


def sweep_ms(sweep, technique, settings):
    found = [r for r in sweep["rows"] if r["technique"] == technique and r["settings"] == settings]
    if len(found) != 1:
        sys.exit(f"peers_table.py: {sweep['scene']}: expected one {technique} {settings} row, found {len(found)}")
    return found[0]["median_ms"]


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def rows_for(scene, peers, bench, sweep, threads):
    p = [r for r in peers["rows"] if r["scene"] == scene]
    passes = [r for r in bench["passes"] if r["scene"] == scene and r["threads"] == threads]
    rays = [r for r in bench["reference"] if r["scene"] == scene and r["threads"] == threads]
    camera = [r for r in passes if r["pass"].startswith("camera ")]
    if len(camera) != 1:
        sys.exit(f"peers_table.py: {scene}: no camera pass in the bench JSON")
    camera_ms, camera_pass = camera[0]["median_ms"], camera[0]["pass"]
    map_nearest = sweep_ms(sweep, "shadow-map", {"filter": "nearest"})
    map_grid = sweep_ms(sweep, "shadow-map", {"filter": "grid"})
    volume = sweep_ms(sweep, "shadow-volume", {"mode": "zfail"})
    izb = sweep_ms(sweep, "izb", {})
    stencil = median_of(p, workload="stencil volumes z-fail")
    geometry = median_of(p, workload="volume geometry (cpu)")
    out = [
        ("light pass 2048x2048 both facings", median_of(p, workload="light pass"), None,
         median_of(passes, **{"pass": "light 2048x2048 both facings"}), "bench: light 2048x2048 both facings"),
        (f"camera prepass {camera_pass[7:]}", median_of(p, workload="camera prepass"), None, camera_ms,
         f"bench: {camera_pass}"),
        ("shadowed frame, 1 tap", median_of(p, workload="shadowed frame 1 tap"), None, map_nearest + camera_ms,
         "shadow-map filter=nearest + camera pass"),
        ("shadowed frame, 3x3 PCF", median_of(p, workload="shadowed frame 3x3 pcf"), None, map_grid + camera_ms,
         "shadow-map filter=grid grid-size=3 + camera pass"),
        ("stencil volumes z-fail (volumes prebuilt)", stencil, None, volume + camera_ms,
         "shadow-volume mode=zfail + camera pass"),
        ("stencil volumes z-fail + CPU volume geometry", stencil + geometry, None, volume + camera_ms,
         "peer: llvmpipe + extrudeShadowVolume on the CPU"),
        ("exact hard shadows per pixel, BVH built once", None, median_of(rays, bvh="built once"), izb,
         "izb: exact V for the same pixels, given the G-buffer"),
        ("exact hard shadows per pixel, BVH built per frame", None, median_of(rays, bvh="built per run"), izb,
         "izb: exact V for the same pixels, given the G-buffer"),
    ]
    table = []
    for workload, llvmpipe, embree, shadowlab, note in out:
        peer = llvmpipe if llvmpipe is not None else embree
        table.append({"scene": scene, "workload": workload, "llvmpipe_ms": llvmpipe, "embree_ms": embree,
                      "shadowlab_ms": shadowlab, "ratio_shadowlab_over_peer": shadowlab / peer, "note": note})
    return table


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--peers", required=True, help="shadowlab_peers --json output")
    ap.add_argument("--bench", required=True, help="shadowlab bench --json output")
    ap.add_argument("--sweep", action="append", default=[], help="shadowlab sweep JSON, one per scene")
    ap.add_argument("--threads", type=int, required=True)
    ap.add_argument("--json", help="write the table here too")
    a = ap.parse_args()
    peers = json.load(open(a.peers))
    bench = json.load(open(a.bench))
    sweeps = {s["scene"]: s for s in (json.load(open(path)) for path in a.sweep)}
    rows = []
    for scene in dict.fromkeys(r["scene"] for r in peers["rows"]):
        if scene not in sweeps:
            sys.exit(f"peers_table.py: no sweep JSON for {scene}")
        rows += rows_for(scene, peers, bench, sweeps[scene], a.threads)

    machine = {"cpu": cpu_model(), "threads": a.threads, "date": time.strftime("%Y-%m-%d"),
               "renderer": peers["renderer"], "gl_version": peers["gl_version"]}
    print(f"{machine['cpu']}, {a.threads} threads, {machine['date']}; {machine['renderer']}")
    fmt = "{:<11} {:<50} {:>11} {:>10} {:>13} {:>16}  {}"
    print(fmt.format("scene", "workload", "llvmpipe ms", "embree ms", "shadowlab ms", "shadowlab/peer", "shadowlab side"))
    num = lambda v: "-" if v is None else f"{v:.2f}"
    for r in rows:
        print(fmt.format(r["scene"], r["workload"], num(r["llvmpipe_ms"]), num(r["embree_ms"]), num(r["shadowlab_ms"]),
                         f"{r['ratio_shadowlab_over_peer']:.2f}", r["note"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"machine": machine, "rows": rows}, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
