"""Sweeps and fly-throughs from Python (docs/python.md, "Sweeps", "Fly-throughs" and "Dask").

sweep() runs the library's sweep (the command `shadowlab sweep`) in this process, one shard of
it, or all its shards over a dask.distributed cluster: each worker runs its shard with the
library and sends back the shard's JSON text (nothing of C++ is pickled), and the shards are
merged as `shadowlab merge-sweep` merges their files.
"""

import io
import operator
import os

from . import _shadowlab, load_scene   # the package imports this module after defining load_scene
from ._shadowlab import FlythroughFrame, FlythroughResults, FlythroughSeries, SweepResults, SweepRow, merge_sweeps

__all__ = ["sweep", "flythrough", "merge_sweeps", "SweepResults", "SweepRow", "FlythroughResults",
           "FlythroughSeries", "FlythroughFrame"]


def _technique_names(techniques):
    """A name, a Technique or a list of either -> [names]."""
    if isinstance(techniques, str) or hasattr(techniques, "name"):
        techniques = [techniques]
    names = []
    for t in techniques:
        name = t if isinstance(t, str) else getattr(t, "name", None)
        if not isinstance(name, str):
            raise TypeError(f"techniques: expected names or Technique objects, got {type(t).__name__}")
        names.append(name)
    return names


def _portable_scene(scene, base_dir):
    """The scene as another process loads it: a name, an absolute path, or a dict with an
    absolute base_dir. A Scene object is not sent (nothing of C++ is pickled)."""
    if isinstance(scene, os.PathLike):
        scene = os.fspath(scene)
    if isinstance(scene, str):
        return {"source": os.path.abspath(scene) if _shadowlab._looks_like_path(scene) else scene, "base_dir": None}
    if isinstance(scene, dict):
        return {"source": scene, "base_dir": os.path.abspath(base_dir if base_dir is not None else os.getcwd())}
    raise TypeError("sweep(client=...): give the scene as a name, a path or a dict, which the workers load; "
                    f"a {type(scene).__name__} is not sent to them")


def _thread_list(threads):
    """None, a count or a list of counts -> [counts]. operator.index, not int(): threads="12"
    was the counts 1 and 2, and 1.7 was 1."""
    if threads is None:
        return []
    if isinstance(threads, (str, bytes)):
        raise TypeError(f"threads: expected an int or a list of ints, got {type(threads).__name__}")
    if not hasattr(threads, "__iter__"):
        return [operator.index(threads)]
    return [operator.index(n) for n in threads]


def _run(call, shard):
    """One sweep (or shard) in this process; call holds the arguments as plain values."""
    scene = load_scene(call["scene"]["source"], base_dir=call["scene"]["base_dir"])
    return _shadowlab._sweep(scene, call["techniques"], call["params"], call["threads"], call["runs"],
                             call["warmup"], call["reference"], shard, call["simd"], **call["overrides"])


def _run_shard(call, index, count):
    """A Dask task: shard index/count of the sweep, as the JSON text the command writes."""
    return _run(call, (index, count)).to_json()


