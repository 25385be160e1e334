"""glscene from Python: a ctypes binding over libglscene (include/glscene.h,
docs/api.md, docs/python.md) that returns numpy arrays.  No compiled
extension: Debian's python3 and python3-numpy are all it needs.

    import glscene
    with glscene.Player("scene.glsb", aa=4) as player:
        cam = glscene.Camera.from_file("left.cam")
        out = player.render(cam, outputs=("image", "depth", "instance"))
    out["image"]   # H x W x 3 uint8; out["depth"]: H x W float32 Zc, inf: nothing

Every glsplay output word is an output of render, with the values of
glsplay's file; a rig (a list of cameras) gives a list of dicts;
Player.sequence walks a trajectory.  Errors raise glscene.Error with the
library's message.  A Player owns a GL context: use it only from the
thread that made it.

The library is looked for in this order: $GLSCENE_LIBRARY (a path), beside
this package, the lib/ directory of the prefix it is installed in
(PREFIX/lib/python3/dist-packages/glscene -> PREFIX/lib), the build/ of the
checkout it is in (python/glscene -> build/), then the system's
(ctypes.util.find_library)."""
import ctypes
import os
from typing import Sequence, Union

from ._lib import Error, _Error, _lib, _path, _raise
from .camera import Camera
from .player import BOX_DTYPE, COVERAGE_DTYPE, EDGE_SEGMENT_DTYPE, LANDMARK_DTYPE, POINT_DTYPE, Player

__all__ = ["Error", "Camera", "Player", "compile", "version", "BOX_DTYPE", "COVERAGE_DTYPE", "EDGE_SEGMENT_DTYPE", "LANDMARK_DTYPE", "POINT_DTYPE"]


def version() -> str:
    """The library's version (GLSCENE_VERSION)."""
    return _lib.glscene_version().decode()


def compile(scene: Union[str, os.PathLike], roots: Sequence[Union[str, os.PathLike]] = (),
            out: Union[str, os.PathLike, None] = None) -> str:
    """What glsc does: compile the scene, a .scene path, a dotted name
    found under the roots, or the text of a scene (anything holding a
    newline or a brace), with the search roots (directories or library
    bundles) into out (default: the scene's name + .glsb; for text,
    scene.glsb, its errors located as "<scene text>:line:col"); returns
    out."""
    text = isinstance(scene, str) and ("\n" in scene or "{" in scene)
    if text:
        import tempfile
        with tempfile.TemporaryDirectory(prefix="glscene-") as d:
            path = os.path.join(d, "scene.scene")
            with open(path, "w") as f:
                f.write(scene)
            try:
                return compile(path, list(roots) + [d], out if out is not None else "scene.glsb")
            except Error as e:  # the text has no file: its lines are the text's
                raise Error(str(e).replace(path, "<scene text>")) from None
    scene = os.fspath(scene)
    if out is None:
        out = os.path.splitext(os.path.basename(scene))[0].split(".")[-1] + ".glsb"
    arr = (ctypes.c_char_p * max(len(roots), 1))(*[_path(r) for r in roots])
    err = _Error()
    if _lib.glscene_compile(_path(scene), arr, len(roots), _path(out), ctypes.byref(err)):
        _raise(err)
    return os.fspath(out)
