"""Bad input is a Python exception of the right type with the library's one-line message, never
a crash: ValueError for a bad setting or scene content, FileNotFoundError for a missing file,
TypeError for a value of the wrong Python type."""
import os

import pytest

import shadowlab
from conftest import tiny_scene


def one_line(error):
    text = str(error.value)
    assert text and "\n" not in text
    return text


@pytest.mark.parametrize("params, message", [
    ({"resolution": 3}, "shadow-map: parameter resolution=3: must be an integer in 16..8192"),
    ({"bogus": 1}, "technique 'shadow-map' has no parameter 'bogus'"),
    ({"filter": "blurry"}, "filter"),
])
def test_a_bad_setting_is_a_value_error(prepared, params, message):
    with pytest.raises(ValueError) as error:
        shadowlab.render(prepared, "shadow-map", params)
    assert message in one_line(error)


@pytest.mark.parametrize("call, message", [
    (lambda p: shadowlab.render(p, "no-such-technique"), "unknown technique 'no-such-technique'"),
    (lambda p: shadowlab.render(p, "shadow-map", threads=-1), "threads must be within 0..1024"),
    (lambda p: shadowlab.render(p, "shadow-map", simd="neon"), "unknown SIMD level 'neon'"),
    (lambda p: shadowlab.load_scene("no-such-scene"), "unknown scene \"no-such-scene\""),
    (lambda p: shadowlab.load_scene({"meshes": []}), "<dict>: missing required field"),
    (lambda p: shadowlab.load_scene("sphere-box").apply_overrides(fovy_deg=200), "--fovy must be in (0, 180)"),
    (lambda p: shadowlab.load_scene("sphere-box").apply_overrides(light=3), "light"),
    (lambda p: shadowlab.Camera().replace(target=(0.0, 4.0, 9.0)), "Camera.target: the camera's eye and target"),
    (lambda p: shadowlab.Light(type="disk", radius=-1.0), "Light.radius: must be > 0, got -1"),
])
def test_bad_values_are_value_errors(prepared, call, message):
    with pytest.raises(ValueError) as error:
        call(prepared)
    assert message in one_line(error)


def test_a_missing_file_is_file_not_found(tmp_path):
    for source in [str(tmp_path / "missing.json"), tmp_path / "missing.json"]:
        with pytest.raises(FileNotFoundError) as error:
            shadowlab.load_scene(source)
        assert one_line(error).startswith(str(tmp_path / "missing.json") + ": ")


def test_a_missing_mesh_is_file_not_found(tmp_path):
    scene = {"meshes": [{"name": "m", "file": "nowhere.obj"}], "materials": [{"name": "grey"}],
             "instances": [{"mesh": "m", "material": "grey"}],
             "lights": [{"type": "point", "position": [0, 5, 0]}],
             "camera": {"eye": [0, 1, 5], "target": [0, 0, 0], "fovy": 45, "width": 8, "height": 8}}
    with pytest.raises(FileNotFoundError) as error:
        shadowlab.load_scene(scene, base_dir=tmp_path)
    assert "nowhere.obj" in one_line(error)


@pytest.mark.parametrize("call", [
    lambda p: shadowlab.load_scene(42),
    lambda p: shadowlab.render(p, "shadow-map", {"resolution": [64]}),
    lambda p: shadowlab.render(p, "shadow-map", {1: 64}),
    lambda p: shadowlab.render(p, 7),
    lambda p: shadowlab.render(None, "shadow-map"),
    lambda p: shadowlab.render(p, "shadow-map", simd=2),
    lambda p: shadowlab.score(None, None),
    lambda p: setattr(p, "camera", "front"),
    lambda p: shadowlab.Light(position=(1, 2)),
    lambda p: shadowlab.Light(positon=(1, 2, 3)),
])
def test_wrong_types_are_type_errors(prepared, call):
    with pytest.raises(TypeError):
        call(prepared)


def test_scoring_against_the_other_output_is_a_value_error():
    """A radiance frame (an environment technique) against a visibility reference of its size."""
    sky = shadowlab.load_scene(os.path.join(shadowlab.scene_dir(), "environment", "sphere-sky.json"))
    sky.apply_overrides(width=16, height=10)
    radiance = shadowlab.render(shadowlab.prepare(sky), "env-additive")
    assert radiance.output == "radiance" and radiance.visibility is None
    visibility = shadowlab.reference(shadowlab.prepare(tiny_scene(width=16, height=10)))
    with pytest.raises(ValueError) as error:
        shadowlab.score(visibility, radiance)
    one_line(error)


@pytest.mark.parametrize("score", [shadowlab.score, shadowlab.score_lights])
def test_scoring_against_a_reference_of_another_size_is_a_value_error(prepared, score):
    other = shadowlab.reference(shadowlab.prepare(tiny_scene(width=16, height=10)))
    with pytest.raises(ValueError, match=r"the reference is 16 x 10 and the frame \d+ x \d+"):
        score(other, shadowlab.render(prepared, "shadow-map"))


def test_a_path_with_a_nul_is_refused_not_cut(prepared, tmp_path):
    # The C library stops a path at its NUL: "a\0b.json" opened "a", and write_exr wrote "a".
    (tmp_path / "a").write_text("{}")
    frame = shadowlab.render(prepared, "shadow-map", threads=1)
    for call in (lambda: shadowlab.load_scene(str(tmp_path / "a\0b.json")),
                 lambda: frame.write_exr(str(tmp_path / "a\0b.exr")),
                 lambda: shadowlab.flythrough("sphere-box", "shadow-map", path=str(tmp_path / "a\0b.csv"), frames=2)):
        with pytest.raises(ValueError) as error:
            call()
        assert one_line(error) == "a path must not contain a NUL character"
    assert (tmp_path / "a").read_text() == "{}"
    frame.write_exr(tmp_path / "path-like.exr")   # an os.PathLike, as load_scene takes one
    assert (tmp_path / "path-like.exr").stat().st_size > 0


@pytest.mark.parametrize("call, error_type, escaped", [
    (lambda p: shadowlab.render(p, "shadow-map", {"resolution": "5\n12"}), ValueError, "5\\n12"),
    (lambda p: shadowlab.load_scene("/no-such-dir/a\nb.json"), FileNotFoundError, "a\\nb.json"),
])
def test_a_message_quoting_a_control_character_stays_one_line(prepared, call, error_type, escaped):
    with pytest.raises(error_type) as error:
        call(prepared)
    assert escaped in one_line(error)
