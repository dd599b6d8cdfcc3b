"""Camera and Light are immutable values, as frozen dataclasses: a field is never written in
place (an AttributeError naming the fix), replace() gives a changed copy, and every value made
is checked by the scene format's rules (scenes/view_rules.h), so that no camera or light the
scene file would refuse reaches the renderer."""
import copy
import pickle

import numpy as np
import pytest

import shadowlab
from conftest import HEIGHT, WIDTH, tiny_scene


def one_line(error):
    text = str(error.value)
    assert text and "\n" not in text
    return text

CAMERA_FIELDS = ["eye", "target", "up", "fovy_deg", "width", "height", "near", "far"]
LIGHT_FIELDS = ["type", "position", "direction", "cone_angle", "inner_cone_angle", "range", "radius",
                "half_edge_u", "half_edge_v", "angular_diameter", "intensity"]


def holders(prepared):
    """Every place a Camera or Light is read from: made, a Scene's, a PreparedScene's."""
    scene = tiny_scene()
    return [("camera", shadowlab.Camera(), CAMERA_FIELDS), ("camera", scene.camera, CAMERA_FIELDS),
            ("camera", prepared.camera, CAMERA_FIELDS), ("light", shadowlab.Light(), LIGHT_FIELDS),
            ("light", scene.lights[0], LIGHT_FIELDS), ("light", prepared.lights[0], LIGHT_FIELDS)]


def test_writing_any_field_is_an_attribute_error_naming_the_fix(prepared):
    for name, value, fields in holders(prepared):
        for field in fields:
            before = getattr(value, field)
            with pytest.raises(AttributeError) as error:
                setattr(value, field, before)
            assert f"is a value: use {name}.replace({field}=" in one_line(error)
            assert "and assign it back" in one_line(error)
    with pytest.raises(AttributeError):
        shadowlab.Camera().colour = 3   # no field of that name either


def test_replace_gives_a_new_value_and_leaves_the_old(prepared):
    camera = prepared.camera
    wider = camera.replace(width=2 * WIDTH, fovy_deg=60.0)
    assert (camera.width, camera.fovy_deg) == (WIDTH, 45.0)
    assert (wider.width, wider.fovy_deg, wider.eye) == (2 * WIDTH, 60.0, camera.eye)
    assert prepared.camera == camera != wider
    light = shadowlab.Light(type="disk", radius=0.5, direction=(0.0, -2.0, 0.0))
    smaller = light.replace(radius=0.25)
    assert (light.radius, smaller.radius, smaller.direction) == (0.5, 0.25, (0.0, -1.0, 0.0))   # normalised
    assert light.replace() == light and light.replace() is not light


def test_values_compare_hash_copy_and_pickle(prepared):
    for value in [prepared.camera, prepared.lights[0], shadowlab.Light(type="spot", inner_cone_angle=10.0)]:
        assert copy.copy(value) == value == copy.deepcopy(value) == pickle.loads(pickle.dumps(value))
        assert hash(value) == hash(value.replace())
        assert repr(value).startswith(type(value).__name__ + "(") and "=" in repr(value)
    assert len({shadowlab.Camera(), shadowlab.Camera(), shadowlab.Camera(width=8)}) == 2


def test_a_field_must_exist_and_have_its_type():
    with pytest.raises(TypeError, match='Camera has no field "widht"'):
        shadowlab.Camera(widht=8)
    with pytest.raises(TypeError, match="Light.radius: cannot be str"):
        shadowlab.Light(radius="big")
    with pytest.raises(ValueError, match="unknown light type"):
        shadowlab.Light(type="area")


# One case per rule: the value's keyword arguments and the one-line message (the scene file's
# wording, with Python's field name).
INVALID_CAMERAS = [
    (dict(width=0), "Camera.width: must be in [1, 8192], got 0"),
    (dict(height=9000), "Camera.height: must be in [1, 8192], got 9000"),
    (dict(fovy_deg=180.0), "Camera.fovy_deg: must be in (0, 180), got 180"),
    (dict(near=0.0), "Camera.near: must be > 0, got 0"),
    (dict(near=5.0, far=2.0), "Camera.far: near must be less than far"),
    (dict(eye=(float("nan"), 0.0, 0.0)), "Camera.eye: must be in [-1e+06, 1e+06], got nan"),
    (dict(target=(0.0, 4.0, 9.0)), "Camera.target: the camera's eye and target must differ"),
    (dict(up=(0.0, 0.0, 0.0)), "Camera.up: up must not be zero or parallel to the viewing direction"),
]
INVALID_LIGHTS = [
    (dict(position=(0.0, float("inf"), 0.0)), "Light.position: must be in [-1e+06, 1e+06], got inf"),
    (dict(type="point", range=-1.0), "Light.range: must be >= 0, got -1"),
    (dict(intensity=(1.0, -0.5, 1.0)), "Light.intensity: color * power must be >= 0, got -0.5"),
    (dict(intensity=(float("nan"), 1.0, 1.0)), "Light.intensity: color * power must be >= 0, got nan"),
    (dict(type="spot", direction=(0.0, 0.0, 0.0)), "Light.direction: must not be the zero vector"),
    (dict(type="spot", cone_angle=0.0), "Light.cone_angle: must be in (0, 90], got 0"),
    (dict(type="spot", cone_angle=120.0), "Light.cone_angle: must be in (0, 90], got 120"),
    (dict(type="spot", cone_angle=20.0, inner_cone_angle=20.0), "Light.inner_cone_angle: must be in [0, 20), got 20"),
    (dict(type="directional", direction=(0.0, float("nan"), 0.0)), "Light.direction: must not be the zero vector"),
    (dict(type="directional", angular_diameter=180.0), "Light.angular_diameter: must be in [0, 180), got 180"),
    (dict(type="disk", radius=0.0), "Light.radius: must be > 0, got 0"),
    (dict(type="disk", radius=-1.0), "Light.radius: must be > 0, got -1"),
    (dict(type="disk", radius=1.0, direction=(0.0, 0.0, 0.0)), "Light.direction: must not be the zero vector"),
    (dict(type="rectangle", half_edge_u=(1.0, 0.0, 0.0), half_edge_v=(2.0, 0.0, 0.0)),
     "Light.half_edge_v: the rectangle has zero area"),
    (dict(type="rectangle", half_edge_u=(1.0, 0.0, 0.0), half_edge_v=(1.0, 1.0, 0.0)),
     "Light.half_edge_v: must be perpendicular to halfEdgeU"),
]


