"""The player: a compiled scene rendered through a camera or a rig, one
frame or a trajectory's frames, into numpy arrays keyed by glsplay's output
words.  Each render is a run of the library's player (glscene_play_render,
include/glscene.h): the same options, plan, passes and arrays as glsplay's
files; what is done here is turning the library's arrays into numpy's and
its text into records.  The player keeps the run of its last settings open
(the library keeps its bundle, GL context and uploaded scene across
frames), so a sequence or repeated renders load the scene once."""
import csv
import ctypes
import io
import json
import os
from typing import Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from ._lib import Error, _Array, _Buffers, _Error, _Options, _doubles, _lib, _path, _raise
from .camera import Camera

Outputs = Dict[str, object]
Rig = Union[Camera, Sequence[Camera]]

_BACKENDS = {"auto": 0, "egl": 1, "osmesa": 2}
_PATTERNS = {"lattice": 0, "grid": 1, "stratified": 2}
# what glscene_render draws into caller buffers: name -> (field, dtype, channels)
_DIRECT = {"image": ("rgb8", np.uint8, 3), "image_float": ("rgbf", np.float32, 3),
           "depth": ("depth", np.float32, 1), "instance": ("instance", np.uint32, 1),
           "normals": ("normals", np.float32, 3)}
_DTYPES = {1: np.uint8, 2: np.uint16, 3: np.float32}
_TEXT, _BYTES = 4, 5

# landmarks_F.csv's columns (spec/outputs.md "Landmarks")
LANDMARK_DTYPE = np.dtype([("name", object), ("path", object), ("X", "f8"), ("Y", "f8"), ("Z", "f8"),
                           ("u", "f8"), ("v", "f8"), ("depth", "f8"), ("in_image", "?"), ("visible", "?")])
# boxes_F.txt's KITTI object label fields (spec/outputs.md "Boxes")
BOX_DTYPE = np.dtype([("type", object), ("truncated", "f8"), ("occluded", "i4"), ("alpha", "f8"),
                      ("bbox", "f8", (4,)), ("dimensions", "f8", (3,)), ("location", "f8", (3,)),
                      ("rotation_y", "f8")])
# coverage (--aa exact): each instance's exact visible area in a pixel
COVERAGE_DTYPE = np.dtype([("x", "<i4"), ("y", "<i4"), ("id", "<u2"), ("area", "<f8")])
# edge_segments (--aa exact): a visible edge's piece, in pixel coordinates,
# with the instance ids on its left and right
EDGE_SEGMENT_DTYPE = np.dtype([("x0", "<f8"), ("y0", "<f8"), ("x1", "<f8"), ("y1", "<f8"), ("left", "<u2"),
                               ("right", "<u2")])
POINT_DTYPE = np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("red", "u1"), ("green", "u1"),
                        ("blue", "u1")])


def _landmarks(text: str) -> np.ndarray:
    rows = list(csv.reader(io.StringIO(text)))[1:]
    out = np.zeros(len(rows), dtype=LANDMARK_DTYPE)
    for i, r in enumerate(rows):
        num = [float(x) if x != "" else np.nan for x in r[2:8]]
        out[i] = (r[0], r[1], *num, r[8] == "1", r[9] == "1")
    return out


def _boxes(text: str) -> np.ndarray:
    rows = [line.split() for line in text.splitlines() if line.strip()]
    out = np.zeros(len(rows), dtype=BOX_DTYPE)
    for i, f in enumerate(rows):
        v = [float(x) for x in f[-14:]]
        out[i] = (" ".join(f[:-14]), v[0], int(v[1]), v[2], v[3:7], v[7:10], v[10:13], v[13])
    return out


def _coverage(text: str) -> np.ndarray:
    rows = list(csv.reader(io.StringIO(text)))[1:]
    out = np.zeros(len(rows), dtype=COVERAGE_DTYPE)
    for i, r in enumerate(rows):
        out[i] = (int(r[0]), int(r[1]), int(r[2]), float(r[3]))
    return out


def _edge_segments(text: str) -> np.ndarray:
    rows = list(csv.reader(io.StringIO(text)))[1:]
    out = np.zeros(len(rows), dtype=EDGE_SEGMENT_DTYPE)
    for i, r in enumerate(rows):
        out[i] = (float(r[0]), float(r[1]), float(r[2]), float(r[3]), int(r[4]), int(r[5]))
    return out


