"""shadowlab from Python: load and prepare scenes, render a frame with a shadow technique,
read its buffers as numpy arrays, score it against the exact reference, and run sweeps and
fly-throughs (docs/python.md)."""

import os

from . import _shadowlab
from ._shadowlab import (  # noqa: F401  (the library's types and functions)
    __version__, Camera, ErrorFigures, Frame, FrameHistory, Light, LightPass, Param, PreparedScene, Scene,
    Technique, prepare, reference, render, score, score_lights, technique, techniques)


def data_dir():
    """The data folder (scenes/, meshes/, textures/...): the installed one beside this package
    (<prefix>/share/shadowlab) if it exists, as the installed command finds it beside itself;
    otherwise the source tree's assets/ the module was compiled with."""
    installed = os.path.normpath(os.path.join(os.path.dirname(__file__), _shadowlab._data_dir_from_package))
    if os.path.isdir(os.path.join(installed, "scenes")):
        return installed
    return _shadowlab._compiled_data_dir


def scene_dir():
    """The built-in scene directory: $SHADOWLAB_SCENE_DIR if set and not empty, else
    data_dir()/scenes (docs/scene-format.md, "Finding scenes")."""
    return os.environ.get("SHADOWLAB_SCENE_DIR") or os.path.join(data_dir(), "scenes")


def scene_names():
    """The built-in scenes' names, sorted: what load_scene() takes as a name."""
    return _shadowlab._scene_names(scene_dir())


def load_scene(source, *, base_dir=None):
    """A Scene from a built-in scene's name (scene_names()), a path (str or os.PathLike; a
    scene file .json, or a glTF file .gltf/.glb), a dict in the scene format's shape
    (docs/scene-format.md; its mesh paths relative to base_dir, default the working
    directory), or a Scene (copied). A str is a path when it ends in .json, .gltf or .glb or
    contains a '/'. FileNotFoundError for a file that does not exist, ValueError for an
    invalid one (the library's one-line message: the file, the field, the problem),
    TypeError for another type."""
    return _shadowlab._load_scene(source, base_dir, scene_dir())


from .sweeps import (FlythroughFrame, FlythroughResults, FlythroughSeries, SweepResults, SweepRow,  # noqa: E402,F401
                     flythrough, merge_sweeps, sweep)
