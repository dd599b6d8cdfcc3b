#!/usr/bin/env python3
"""What a Dask cluster of two worker processes costs and saves on one machine: a sweep of
shadow-map (hard reference) and one of pcss (reference-soft) on sphere-box at 640 x 400, four
map resolutions, run here and over the cluster alternately, three times each (docs/python.md,
"Dask"); and the reference alone, which every shard renders again.

    PYTHONPATH=build/python /usr/bin/python3 scripts/dask_sweep_timing.py

Prints JSON: the cluster's start time, each run's wall time (s), the ratio of the medians
(here / cluster: above 1, the cluster is faster) and the reference's sweep time.
"""
import json
import statistics
import time

import distributed

import shadowlab

ARGS = dict(threads=1, runs=5, warmup=1, width=640, height=400)
PARAMS = {"resolution": [256, 512, 1024, 2048]}


def seconds(run):
    start = time.perf_counter()
    run()
    return time.perf_counter() - start


def main():
    start = time.perf_counter()
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    out = {"cluster_start_s": time.perf_counter() - start}
    for name, technique, reference in (("hard", "shadow-map", "reference"), ("soft", "pcss", "reference-soft")):
        here, spread = [], []
        for _ in range(3):   # alternated, so that both see the same load
            here.append(seconds(lambda: shadowlab.sweep("sphere-box", technique, PARAMS, **ARGS)))
            spread.append(seconds(lambda: shadowlab.sweep("sphere-box", technique, PARAMS, client=client, **ARGS)))
        alone = seconds(lambda: shadowlab.sweep("sphere-box", "none", reference=reference,
                                                **{**ARGS, "runs": 1, "warmup": 0}))
        out[name] = {"here_s": here, "cluster_s": spread,
                     "here_over_cluster": statistics.median(here) / statistics.median(spread),
                     "reference_sweep_s": alone}
    print(json.dumps(out, indent=1))
    client.close()
    cluster.close()


if __name__ == "__main__":   # the worker processes import this file again
    main()
