"""Reference counting and ownership. No leak over 1,000 tiny frames (RSS and tracemalloc
bounds; not under ASan, since Python under ASan needs the runtime LD_PRELOADed and reports the
interpreter's own allocations as leaks, and the sanitizer builds leave the module out). And a
scene, a frame and a history outlive the prepared scene they came from."""
import gc
import tracemalloc
import weakref

import numpy as np

import shadowlab
from conftest import tiny_scene


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def frame_round(prepared, reference):
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 16}, threads=1)
    figures = shadowlab.score(reference, frame)
    views = (frame.visibility, frame.radiance, frame.passes[0].visibility, frame.srgb())
    return figures.rms + float(views[0].sum()) + len(frame.stats) + len(figures.as_dict())


def test_a_thousand_frames_leak_nothing():
    prepared = shadowlab.prepare(tiny_scene(width=8, height=8))
    reference = shadowlab.reference(prepared)
    for _ in range(100):   # warm up: the allocator's pools, TBB's threads, pybind11's type caches
        frame_round(prepared, reference)
    gc.collect()
    tracemalloc.start()
    rss_before, traced_before = resident_bytes(), tracemalloc.get_traced_memory()[0]
    for _ in range(1000):
        frame_round(prepared, reference)
    gc.collect()
    traced_growth = tracemalloc.get_traced_memory()[0] - traced_before
    tracemalloc.stop()
    rss_growth = resident_bytes() - rss_before
    # Measured: 6 KB traced and no RSS growth. 1,000 leaked Frames (kept in a list) grow the
    # traced memory by 64 KB (their Python objects) and RSS by 9 MB (their 8 x 8 buffers), so
    # a leak of one Python object or one frame's buffers per frame fails a bound.
    assert traced_growth < 32 * 1024, traced_growth
    assert rss_growth < 4 * 1024 * 1024, rss_growth


def test_a_frame_dies_with_its_last_reference():
    prepared = shadowlab.prepare(tiny_scene(width=8, height=8))
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 16})
    expected = frame.visibility.copy()
    alive = [weakref.ref(frame), weakref.ref(prepared)]
    del prepared
    gc.collect()
    assert alive[1]() is None   # a Frame does not hold its scene
    passes = frame.passes
    del frame
    gc.collect()
    assert alive[0]() is None   # nor a LightPass the Python Frame: it holds the frame's buffers
    assert np.array_equal(passes[0].visibility, expected)


def test_scene_frame_and_history_outlive_their_prepared_scene():
    prepared = shadowlab.prepare(tiny_scene(width=16, height=10))
    history = shadowlab.FrameHistory()
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64, "temporal": True}, history=history)
    scene = prepared.scene
    expected = frame.visibility.copy()
    del prepared
    gc.collect()
    assert history.frames == 1 and scene.camera.width == 16 and np.array_equal(frame.visibility, expected)
    # The history holds the prepared scene: its next frame is the sequence's second.
    second = shadowlab.render(history.prepared, "shadow-map", {"resolution": 64, "temporal": True}, history=history)
    assert history.frames == 2 and second.motion is not None
    assert shadowlab.prepare(scene).scene.name == scene.name
    assert np.array_equal(frame.visibility, expected)


def test_a_history_belongs_to_one_series():
    first = shadowlab.prepare(tiny_scene(width=8, height=8))
    other = shadowlab.prepare(tiny_scene(width=8, height=8))
    history = shadowlab.FrameHistory()
    shadowlab.render(first, "shadow-map", {"resolution": 16}, history=history)
    second = shadowlab.render(first, "shadow-map", {"resolution": 16}, history=history)
    assert second.motion is not None and second.motion.shape == (8, 8, 2)
    try:
        shadowlab.render(other, "shadow-map", {"resolution": 16}, history=history)
        raise AssertionError("a history took a frame of another scene")
    except RuntimeError as error:
        assert "keep one history per series" in str(error)


def test_a_history_keeps_the_scene_of_its_frames_not_of_a_failed_first():
    failed = shadowlab.prepare(tiny_scene(width=8, height=8))
    history = shadowlab.FrameHistory()
    try:   # sphere-box has no environment map: the first frame fails
        shadowlab.render(failed, "env-additive", history=history)
        raise AssertionError("env-additive rendered a scene without an environment map")
    except ValueError:
        pass
    assert history.frames == 0 and history.prepared is None
    prepared = shadowlab.prepare(tiny_scene(width=8, height=8))
    shadowlab.render(prepared, "shadow-map", {"resolution": 16}, history=history)
    assert history.prepared is prepared   # was `failed`, and nothing kept `prepared` alive
