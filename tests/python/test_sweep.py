"""sweep() and flythrough() give what the command gives: the same JSON but for the measured
times, the same bytes back from from_json, shards that merge into the whole sweep, and
exceptions (not crashes) for bad input."""
import json
import os
import pathlib
import pickle
import subprocess
import sys
import threading

import pytest

import shadowlab
from conftest import ticks_while

COMMAND = os.environ["SHADOWLAB_COMMAND"]
SIZE = {"width": 64, "height": 48}
SMALL = {"threads": 1, "runs": 1, "warmup": 0, **SIZE}


def without_times(text):
    """A sweep's or fly-through's JSON without what each machine measures for itself
    (sweep_merge.h): every field named *_ms, the rows' times and the stats' stage times."""
    def strip(value):
        if isinstance(value, dict):
            return {k: strip(v) for k, v in value.items() if not k.endswith("_ms")}
        return [strip(v) for v in value] if isinstance(value, list) else value
    return strip(json.loads(text))


def command_json(tmp_path, *args):
    subprocess.run([COMMAND, *args, "--out", str(tmp_path)], check=True, capture_output=True)
    [path] = tmp_path.glob("*.json")
    return path.read_text()


@pytest.fixture(scope="module")
def two_techniques():
    params = {"resolution": [64, 256], "filter": ["nearest", "grid"]}
    return shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], params, **SMALL)


def test_a_sweep_is_the_commands_but_for_its_times(tmp_path, two_techniques):
    text = command_json(tmp_path, "sweep", "sphere-box", "--technique", "shadow-map,pcss", "--param",
                        "resolution=64,256", "--param", "filter=nearest,grid", "--threads", "1", "--runs", "1",
                        "--warmup", "0", "--width", "64", "--height", "48")
    assert without_times(two_techniques.to_json()) == without_times(text)
    # Read back, the command's file writes the same bytes again; so does a pickled copy (as its JSON).
    assert shadowlab.SweepResults.from_json(text).to_json() == text
    assert pickle.loads(pickle.dumps(two_techniques)).to_json() == two_techniques.to_json()
    # A pickle whose text is not a sweep's is a bad value, as from_json's is.
    broken = pickle.dumps(two_techniques).replace(b'"grid"', b'"gird"')
    with pytest.raises(ValueError, match="a pickled SweepResults"):
        pickle.loads(broken)


def test_rows_are_objects_with_the_jsons_figures(two_techniques):
    r = two_techniques
    assert (r.scene, r.techniques, r.shard) == ("sphere-box", ["shadow-map", "pcss"], (1, 1))
    assert r.grid["axes"] == {"resolution": ["64", "256"], "filter": ["nearest", "grid"]}
    assert r.grid["overrides"] == SIZE and r.grid["threads"] == [1] and r.grid["settings"] == len(r.rows)
    rows = json.loads(r.to_json())["rows"]
    assert [row.setting for row in r.rows] == [row["setting"] for row in rows] == list(range(len(rows)))
    for row, written in zip(r.rows, rows):
        assert row.settings == written["settings"] and row.technique == written["technique"]
        assert row.errors.rms == written["errors"]["rms"] and row.median_ms == written["median_ms"]
        assert row.stats == written["stats"] and row.threads == 1 and row.light_errors == []
    # The finer map misclassifies fewer pixels: the rows carry the figures, not placeholders.
    by = {(row.technique, row.settings_label): row.errors for row in r.rows}
    assert by["shadow-map", "filter=nearest resolution=256"].rms < by["shadow-map", "filter=nearest resolution=64"].rms


def test_the_dataframe_is_the_csv(two_techniques):
    frame = two_techniques.to_dataframe()
    assert list(frame.columns[:6]) == ["setting", "technique", "settings", "threads", "median_ms", "min_ms"]
    assert len(frame) == len(two_techniques.rows)
    assert list(frame["rms"]) == pytest.approx([row.errors.rms for row in two_techniques.rows], rel=1e-8)


