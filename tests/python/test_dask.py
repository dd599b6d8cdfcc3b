"""sweep(client=...) on a Dask cluster of two worker processes (which import shadowlab from
PYTHONPATH, as a cluster's would from its installation): the shards' merge equals the sweep
run here in everything but the measured times, as merge-sweep's does."""
import json
import os

import pytest

import shadowlab

distributed = pytest.importorskip("distributed")

SMALL = {"threads": 1, "runs": 1, "warmup": 0, "width": 64, "height": 48}
PARAMS = {"resolution": [64, 128, 256]}


def without_times(text):
    def strip(value):
        if isinstance(value, dict):
            return {k: strip(v) for k, v in value.items() if not k.endswith("_ms")}
        return [strip(v) for v in value] if isinstance(value, list) else value
    return strip(json.loads(text))


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_the_clusters_merge_is_the_sweep_run_here(client):
    here = shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], PARAMS, **SMALL)
    # Default: one shard per worker.
    spread = shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], PARAMS, client=client, **SMALL)
    assert spread.shard == (1, 1) and len(spread.rows) == 6
    assert without_times(spread.to_json()) == without_times(here.to_json())
    # More shards than workers; a scene file's path, made absolute for the workers.
    path = os.path.relpath(os.path.join(shadowlab.scene_dir(), "sphere-box.json"))
    three = shadowlab.sweep(path, ["shadow-map", "pcss"], PARAMS, client=client, shards=3, **SMALL)
    assert without_times(three.to_json()) == without_times(here.to_json())


def test_a_dict_scene_is_sent_as_a_dict(client):
    with open(os.path.join(shadowlab.scene_dir(), "sphere-box.json")) as f:
        scene = json.load(f)
    here = shadowlab.sweep(scene, "shadow-map", PARAMS, **SMALL)
    spread = shadowlab.sweep(scene, "shadow-map", PARAMS, client=client, **SMALL)
    assert without_times(spread.to_json()) == without_times(here.to_json())
    with pytest.raises(TypeError, match="not sent"):
        shadowlab.sweep(shadowlab.load_scene(scene), "shadow-map", PARAMS, client=client, **SMALL)


def test_a_bad_sweep_fails_with_the_librarys_error(client):
    with pytest.raises(ValueError, match="only 6 settings"):
        shadowlab.sweep("sphere-box", ["shadow-map", "pcss"], PARAMS, client=client, shards=7, **SMALL)
    with pytest.raises(ValueError, match="resolution"):   # found by the workers' checking frames
        shadowlab.sweep("sphere-box", "shadow-map", {"resolution": [3, 64]}, client=client, **SMALL)
    with pytest.raises(ValueError, match="either shard"):
        shadowlab.sweep("sphere-box", "shadow-map", client=client, shard=(1, 2), **SMALL)
