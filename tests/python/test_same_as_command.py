"""A frame rendered and scored from Python is the command's frame: the same EXR bytes as
`render --aov`, the same pixels as its PNG, and the same settings and figures as its JSON."""
import json

import numpy as np
import pytest

import shadowlab
from conftest import HEIGHT, WIDTH, read_png, run_command, tiny_scene

# A hard-shadow technique at a resolution with errors to score, and a soft one (reference-soft).
CASES = [("shadow-map", {"resolution": 32, "filter": "bilinear"}), ("pcss", {})]


def command_text(value):
    return {True: "on", False: "off"}.get(value, str(value))


@pytest.mark.parametrize("technique, params", CASES)
def test_render_and_score_match_the_command(tmp_path, technique, params):
    run_command("render", "sphere-box", "--technique", technique, "--width", str(WIDTH), "--height", str(HEIGHT),
                *[a for k, v in params.items() for a in ("--param", f"{k}={command_text(v)}")],
                "-o", "command.png", "--aov", "command.exr", "--error-map", "map.png", "--json", "command.json",
                "--threads", "1", cwd=tmp_path)
    prepared = shadowlab.prepare(tiny_scene())
    frame = shadowlab.render(prepared, technique, params, threads=2)
    frame.write_exr(str(tmp_path / "python.exr"))
    assert (tmp_path / "python.exr").read_bytes() == (tmp_path / "command.exr").read_bytes()
    assert np.array_equal(frame.srgb(), read_png(tmp_path / "command.png"))

    expected = json.loads((tmp_path / "command.json").read_text())
    assert frame.settings == expected["settings"]
    assert {k: v for k, v in frame.stats.items() if not k.endswith("_ms")} == \
        {k: v for k, v in expected["stats"].items() if not k.endswith("_ms")}
    reference = shadowlab.reference(prepared, shadowlab.technique(technique).reference)
    assert expected["reference"] == shadowlab.technique(technique).reference
    figures = shadowlab.score(reference, frame)
    assert figures.as_dict() == expected["errors"]
    assert figures.rms == expected["errors"]["rms"] and figures.flip_mean == expected["errors"]["flip_mean"]
    assert json.loads(figures.to_json()) == expected["errors"]


def test_a_frame_has_the_exr_channels(prepared, tmp_path):
    """The arrays are the EXR's channels: V, P, N, depth and hit as the command writes them."""
    frame = shadowlab.render(prepared, "shadow-map", {"resolution": 64})
    assert frame.visibility.shape == (HEIGHT, WIDTH) and frame.visibility.dtype == np.float32
    assert frame.radiance.shape == frame.position.shape == frame.normal.shape == (HEIGHT, WIDTH, 3)
    assert frame.hit.dtype == np.uint8 and frame.depth.shape == (HEIGHT, WIDTH)
    hit = frame.hit == 1
    assert 0 < hit.sum() < hit.size
    assert np.all(frame.depth[~hit] == 1.0) and np.all(frame.visibility[~hit] == 0.0)
    assert np.allclose(np.linalg.norm(frame.normal[hit], axis=-1), 1.0, atol=1e-5)
    assert frame.motion is None and frame.stencil is None
    assert [p.light for p in frame.passes] == [0]
    assert np.array_equal(frame.passes[0].visibility, frame.visibility)


def test_every_simd_level_and_thread_count_gives_the_same_bytes(prepared):
    """The library's determinism holds through the module: simd= and threads= change no bit."""
    frames = [shadowlab.render(prepared, "pcss", simd=simd, threads=threads)
              for simd, threads in ((None, 0), ("scalar", 1), ("auto", 3))]
    for frame in frames[1:]:
        assert np.array_equal(frame.radiance, frames[0].radiance)
        assert np.array_equal(frame.visibility, frames[0].visibility)
