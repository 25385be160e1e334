"""Cameras (spec/camera.md): a camera file (.cam or OpenCV YAML, lens,
sensor and exposure keys included), or numbers written as a camera file's
keys, so that the library's own parser and camera model read either; no
part of the model is computed here."""
import ctypes
import os
from typing import Iterable, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from ._lib import Error, _Camera, _Error, _doubles, _lib, _path, _raise

Numbers = Union[Sequence[float], np.ndarray]


def _num(v) -> str:
    """A number as a camera file's key takes it, exactly (repr round-trips
    a double)."""
    f = float(v)
    if not np.isfinite(f):
        raise ValueError("camera: %r is not a finite number" % (v,))
    return repr(f)


def _key(name: str, values) -> str:
    v = np.asarray(values, dtype=np.float64).reshape(-1)
    return name + " " + " ".join(_num(x) for x in v)


class Camera:
    """A camera the library renders through, with a name (its output
    directory under glsplay, its place in a rig's results).

    Build one with Camera(width, height, fx, fy, cx, cy, ...) (a pinhole
    by numbers), Camera.from_opencv(K, dist, rvec, tvec, size) or
    Camera.from_file(path).  Numbers are checked by the library as a
    camera file's are: a bad one raises glscene.Error (at construction
    for a pinhole, at the render for keys beyond it)."""

    def __init__(self, width: int, height: int, fx: float, fy: float, cx: float, cy: float, skew: float = 0.0,
                 R: Optional[Numbers] = None, T: Optional[Numbers] = None, near: float = 0.1, far: float = 1000.0,
                 name: str = "camera", keys: Optional[Mapping[str, object]] = None):
        c = _Camera()
        err = _Error()
        if _lib.glscene_camera_set(ctypes.byref(c), int(width), int(height), fx, fy, cx, cy, skew,
                                   _doubles(R, 9, "R"), _doubles(T, 3, "T"), near, far, ctypes.byref(err)):
            _raise(err)
        lines = ["width %d" % c.width, "height %d" % c.height, _key("K", [[c.fx, c.skew, c.cx], [0, c.fy, c.cy],
                                                                         [0, 0, 1]]),
                 _key("R", R if R is not None else np.eye(3)), _key("T", T if T is not None else np.zeros(3)),
                 "near " + _num(near), "far " + _num(far)]
        self._init(name, None, "\n".join(lines + _extra(keys)) + "\n", c)
        self._plain = not keys  # the library's glscene_render draws it whole

    def _init(self, name, path, text, pinhole):
        self._name, self._path, self._text, self._c, self._plain = name, path, text, pinhole, False

    @classmethod
    def from_file(cls, path: Union[str, os.PathLike]) -> "Camera":
        """A camera file (.cam keys, or OpenCV YAML with distortion or
        fisheye, sensor and exposure keys), as glsplay --camera reads it:
        its pose in the world for a single frame, relative to the rig with
        a trajectory.  Its name is the file's without its directory and
        extension, as glsplay names its output directory (from_text names
        a camera as you like)."""
        cam = cls.__new__(cls)
        path = os.fspath(path)
        cam._init(os.path.splitext(os.path.basename(path))[0], path, None, None)
        return cam

    @classmethod
    def from_opencv(cls, K: Numbers, dist: Optional[Numbers] = None, rvec: Optional[Numbers] = None,
                    tvec: Optional[Numbers] = None, size: Tuple[int, int] = (640, 480), near: float = 0.1,
                    far: float = 1000.0, fisheye: bool = False, name: str = "camera",
                    keys: Optional[Mapping[str, object]] = None) -> "Camera":
        """A camera from OpenCV's numbers, as cv2.projectPoints (or
        cv2.fisheye.projectPoints with fisheye=True) takes them: K (3x3),
        dist (4, 5 or 8 coefficients; fisheye: 4), rvec (Rodrigues, 3) or a
        3x3 R, tvec (3), size (width, height).  keys: more camera keys
        (gain, read_noise, shutter, aperture, ...: spec/camera.md) by name."""
        w, h = size
        lines = ["width %d" % int(w), "height %d" % int(h), _key("K", K)]
        r = np.zeros(3) if rvec is None else np.asarray(rvec, dtype=np.float64)
        lines.append(_key("R", r) if r.size == 9 else _key("rvec", r))
        lines.append(_key("T", np.zeros(3) if tvec is None else tvec))
        lines += ["near " + _num(near), "far " + _num(far)]
        d = None if dist is None else np.asarray(dist, dtype=np.float64).reshape(-1)
        if d is not None and (d.size or fisheye):
            lines.append(_key("fisheye" if fisheye else "distortion", d))
        return cls.from_text("\n".join(lines + _extra(keys)) + "\n", name)

    @classmethod
    def from_text(cls, text: str, name: str = "camera") -> "Camera":
        """A camera from a camera file's text (.cam keys or OpenCV YAML);
        its messages locate errors as NAME:line:col."""
        cam = cls.__new__(cls)
        cam._init(name, None, text, None)
        return cam

    @property
    def name(self) -> str:
        return self._name

    @property
    def text(self) -> Optional[str]:
        """The camera file's text the library reads (None: a file's path)."""
        return self._text

    @property
    def path(self) -> Optional[str]:
        return self._path

    def _pinhole(self) -> _Camera:
        """The numbers of a pinhole camera (the library's glscene_camera):
        a file without a lens, or numbers; a lens raises Error."""
        if self._c is None:
            if self._path is None:
                raise Error("camera %s: its K, R and T are read from a file; this one was built from text"
                            % self._name)
            c, err = _Camera(), _Error()
            if _lib.glscene_camera_from_file(_path(self._path), ctypes.byref(c), ctypes.byref(err)):
                _raise(err)
            self._c = c
        return self._c

    width = property(lambda self: self._pinhole().width)
    height = property(lambda self: self._pinhole().height)
    near = property(lambda self: self._pinhole().near)
    far = property(lambda self: self._pinhole().far)

    @property
    def K(self) -> np.ndarray:
        c = self._pinhole()
        return np.array([[c.fx, c.skew, c.cx], [0.0, c.fy, c.cy], [0.0, 0.0, 1.0]])

    @property
    def R(self) -> np.ndarray:
        return np.array(self._pinhole().R[:]).reshape(3, 3)

    @property
    def T(self) -> np.ndarray:
        return np.array(self._pinhole().T[:])

    def __repr__(self) -> str:
        return "Camera(%r, %s)" % (self._name, "path=%r" % self._path if self._path else "from numbers or text")


def _extra(keys: Optional[Mapping[str, object]]) -> list:
    """More keys, each 'name value...' as a camera file has them."""
    out = []
    for k, v in (keys or {}).items():
        if isinstance(v, str):
            out.append("%s %s" % (k, v))
        elif isinstance(v, Iterable) or isinstance(v, np.ndarray):
            out.append(_key(k, v))
        else:
            out.append("%s %s" % (k, v if isinstance(v, int) else _num(v)))
    return out