def test_shards_merge_into_the_whole_sweep(two_techniques):
    params = {"resolution": [64, 256], "filter": ["nearest", "grid"]}
    shards = [shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], params, shard=f"{i}/3", **SMALL)
              for i in (1, 2, 3)]
    assert [s.shard for s in shards] == [(1, 3), (2, 3), (3, 3)]
    merged = shadowlab.merge_sweeps(list(reversed(shards)))
    assert merged.shard == (1, 1)
    assert without_times(merged.to_json()) == without_times(two_techniques.to_json())
    with pytest.raises(ValueError, match=r"missing shard\(s\) 2/3"):
        shadowlab.merge_sweeps([shards[0], shards[2]])
    other = shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], params, shard=(2, 3), **{**SMALL, "runs": 2})
    with pytest.raises(ValueError, match="runs"):
        shadowlab.merge_sweeps([shards[0], other, shards[2]])


def test_bad_input_raises(two_techniques):
    with pytest.raises(ValueError, match="no-such"):
        shadowlab.sweep("sphere-box", "no-such", **SMALL)
    with pytest.raises(ValueError, match="resolution"):
        shadowlab.sweep("sphere-box", "shadow-map", {"resolution": [3]}, **SMALL)
    with pytest.raises(ValueError, match="no technique|none of the techniques"):
        shadowlab.sweep("sphere-box", "shadow-map", {"rays": 2}, **SMALL)
    with pytest.raises(ValueError, match="shard"):
        shadowlab.sweep("sphere-box", "shadow-map", shard=(3, 2), **SMALL)
    with pytest.raises(ValueError, match="only 1 settings"):
        shadowlab.sweep("sphere-box", "shadow-map", shard="1/2", **SMALL)
    with pytest.raises(ValueError, match="thread"):
        shadowlab.sweep("sphere-box", "shadow-map", **{**SMALL, "threads": 0})
    with pytest.raises(ValueError, match="within 1..1024"):   # TBB crashed on a billion threads
        shadowlab.sweep("sphere-box", "shadow-map", **{**SMALL, "threads": 10**9})
    with pytest.raises(ValueError, match="more than 1048576 settings"):   # filled the memory planning it
        shadowlab.sweep("sphere-box", "shadow-map", {"resolution": range(16, 8192), "slope-factor": range(1000)}, **SMALL)
    with pytest.raises(ValueError, match="more than 1048576 values"):
        shadowlab.sweep("sphere-box", "shadow-map", {"slope-factor": range(10**12)}, **SMALL)
    with pytest.raises(ValueError, match="warm-up runs 0..1000"):   # results its own JSON refused
        shadowlab.sweep("sphere-box", "shadow-map", **{**SMALL, "warmup": 1001})
    with pytest.raises(ValueError, match="given twice"):   # rows whose JSON from_json refused
        shadowlab.sweep("sphere-box", "shadow-map", **{**SMALL, "threads": [1, 1]})
    with pytest.raises(ValueError, match="within 0..1024"):   # hung making a million threads
        shadowlab.flythrough("sphere-box", "shadow-map", frames=2, runs=1, **{**SIZE, "threads": 10**6})
    with pytest.raises(ValueError):
        shadowlab.sweep("sphere-box", "shadow-map", simd="sse9", **SMALL)
    with pytest.raises(ValueError, match="light"):
        shadowlab.sweep("sphere-box", "shadow-map", light=7, **SMALL)
    with pytest.raises(TypeError):
        shadowlab.sweep("sphere-box", "shadow-map", {"resolution": [object()]}, **SMALL)
    with pytest.raises(TypeError):
        shadowlab.sweep("sphere-box", "shadow-map", eye="up", **SMALL)
    for threads in ("12", [1.7], 2.0):   # were the counts [1, 2], [1] and [2]
        with pytest.raises(TypeError):
            shadowlab.sweep("sphere-box", "shadow-map", **{**SMALL, "threads": threads})
    with pytest.raises(ValueError, match="JSON"):
        shadowlab.SweepResults.from_json('{"scene": 1}')
    with pytest.raises(ValueError, match="JSON"):
        shadowlab.SweepResults.from_json(two_techniques.to_json()[:-20])


