"""Frame's buffers are numpy views of the library's buffers, without a copy: two reads share
memory, a write shows through, each view's base chain ends at its Frame, and a view outlives
the Python name of its Frame. .srgb() and .debug are copies, as documented."""
import gc
import os
import weakref

import numpy as np

import shadowlab

VIEWS = ["visibility", "radiance", "position", "normal", "shading_normal", "depth", "hit", "material", "triangle"]


def base_chain_ends_at(array, owner):
    while isinstance(array, np.ndarray):
        array = array.base
    return array is owner


def test_buffers_are_views_of_the_frame(prepared):
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    for name in VIEWS:
        first, second = getattr(frame, name), getattr(frame, name)
        assert np.shares_memory(first, second), name
        assert base_chain_ends_at(first, frame), name
        assert first.flags.c_contiguous and first.flags.writeable, name
    pass_view = frame.passes[0].visibility
    assert np.shares_memory(pass_view, frame.passes[0].visibility)
    assert not np.shares_memory(frame.srgb(), frame.srgb())


def test_a_write_through_a_view_reads_back(prepared):
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    frame.visibility[3, 5] = 0.25
    frame.radiance[1, 2, 1] = 7.0
    assert frame.visibility[3, 5] == np.float32(0.25)
    assert frame.radiance[1, 2, 1] == np.float32(7.0)


def test_a_write_to_the_frames_v_is_what_score_reads(prepared):
    # Frame.visibility was the library's copy of the first pass's V, which score() does not
    # read: writing to it changed nothing that was scored or written.
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    reference = shadowlab.reference(prepared)
    assert np.shares_memory(frame.visibility, frame.passes[0].visibility)
    before = shadowlab.score(frame, reference).rms
    frame.visibility[...] = 1.0 - reference.visibility
    assert shadowlab.score(frame, reference).rms > before + 0.5


def test_a_view_keeps_its_frame_alive(prepared):
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    expected = frame.visibility.copy()
    view, light_view = frame.visibility, frame.passes[0].visibility
    alive = weakref.ref(frame)
    del frame
    gc.collect()
    assert alive() is not None   # the views hold it
    garbage = [np.full(expected.shape, 9.0, np.float32) for _ in range(50)]   # reuse freed memory, if any were
    assert np.array_equal(view, expected) and np.array_equal(light_view, expected)
    del view, light_view, garbage
    gc.collect()
    assert alive() is None   # and no more than that


def test_debug_buffers_are_copies_read_back(prepared):
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64}, debug=True)
    debug = frame.debug
    assert debug["shadow-map-depth"].shape == (64, 64) and debug["shadow-map-depth"].dtype == np.float32
    assert not np.shares_memory(debug["shadow-map-depth"], frame.debug["shadow-map-depth"])
    assert shadowlab.render(prepared, "shadow-map", {"resolution": 64}).debug == {}


def test_a_frame_of_several_lights_has_a_pass_per_light():
    scene = shadowlab.load_scene(os.path.join(shadowlab.scene_dir(), "many-lights", "three-lights.json"))
    scene.apply_overrides(width=24, height=16)
    prepared = shadowlab.prepare(scene)
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 32}, debug=True)
    assert [p.light for p in frame.passes] == [0, 1, 2]
    assert np.array_equal(frame.visibility, frame.passes[0].visibility)
    assert not np.shares_memory(frame.passes[1].visibility, frame.passes[2].visibility)
    assert "light0_resolution_texels" in frame.stats and "resolution_texels" in frame.passes[1].stats
    assert {name.split("/")[0] for name in frame.debug} == {"light0", "light1", "light2"}
    per_light = shadowlab.score_lights(shadowlab.reference(prepared), frame)
    assert [f.channel for f in per_light] == ["light0.V", "light1.V", "light2.V"]