def sweep(scene, techniques, params=None, *, threads=None, runs=5, warmup=1, reference=None, shard=None,
          simd=None, light=None, width=None, height=None, eye=None, target=None, fovy_deg=None,
          light_position=None, light_radius=None, base_dir=None, client=None, shards=None):
    """Speed against error over a grid of technique settings: `shadowlab sweep` as a function.

    Every technique runs the cross product of the params axes it has (an axis a technique
    lacks does not multiply its runs), at every thread count: warm-up frames, then `runs`
    measured frames, of which the median and minimum technique time are kept; each setting
    is scored against its technique's reference (or `reference`), rendered once per sweep.

    Args:
        scene: a built-in scene's name, a scene file's path (str or os.PathLike), a dict in the
            scene format's shape (meshes relative to base_dir, default the current directory),
            or a Scene.
        techniques: a technique's name or Technique, or a list of them.
        params: {name: value or list of values}, one axis per name (str, int, float or bool;
            a bool is on/off), e.g. {"resolution": [512, 1024], "filter": "grid"}.
        threads: worker threads: an int or a list of counts, each a row; None: all cores.
        runs, warmup: measured and warm-up frames per row.
        reference: score every technique against this one (default: each its own).
        shard: (i, n) or "i/n": run only the settings k with k mod n == i - 1 (i from 1).
        simd: "scalar", "avx2", "avx512" or "auto"; None: the best this CPU runs.
        light, width, height, eye, target, fovy_deg, light_position, light_radius: the
            scene's overrides, as the command's --light, --width, ... and Scene.apply_overrides.
        client: a dask.distributed Client: the sweep is split into `shards` shards (default:
            the client's workers, at most the sweep's settings), each run by a worker, and
            merged (merge_sweeps). The workers import shadowlab themselves and load the scene
            by its name, path or dict: a path must be readable where they run. Give threads=
            too: None is each worker's own core count, and shards of different counts do not
            merge.
        shards: the number of shards with a client.

    Returns:
        SweepResults; its to_json() and to_csv() are the bytes the command writes.

    Raises:
        ValueError: an unknown technique or parameter, a value a technique rejects, a bad
            shard, thread count or override, a scene file's problem.
        FileNotFoundError: a scene file that does not exist.
        TypeError: an argument of the wrong type.

    Threads: the GIL is released while the library runs, and each thread count runs in a TBB
    arena of its own, so sweeps and renders in other Python threads keep their counts. More
    threads than the machine has cores need a process-wide TBB limit raised
    (raster/thread_count.h): two such sweeps at once cap each other at the smaller count
    (the same bytes, but times of fewer threads than they say).
    """
    names = _technique_names(techniques)
    call = {"techniques": names, "params": params, "threads": _thread_list(threads), "runs": runs,
            "warmup": warmup, "reference": reference or "", "simd": simd,
            "overrides": {"light": light, "width": width, "height": height, "eye": eye, "target": target,
                          "fovy_deg": fovy_deg, "light_position": light_position, "light_radius": light_radius}}
    if client is None:
        if shards is not None:
            raise ValueError("sweep: shards= splits the sweep over a client; give client= too (or shard= for one part)")
        call["scene"] = {"source": scene, "base_dir": base_dir}
        return _run(call, shard)
    if shard is not None:
        raise ValueError("sweep: give either shard= (one part, here) or client= (every part, on the cluster)")
    call["scene"] = _portable_scene(scene, base_dir)
    settings = _shadowlab._sweep_settings(names, params)
    if shards is None:
        shards = max(1, min(len(client.scheduler_info()["workers"]), settings))
    _shadowlab._check_shard_count(operator.index(shards), settings)   # before the cluster works
    futures = [client.submit(_run_shard, call, i, shards, pure=False) for i in range(1, shards + 1)]
    return merge_sweeps([SweepResults.from_json(text) for text in client.gather(futures)])


def flythrough(scene, techniques, params=None, *, path=None, frames=0, threads=0, runs=3, warmup=1,
               stable_tolerance=None, simd=None, light=None, width=None, height=None, base_dir=None):
    """Shadows in motion: `shadowlab flythrough` as a function (docs/flythrough.md).

    The camera (and maybe the first light and some instances) follows a path sampled at
    `frames` frames; at every frame each technique setting is timed (warm-up, then the median
    of `runs`), scored against the frame's exact reference and its flicker measured against
    the frame before, on the pixels where the reference did not change.

    Args:
        scene: as sweep() takes it (a name, a path, a dict or a Scene).
        techniques: a technique's name or Technique, or a list of them (each producing V).
        params: {name: value or list of values}, axes as in sweep().
        path: a keyframes CSV file; None: the scene's own "flythrough".
        frames: frames along the path (>= 2); 0: the path's own count, else 48.
        threads: worker threads, 0: all cores.
        runs, warmup: measured and warm-up runs per path frame.
        stable_tolerance: the reference's V counts as unchanged if it moves by at most this;
            None: the command's default.
        simd: as sweep() takes it.
        light, width, height: the scene's light selection and image size.

    Returns:
        FlythroughResults: .series, one per technique setting, each with .frames (one
        FlythroughFrame per path frame) and .path_figures; to_json(), to_csv() and
        to_dataframe().

    Raises:
        ValueError: an unknown technique or parameter, a technique that shades, a scene of
            several lights without light=, a scene without a path and no path=.
    """
    path_file = "" if path is None else os.fspath(path)
    return _shadowlab._flythrough(load_scene(scene, base_dir=base_dir), _technique_names(techniques),
                                  params, path_file, frames, threads, runs, warmup, stable_tolerance, simd,
                                  light, width, height)


def _read_csv(text):
    try:
        import pandas
    except ImportError as e:
        raise ImportError("to_dataframe() needs pandas (Debian: python3-pandas; pip: pandas); "
                          "to_csv() gives the same table as text") from e
    return pandas.read_csv(io.StringIO(text))


def _sweep_dataframe(self):
    """The rows as a pandas DataFrame: the command's CSV columns (technique, settings, threads,
    median_ms, min_ms, the error figures, reference, flip_mean, per-light figures, the stats),
    after a first column `setting` (SweepRow.setting). pandas is imported here: ImportError
    without it."""
    frame = _read_csv(self.to_csv())
    frame.insert(0, "setting", [row.setting for row in self.rows])
    return frame


def _flythrough_dataframe(self):
    """One row per series and path frame as a pandas DataFrame, with the command's CSV columns
    (technique, settings, frame, time, eye_x, ..., median_ms, rms, ..., flicker_mean, moved,
    the stats). pandas is imported here: ImportError without it."""
    return _read_csv(self.to_csv())


SweepResults.to_dataframe = _sweep_dataframe
FlythroughResults.to_dataframe = _flythrough_dataframe
