"""Scenes from every source load_scene() takes, their camera and lights, and moving them in a
prepared scene: the frame of a moved camera or light is the frame of a scene prepared with it."""
import copy
import json
import pathlib

import numpy as np
import pytest

import shadowlab
from conftest import tiny_scene


def test_built_in_scenes_are_listed_and_load():
    names = shadowlab.scene_names()
    assert "sphere-box" in names and names == sorted(names)
    assert pathlib.Path(shadowlab.scene_dir(), "sphere-box.json").is_file()
    scene = shadowlab.load_scene("sphere-box")
    assert scene.name == "sphere-box" and len(scene.lights) >= 1 and scene.triangle_count > 0


def test_a_path_a_pathlike_and_a_dict_give_the_same_scene(tmp_path):
    path = pathlib.Path(shadowlab.scene_dir(), "sphere-box.json")
    by_path, by_pathlike = shadowlab.load_scene(str(path)), shadowlab.load_scene(path)
    by_dict = shadowlab.load_scene(json.loads(path.read_text()), base_dir=path.parent)
    assert by_dict.name == "<dict>"
    for scene in (by_pathlike, by_dict):
        assert scene.camera == by_path.camera and scene.instance_names == by_path.instance_names
        assert scene.triangle_count == by_path.triangle_count
    assert shadowlab.load_scene(by_path) is not by_path   # a Scene is copied


def test_the_camera_and_lights_are_values_assigned_whole():
    scene = shadowlab.load_scene("sphere-box")
    scene.camera = scene.camera.replace(width=33)
    assert scene.camera.width == 33
    scene.lights = [light.replace(position=(1.0, 9.0, 2.0)) for light in scene.lights]
    assert scene.lights[0].position == (1.0, 9.0, 2.0)
    other = copy.copy(scene)
    other.camera = other.camera.replace(width=12)
    assert scene.camera.width == 33


def test_overrides_act_as_the_commands():
    scene = shadowlab.load_scene("sphere-box")
    scene.apply_overrides(width=20, height=10, eye=(0, 3, 7), fovy_deg=50, light_position=(2, 6, 1), light_radius=0.3)
    assert (scene.camera.width, scene.camera.height, scene.camera.fovy_deg) == (20, 10, 50)
    assert scene.camera.eye == (0, 3, 7) and scene.lights[0].position == (2, 6, 1)
    assert scene.lights[0].radius == np.float32(0.3)   # a float32 field


def test_moving_a_prepared_scenes_camera_and_light_renders_as_preparing_it_moved():
    moved = tiny_scene()
    moved.apply_overrides(eye=(1.0, 5.0, 8.0), light_position=(3.0, 7.0, 2.0))
    expected = shadowlab.render(shadowlab.prepare(moved), "pcss")
    prepared = shadowlab.prepare(tiny_scene())
    prepared.camera = moved.camera
    prepared.lights = moved.lights
    assert prepared.scene.camera == moved.camera
    assert np.array_equal(shadowlab.render(prepared, "pcss").radiance, expected.radiance)


def test_techniques_carry_typed_parameters():
    names = [t.name for t in shadowlab.techniques()]
    assert "shadow-map" in names and "reference" in names
    shadow_map = shadowlab.technique("shadow-map")
    assert shadow_map.output == "visibility" and shadow_map.reference == "reference"
    params = {p.name: p for p in shadow_map.params}
    resolution = params["resolution"]
    assert resolution.type == "integer" and isinstance(resolution.default, int)
    assert (resolution.min, resolution.max) == (16, 8192) and "16..8192" in resolution.help
    assert params["filter"].type == "choice" and "bilinear" in params["filter"].choices
    assert params["temporal"].type == "flag" and params["temporal"].default is False
    assert isinstance(params["constant-bias"].default, float) and params["filter"].min is None
    assert shadowlab.technique("pcss").reference == "reference-soft"
    assert any(t.output == "radiance" for t in shadowlab.techniques())


def test_moving_an_instance_renders_as_preparing_it_moved():
    scene = tiny_scene()
    name = scene.instance_names[-1]
    transform = scene.instance_transforms[name]
    transform[:3, 3] += np.float32([0.5, 0.0, -0.25])   # translated, acting on column vectors
    prepared = shadowlab.prepare(scene)
    shadowlab.render(prepared, "shadow-map", {"resolution": 64})   # a frame before the move
    assert prepared.set_instance_transforms({name: transform}) == 1
    assert prepared.geometry_version == 1
    assert np.array_equal(prepared.scene.instance_transforms[name], transform)
    moved = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    with pytest.raises(ValueError):
        prepared.set_instance_transforms({"no-such-instance": transform})
    with pytest.raises(TypeError):
        prepared.set_instance_transforms({name: [[1, 0], [0, 1]]})

    # The same move before any frame: nothing derived from the old place survives it.
    again = shadowlab.prepare(tiny_scene())
    again.set_instance_transforms({name: transform})
    assert np.array_equal(shadowlab.render(again, "shadow-map", {"resolution": 64}).visibility, moved.visibility)
    unmoved = shadowlab.render(shadowlab.prepare(tiny_scene()), "shadow-map", {"resolution": 64})
    assert not np.array_equal(unmoved.visibility, moved.visibility)


def test_gltf_files_load_by_path():
    corpus = pathlib.Path(__file__).resolve().parents[1] / "fuzz" / "corpus" / "gltf_file"
    text, binary = shadowlab.load_scene(corpus / "lit_mask.gltf"), shadowlab.load_scene(str(corpus / "lit_mask.glb"))
    assert len(text.instance_names) == len(binary.instance_names) == 2   # named after their file's nodes
    assert text.triangle_count == binary.triangle_count and len(text.lights) == len(binary.lights) == 2
    assert text.camera == binary.camera
