"""The GIL is released while the library renders: a busy Python thread makes progress while
another thread is inside render(), and two Python threads render at once, each on its own
TBB arena, with the bytes of a frame rendered alone. Progress is counted in ticks of the busy
thread, never in seconds."""
import sys
import threading
import time

import numpy as np

import shadowlab
from conftest import tiny_scene


def ticks_while_rendering(prepared):
    """Ticks of this thread while another renders. With a switch interval too long to ever
    expire, no thread is made to give up the GIL: this one waits in start() until the renderer
    releases it, and the renderer, once done, waits for this one's sleep. A render that held
    the GIL would run to its end first and leave 0 ticks; one that releases it leaves at least 1."""
    done = threading.Event()
    ticks = 0

    def renderer():
        shadowlab.render(prepared, "reference-soft", threads=1)
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        thread = threading.Thread(target=renderer)
        thread.start()
        while not done.is_set():
            ticks += 1
            time.sleep(1e-4)   # hands the GIL to the renderer once it is done
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    return ticks


def test_a_python_thread_runs_while_another_renders(prepared):
    assert ticks_while_rendering(prepared) > 0


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