def _points(data: bytes) -> np.ndarray:
    end = data.index(b"end_header\n") + len(b"end_header\n")
    return np.frombuffer(data[end:], dtype=POINT_DTYPE).copy()


def _decode(name: str, a: _Array):
    """The library's array as numpy's (a copy), its text as records."""
    raw = ctypes.string_at(a.data, a.bytes)
    if a.dtype == _BYTES:
        return _points(raw) if name == "points" else raw
    if a.dtype == _TEXT:
        text = raw.decode("utf-8")
        if name == "landmarks":
            return _landmarks(text)
        if name == "boxes":
            return _boxes(text)
        if name == "coverage":
            return _coverage(text)
        if name == "edge_segments":
            return _edge_segments(text)
        return json.loads(text) if name in ("coco", "instances", "boxes_json") else text
    dims = tuple(a.dims[:a.ndim])
    return np.frombuffer(raw, dtype=_DTYPES[a.dtype]).reshape(dims).copy()


class Player:
    """A compiled scene (.glsb) ready to render.

    Player(bundle, aa="auto" (the default, glsplay's: exact coverage
    where the scene and cameras allow it, else one sample a pixel), "exact"
    (the exact area of what is visible in each pixel times its colour;
    refuses a scene or camera it cannot draw) or N (N x N samples a pixel,
    glsplay --aa N); with exact coverage outputs may include "coverage" and
    "edge_segments",
    pattern="lattice"|"grid"|"stratified", backend="auto"|"egl"|"osmesa",
    background=(r, g, b) in 0..1, seed=0, options=[more glsplay
    arguments, e.g. "--image-format", "png16"]).  A context manager; close()
    frees it.  Use it from the thread that made it.

    A render or sequence of the player's run keeps that run open: the next
    one with the same cameras, outputs, trajectory, motion and options
    (and their files unchanged) renders in it without loading the scene
    again; other settings close it and begin theirs."""

    def __init__(self, bundle: Union[str, os.PathLike], aa: Union[int, str] = "auto", pattern: str = "lattice",
                 backend: str = "auto", background: Sequence[float] = (0.0, 0.0, 0.0), seed: int = 0,
                 options: Sequence[str] = ()):
        self._p = None
        self._run, self._run_key = None, None
        if backend not in _BACKENDS:
            raise ValueError("backend must be one of %s, got %r" % (", ".join(_BACKENDS), backend))
        if pattern not in _PATTERNS:
            raise ValueError("pattern must be one of %s, got %r" % (", ".join(_PATTERNS), pattern))
        self._bundle = os.fspath(bundle)
        # the run's --aa exact, which has coverage and edge_segments too
        # (glscene_render's GLSCENE_AA_EXACT has the image only)
        exact, auto = aa == "exact", aa == "auto"
        self._args = ["--aa", aa if exact or auto else str(int(aa)), "--pattern", pattern, "--seed", str(int(seed)),
                      "--background", ",".join(repr(float(x)) for x in background)]
        if backend != "auto":
            self._args += ["--backend", backend]
        self._args += [str(x) for x in options]
        self._moved = set()
        # glscene_open's aa: 0 is --aa auto, the same choice (play_aa.c)
        o = _Options(_BACKENDS[backend], 1 if exact else 0 if auto else int(aa), _PATTERNS[pattern], int(seed),
                     (ctypes.c_float * 3)(*background))
        err = _Error()
        p = _lib.glscene_open(_path(bundle), ctypes.byref(o), ctypes.byref(err))
        if not p:
            _raise(err)
        self._p = p
        self._direct_ok = not options and not exact

    def close(self) -> None:
        """Free the scene, the open run and their GL contexts (also when
        collected)."""
        self._drop_run()
        if self._p:
            _lib.glscene_close(self._p)
            self._p = None

    def __del__(self):
        self.close()

    def __enter__(self) -> "Player":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _open(self):
        if not self._p:
            raise Error("the player is closed")
        return self._p

    def _drop_run(self):
        run, self._run, self._run_key = getattr(self, "_run", None), None, None
        if run is not None:
            run.close()

    def _run_for(self, cameras, words, trajectory, motion, options) -> "_Run":
        """The open run of these settings: the last one if they are the
        same (its files unchanged since it began, which is when the
        library reads them), else a new one in its place."""
        key = (tuple(_camera_key(c) for c in cameras), words, _file_key(trajectory),
               tuple(sorted((str(k), _file_key(v)) for k, v in (motion or {}).items())),
               tuple(str(x) for x in options), _file_key(self._bundle))
        if self._run is None or self._run_key != key:
            self._drop_run()
            self._run = _Run(self._bundle, self._args, cameras, words, trajectory, motion, options)
            self._run_key = key
        return self._run

    def render(self, camera: Rig, outputs: Union[str, Sequence[str]] = ("image", "depth"), frame: int = 0,
               trajectory: Optional[Union[str, os.PathLike]] = None,
               motion: Optional[Mapping[str, Union[str, os.PathLike]]] = None,
               options: Sequence[str] = ()) -> Union[Outputs, List[Outputs]]:
        """Render one frame: a dict of numpy arrays keyed by glsplay's
        output words (glsplay --help, spec/outputs.md), for a Camera; a
        list of such dicts, one a camera in order, for a rig (a list of
        cameras: disparity needs a rectified pair).

        Each array holds what glsplay's file holds, decoded: "image" H x W
        x 3 uint8 (uint16 with --image-format png16, float32 with pfm; one
        channel under a Bayer mosaic), "depth" and "disparity" float32,
        "depth16", "disparity16", "instance", "class" uint16 (the PNGs'
        codes), "normals" H x W x 3 float32, "edges" uint8, "flow" H x W x
        2 float32 (u, v; with "flow_kitti" the PNG's codes and "flowmask"),
        "points" a structured array (x y z, red green blue), "landmarks" a
        structured array (LANDMARK_DTYPE), "boxes" KITTI records
        (BOX_DTYPE) and "boxes_json", "coco" and "instances" as parsed
        JSON.  frame: the trajectory's frame (or the single frame's number,
        which keys sensor noise); trajectory: a trajectory file, the rig's
        pose a frame (cameras' poses relative to it); motion: {instance
        name: motion file} as glsplay --motion; options: more glsplay
        arguments for this render.

        A single Camera built from numbers, without trajectory, motion or
        options, asking only image, image_float (the float image), depth,
        instance and normals, is drawn by glscene_render, and sees the
        instances move() has posed; any other render is a run of the
        player, which move() does not reach (use motion)."""
        self._open()
        words = (outputs,) if isinstance(outputs, str) else tuple(outputs)
        rig = list(camera) if isinstance(camera, (list, tuple)) else None
        if (rig is None and camera._plain and self._direct_ok and trajectory is None and not motion
                and not options and all(w in _DIRECT for w in words)):
            return self._render_direct(camera, words)
        if "image_float" in words:
            raise Error("image_float is the float image of a single camera from numbers; for this render ask "
                        "for image with options=['--image-format', 'pfm']")
        if self._moved:
            raise Error("move() posed %s, which a render of a rig, a file's camera, a trajectory or these outputs "
                        "does not see; give motion={name: file} instead" % ", ".join(sorted(self._moved)))
        res = self._run_for(rig if rig is not None else [camera], words, trajectory, motion, options).render(frame)
        return res if rig is not None else res[0]

    def sequence(self, camera: Rig, trajectory: Union[str, os.PathLike],
                 outputs: Union[str, Sequence[str]] = ("image", "depth"),
                 motion: Optional[Mapping[str, Union[str, os.PathLike]]] = None, frames: Optional[Sequence[int]] = None,
                 options: Sequence[str] = ()) -> Iterator[Tuple[int, Union[Outputs, List[Outputs]]]]:
        """The frames of a trajectory, one at a time: (frame number, what
        render gives for it), over the trajectory's frames in order (or the
        frames given).  motion moves named instances a frame as glsplay
        --motion; flow goes from each frame to the next (none on the
        last)."""
        self._open()
        words = (outputs,) if isinstance(outputs, str) else tuple(outputs)
        cams = list(camera) if isinstance(camera, (list, tuple)) else [camera]
        run = self._run_for(cams, words, trajectory, motion, options)
        for f in (frames if frames is not None else run.frames()):
            # the open run, unless a render between two frames changed the
            # player's settings: then the sequence's begins again
            res = self._run_for(cams, words, trajectory, motion, options).render(f)
            yield int(f), (res if isinstance(camera, (list, tuple)) else res[0])

    def _render_direct(self, camera: Camera, words) -> Outputs:
        h, w = camera.height, camera.width
        arrays, buf = {}, _Buffers()
        for name in words:
            field, dtype, ch = _DIRECT[name]
            a = np.empty((h, w, ch) if ch > 1 else (h, w), dtype=dtype)
            arrays[name] = a
            setattr(buf, field, a.ctypes.data)
        err = _Error()
        if _lib.glscene_render(self._open(), ctypes.byref(camera._c), ctypes.byref(buf), ctypes.byref(err)):
            _raise(err)
        if "instance" in arrays:  # the ids as the run's instance array has them
            arrays["instance"] = arrays["instance"].astype(np.uint16)
        return arrays

    def move(self, name: str, R=None, T=None) -> None:
        """Pose the named instance (a named call, as glsplay --motion) for
        the renders glscene_render draws: R (3x3), T object-to-parent; R
        None: back to the identity."""
        err = _Error()
        if _lib.glscene_move_instance(self._open(), name.encode(), _doubles(R, 9, "R"),
                                      _doubles(T if R is not None else None, 3, "T"), ctypes.byref(err)):
            _raise(err)
        (self._moved.add if R is not None else self._moved.discard)(name)

    def instance_path(self, id: int) -> Optional[str]:
        """The call path of an instance id (the instance array's), or None."""
        s = _lib.glscene_instance_path(self._open(), int(id))
        return s.decode() if s is not None else None

    @property
    def instance_count(self) -> int:
        return _lib.glscene_instance_count(self._open())


