"""The GIL is released while the library renders: a busy Python thread makes progress while
another thread is inside render(), and two Python threads render at once, each on its own
TBB arena, with the bytes of a frame rendered alone. Progress is counted in ticks of the busy
thread, never in seconds."""
import threading

import numpy as np

import shadowlab
from conftest import ticks_while, tiny_scene


def test_the_tick_count_sees_a_thread_that_holds_the_gil():
    """The instrument itself: Python work, which keeps the GIL, leaves no tick."""
    assert ticks_while(lambda: sum(range(2_000_000))) == 0


def test_a_python_thread_runs_while_another_renders(prepared):
    assert ticks_while(lambda: shadowlab.render(prepared, "reference-soft", threads=1)) > 0


def test_two_threads_render_at_once_with_the_bytes_of_one():
    prepared = shadowlab.prepare(tiny_scene())
    alone = shadowlab.render(prepared, "pcss", threads=1).radiance.copy()
    results, errors = {}, []

    def renderer(name, threads):
        try:
            for _ in range(3):
                results[name] = shadowlab.render(prepared, "pcss", threads=threads).radiance
        except Exception as error:   # a failure in a thread must fail the test, not vanish
            errors.append(error)

    threads = [threading.Thread(target=renderer, args=(k, k + 1)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert all(np.array_equal(results[k], alone) for k in range(2))


def test_moving_the_camera_waits_for_the_frames_rendering():
    """A camera set from one thread while another renders: each frame sees one camera whole."""
    prepared = shadowlab.prepare(tiny_scene())
    near = prepared.camera
    far = near.replace(eye=(0.0, 6.0, 14.0))
    expected = {}
    for name, camera in (("near", near), ("far", far)):
        prepared.camera = camera
        expected[name] = shadowlab.render(prepared, "shadow-map", {"resolution": 64}).visibility.copy()
    frames = []

    def renderer():
        for _ in range(6):
            frames.append(shadowlab.render(prepared, "shadow-map", {"resolution": 64}).visibility)

    thread = threading.Thread(target=renderer)
    thread.start()
    for k in range(12):
        prepared.camera = far if k % 2 else near
    thread.join()
    assert all(any(np.array_equal(v, e) for e in expected.values()) for v in frames)