@pytest.mark.parametrize("fields, message", INVALID_CAMERAS)
def test_an_invalid_camera_is_a_value_error_where_it_is_made(prepared, fields, message):
    for make in (lambda: shadowlab.Camera(**fields), lambda: prepared.camera.replace(**fields)):
        with pytest.raises(ValueError) as error:
            make()
        assert message in one_line(error)


@pytest.mark.parametrize("fields, message", INVALID_LIGHTS)
def test_an_invalid_light_is_a_value_error_where_it_is_made(prepared, fields, message):
    for make in (lambda: shadowlab.Light(**fields), lambda: prepared.lights[0].replace(**fields)):
        with pytest.raises(ValueError) as error:
            make()
        assert message in one_line(error)


def test_a_light_type_checks_only_the_fields_it_reads():
    """A sun has no position, and a point light no radius: their values there are not its concern."""
    shadowlab.Light(type="directional", position=(0.0, float("nan"), 0.0))
    shadowlab.Light(type="point", radius=-1.0, cone_angle=400.0)


def test_an_unpickled_value_is_checked(prepared):
    state = prepared.lights[0].__getstate__()
    state["radius"] = -2.0
    light = shadowlab.Light.__new__(shadowlab.Light)
    with pytest.raises(ValueError, match="Light.radius: must be > 0, got -2"):
        light.__setstate__(state)


def test_the_scene_file_and_python_word_a_light_rule_alike():
    """One rule in one place: a scene file's spot with its inner cone at the cone fails as a Light does."""
    scene = {"meshes": [{"name": "m", "procedural": "grid", "size": [4, 4], "divisions": [1, 1]}], "materials": [{"name": "grey"}],
             "instances": [{"mesh": "m", "material": "grey"}],
             "lights": [{"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "coneAngle": 20,
                         "innerConeAngle": 20, "power": 10}],
             "camera": {"eye": [0, 1, 5], "target": [0, 0, 0], "fovy": 45, "width": 8, "height": 8}}
    with pytest.raises(ValueError) as error:
        shadowlab.load_scene(scene)
    assert "lights[0].innerConeAngle: must be in [0, 20), got 20" in one_line(error)


def test_too_many_lights_are_refused(prepared):
    with pytest.raises(ValueError, match="17 lights, more than the limit of 16"):
        prepared.lights = [shadowlab.Light()] * 17
    scene = tiny_scene()
    with pytest.raises(ValueError, match="17 lights"):
        scene.lights = [shadowlab.Light()] * 17


def test_a_camera_assigned_to_a_prepared_scene_changes_the_next_frame():
    prepared = shadowlab.prepare(tiny_scene())
    before = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    prepared.camera = prepared.camera.replace(width=2 * WIDTH)
    wider = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    assert before.visibility.shape == (HEIGHT, WIDTH) and wider.visibility.shape == (HEIGHT, 2 * WIDTH)
    assert prepared.scene.camera.width == 2 * WIDTH


def test_lights_assigned_to_a_prepared_scene_change_the_next_frame():
    """A light moved by replace() and assigned back renders as a scene prepared with it."""
    scene = tiny_scene()
    prepared = shadowlab.prepare(scene)
    before = shadowlab.render(prepared, "shadow-map", {"resolution": 64}).visibility.copy()
    moved = [light.replace(position=(-3.0, 6.0, 2.0)) for light in prepared.lights]
    prepared.lights = moved
    after = shadowlab.render(prepared, "shadow-map", {"resolution": 64}).visibility
    scene.lights = moved
    expected = shadowlab.render(shadowlab.prepare(scene), "shadow-map", {"resolution": 64}).visibility
    assert not np.array_equal(before, after) and np.array_equal(after, expected)