def _file_key(path) -> Optional[Tuple[str, int, int]]:
    """A file as a run's settings see it: its path, and its size and time
    of change, so that a file rewritten since a run began begins another."""
    if path is None:
        return None
    p = os.fspath(path)
    try:
        st = os.stat(p)
        return (p, st.st_size, st.st_mtime_ns)
    except OSError:
        return (p, -1, -1)  # the run says what is wrong with it


def _camera_key(c):
    if not isinstance(c, Camera):
        raise TypeError("a camera or a list of cameras, got %r" % (c,))
    return ("text", c.name, c.text) if c.text is not None else ("file", _file_key(c.path))


class _Run:
    """One glscene_play run built from glsplay's arguments, the cameras
    added by path or by text; rendered a frame at a time."""

    def __init__(self, bundle, args, cameras, words, trajectory, motion, options):
        self._r = _lib.glscene_play_new()
        if not self._r:
            raise MemoryError("glscene_play_new")
        try:
            argv = [bundle] + list(args) + [str(x) for x in options]
            argv += ["--outputs", ",".join(words)] if words else []
            if trajectory is not None:
                argv += ["--trajectory", os.fspath(trajectory)]
            for name, f in (motion or {}).items():
                argv += ["--motion", "%s=%s" % (name, os.fspath(f))]
            self._args(argv)
            err = _Error()
            for c in cameras:
                if not isinstance(c, Camera):
                    raise TypeError("a camera or a list of cameras, got %r" % (c,))
                if c.text is not None:
                    if _lib.glscene_play_camera_text(self._r, c.name.encode(), c.text.encode(), ctypes.byref(err)):
                        _raise(err)
                else:
                    self._args(["--camera", c.path])
        except BaseException:
            self.close()
            raise

    def _args(self, argv):
        err = _Error()
        i = 0
        while i < len(argv):
            nxt = _path(argv[i + 1]) if i + 1 < len(argv) else None
            k = _lib.glscene_play_arg(self._r, _path(argv[i]), nxt, ctypes.byref(err))
            if k < 0:
                _raise(err)
            i += k

    def frames(self) -> List[int]:
        err = _Error()
        n = _lib.glscene_play_trajectory_frames(self._r, None, 0, ctypes.byref(err))
        if n < 0:
            _raise(err)
        a = (ctypes.c_uint64 * max(n, 1))()
        _lib.glscene_play_trajectory_frames(self._r, a, n, ctypes.byref(err))
        return [int(x) for x in a[:n]]

    def render(self, frame: int) -> List[Outputs]:
        err = _Error()
        res = _lib.glscene_play_render(self._r, int(frame), ctypes.byref(err))
        if not res:
            _raise(err)
        try:
            out = []
            for c in range(_lib.glscene_result_cameras(res)):
                d = {}
                for k in range(_lib.glscene_result_count(res, c)):
                    name = _lib.glscene_result_name(res, c, k)
                    a = _Array()
                    if _lib.glscene_result_array(res, c, name, ctypes.byref(a), ctypes.byref(err)):
                        _raise(err)
                    d[name.decode()] = _decode(name.decode(), a)
                out.append(d)
            return out
        finally:
            _lib.glscene_result_free(res)

    def close(self):
        if self._r:
            _lib.glscene_play_free(self._r)
            self._r = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