def test_a_flythrough_is_the_commands_but_for_its_times(tmp_path):
    args = {"frames": 3, "threads": 1, "runs": 1, "warmup": 0, **SIZE}
    results = shadowlab.flythrough("sphere-box", ["shadow-map", "pcss"], {"resolution": 128}, **args)
    text = command_json(tmp_path, "flythrough", "sphere-box", "--technique", "shadow-map,pcss", "--param",
                        "resolution=128", "--frames", "3", "--threads", "1", "--runs", "1", "--warmup", "0",
                        "--width", "64", "--height", "48")

    assert without_times(results.to_json()) == without_times(text)
    assert [s.label for s in results.series] == ["shadow-map resolution=128", "pcss resolution=128"]
    written = json.loads(text)["series"]
    for series, series_json in zip(results.series, written):
        assert [f.frame for f in series.frames] == [0, 1, 2]
        assert series.frames[0].flicker == {} and series.frames[1].flicker["pixels"] > 0
        for frame, frame_json in zip(series.frames, series_json["frames"]):
            assert frame.errors.rms == frame_json["errors"]["rms"]
            assert list(frame.eye) == frame_json["eye"] and frame.moved == frame_json["moved"]
        assert series.path_figures["mean_rms"] == series_json["path_figures"]["mean_rms"]
    frame = results.to_dataframe()
    assert len(frame) == 6 and list(frame.columns[:3]) == ["technique", "settings", "frame"]
    with pytest.raises(ValueError, match="shaded image"):
        shadowlab.flythrough("sphere-box", "env-subtractive", **args)


def sphere_box_dict():
    with open(os.path.join(shadowlab.scene_dir(), "sphere-box.json")) as f:
        return json.load(f)


def test_every_scene_form_sweeps_alike(two_techniques):
    params = {"resolution": [64, 256], "filter": ["nearest", "grid"]}
    want = without_times(two_techniques.to_json())
    scene = shadowlab.load_scene("sphere-box")
    path = os.path.join(shadowlab.scene_dir(), "sphere-box.json")
    for form in (scene, path, pathlib.Path(path)):
        got = shadowlab.sweep(form, ["shadow-map", "pcss"], params, **SMALL)
        assert without_times(got.to_json()) == want
    # A dict is a scene of another name; its figures are the file's.
    from_dict = shadowlab.sweep(sphere_box_dict(), ["shadow-map", "pcss"], params, **SMALL)
    assert {**without_times(from_dict.to_json()), "scene": "sphere-box"} == want
    with pytest.raises(FileNotFoundError):
        shadowlab.sweep("no/such/scene.json", "shadow-map", **SMALL)
    with pytest.raises(TypeError):
        shadowlab.sweep(42, "shadow-map", **SMALL)


def test_two_threads_sweep_at_once(two_techniques):
    """Two sweeps at once in one process, each in its own arena (sweep()'s docstring), give
    the figures of one alone."""
    params = {"resolution": [64, 256], "filter": ["nearest", "grid"]}
    results = [None, None]

    def run(k):
        results[k] = shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], params, **{**SMALL, "threads": 2})

    threads = [threading.Thread(target=run, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    want = without_times(two_techniques.to_json())
    for r in results:
        got = without_times(r.to_json())
        assert got["grid"]["threads"] == [2]
        got["grid"]["threads"] = [1]
        for row in got["rows"]:
            row["threads"] = 1
        assert got == want


def test_without_pandas_to_dataframe_says_so(two_techniques, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="needs pandas"):
        two_techniques.to_dataframe()


def test_python_runs_while_a_sweep_does():
    """The GIL is released while the library sweeps (conftest.ticks_while)."""
    assert ticks_while(lambda: shadowlab.sweep("sphere-box", "shadow-map", {"resolution": [64, 128]}, **SMALL)) > 0
