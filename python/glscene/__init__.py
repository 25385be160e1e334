"""glscene from Python: a ctypes binding over libglscene (include/glscene.h,
docs/api.md) that returns numpy arrays.  No compiled extension: Debian's
python3 and python3-numpy are all it needs.

    import glscene
    player = glscene.Player("scene.glsb", aa=4)
    cam = glscene.Camera.from_file("left.cam")
    out = player.render(cam, outputs=("image", "depth"))
    out["image"]   # H x W x 3 uint8; out["depth"]: H x W float32 Zc, inf: nothing

Errors raise glscene.Error with the library's message.  A Player owns a GL
context: use it only from the thread that made it.

The library is looked for in this order: $GLSCENE_LIBRARY (a path), beside
this package, the lib/ directory of the prefix it is installed in
(PREFIX/lib/python3/dist-packages/glscene -> PREFIX/lib), the build/ of the
checkout it is in (python/glscene -> build/), then the system's
(ctypes.util.find_library)."""
import ctypes
import ctypes.util
import os

import numpy as np

__all__ = ["Error", "Camera", "Player", "compile", "version"]

_SONAME = "libglscene.so.0"


class Error(Exception):
    """A failure the library reported; str() is its message."""


class _Error(ctypes.Structure):
    _fields_ = [("message", ctypes.c_char * 1024)]


class _Options(ctypes.Structure):
    _fields_ = [("backend", ctypes.c_int), ("aa", ctypes.c_uint32), ("pattern", ctypes.c_int),
                ("seed", ctypes.c_uint64), ("background", ctypes.c_float * 3)]


class _Camera(ctypes.Structure):
    _fields_ = [("width", ctypes.c_uint32), ("height", ctypes.c_uint32), ("fx", ctypes.c_double),
                ("fy", ctypes.c_double), ("cx", ctypes.c_double), ("cy", ctypes.c_double),
                ("skew", ctypes.c_double), ("R", ctypes.c_double * 9), ("T", ctypes.c_double * 3),
                ("near", ctypes.c_double), ("far", ctypes.c_double)]


class _Buffers(ctypes.Structure):
    _fields_ = [("rgb8", ctypes.c_void_p), ("rgbf", ctypes.c_void_p), ("depth", ctypes.c_void_p),
                ("instance", ctypes.c_void_p), ("normals", ctypes.c_void_p)]


def _candidates():
    here = os.path.dirname(os.path.abspath(__file__))
    env = os.environ.get("GLSCENE_LIBRARY")
    if env:
        yield env
    yield os.path.join(here, _SONAME)
    yield os.path.normpath(os.path.join(here, "..", "..", "..", _SONAME))
    yield os.path.normpath(os.path.join(here, "..", "..", "build", _SONAME))
    found = ctypes.util.find_library("glscene")
    if found:
        yield found


def _load():
    tried = []
    for path in _candidates():
        if os.path.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            return ctypes.CDLL(path)
        except OSError as e:
            tried.append("%s (%s)" % (path, e))
    raise ImportError("glscene: cannot find libglscene (set GLSCENE_LIBRARY to its path); tried: "
                      + ", ".join(tried))


_lib = _load()
_P = ctypes.c_void_p
_E = ctypes.POINTER(_Error)
_D9 = ctypes.POINTER(ctypes.c_double)
_lib.glscene_version.restype = ctypes.c_char_p
_lib.glscene_version.argtypes = []
_lib.glscene_open.restype = _P
_lib.glscene_open.argtypes = [ctypes.c_char_p, ctypes.POINTER(_Options), _E]
_lib.glscene_close.restype = None
_lib.glscene_close.argtypes = [_P]
_lib.glscene_camera_from_file.argtypes = [ctypes.c_char_p, ctypes.POINTER(_Camera), _E]
_lib.glscene_camera_set.argtypes = [ctypes.POINTER(_Camera), ctypes.c_uint32, ctypes.c_uint32] + \
    [ctypes.c_double] * 5 + [_D9, _D9, ctypes.c_double, ctypes.c_double, _E]
_lib.glscene_move_instance.argtypes = [_P, ctypes.c_char_p, _D9, _D9, _E]
_lib.glscene_render.argtypes = [_P, ctypes.POINTER(_Camera), ctypes.POINTER(_Buffers), _E]
_lib.glscene_instance_path.restype = ctypes.c_char_p
_lib.glscene_instance_path.argtypes = [_P, ctypes.c_uint32]
_lib.glscene_instance_count.restype = ctypes.c_uint32
_lib.glscene_instance_count.argtypes = [_P]
_lib.glscene_compile.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p), ctypes.c_size_t,
                                 ctypes.c_char_p, _E]


def _raise(err):
    raise Error(err.message.decode("utf-8", "replace"))


def _path(p):
    return os.fsencode(p)


def _doubles(a, n, what):
    if a is None:
        return None
    v = np.ascontiguousarray(np.asarray(a, dtype=np.float64).reshape(-1))
    if v.size != n:
        raise ValueError("%s needs %d numbers, got %d" % (what, n, v.size))
    return (ctypes.c_double * n)(*v.tolist())


def version():
    """The library's version (GLSCENE_VERSION)."""
    return _lib.glscene_version().decode()


class Camera:
    """An OpenCV pinhole camera (spec/camera.md): Pc = R P + T, R world to
    camera (3x3), the image width x height pixels.  Checked as a camera
    file's values are; a bad one raises Error."""

    def __init__(self, width, height, fx, fy, cx, cy, skew=0.0, R=None, T=None, near=0.1, far=1000.0):
        self._c = _Camera()
        err = _Error()
        if _lib.glscene_camera_set(ctypes.byref(self._c), int(width), int(height), fx, fy, cx, cy, skew,
                                   _doubles(R, 9, "R"), _doubles(T, 3, "T"), near, far, ctypes.byref(err)):
            _raise(err)

    @classmethod
    def from_file(cls, path):
        """A camera file (.cam, or OpenCV YAML), its pose in the world."""
        cam = cls.__new__(cls)
        cam._c = _Camera()
        err = _Error()
        if _lib.glscene_camera_from_file(_path(path), ctypes.byref(cam._c), ctypes.byref(err)):
            _raise(err)
        return cam

    width = property(lambda self: self._c.width)
    height = property(lambda self: self._c.height)
    near = property(lambda self: self._c.near)
    far = property(lambda self: self._c.far)

    @property
    def K(self):
        c = self._c
        return np.array([[c.fx, c.skew, c.cx], [0.0, c.fy, c.cy], [0.0, 0.0, 1.0]])

    @property
    def R(self):
        return np.array(self._c.R[:]).reshape(3, 3)

    @property
    def T(self):
        return np.array(self._c.T[:])


_BACKENDS = {"auto": 0, "egl": 1, "osmesa": 2}
_PATTERNS = {"lattice": 0, "grid": 1, "stratified": 2}
# output name -> (buffer field, dtype, channels)
_OUTPUTS = {"image": ("rgb8", np.uint8, 3), "image_float": ("rgbf", np.float32, 3),
            "depth": ("depth", np.float32, 1), "instance": ("instance", np.uint32, 1),
            "normals": ("normals", np.float32, 3)}


class Player:
    """A compiled scene (.glsb) ready to render: Player(bundle, aa=N (N x N
    samples a pixel, as glsplay --aa), pattern="lattice"|"grid"|"stratified",
    backend="auto"|"egl"|"osmesa", background=(r, g, b) in 0..1, seed=0)."""

    def __init__(self, bundle, aa=1, pattern="lattice", backend="auto", background=(0.0, 0.0, 0.0), seed=0):
        self._p = None
        if backend not in _BACKENDS:
            raise ValueError("backend must be one of %s, got %r" % (", ".join(_BACKENDS), backend))
        if pattern not in _PATTERNS:
            raise ValueError("pattern must be one of %s, got %r" % (", ".join(_PATTERNS), pattern))
        o = _Options(_BACKENDS[backend], int(aa), _PATTERNS[pattern], int(seed), (ctypes.c_float * 3)(*background))
        err = _Error()
        p = _lib.glscene_open(_path(bundle), ctypes.byref(o), ctypes.byref(err))
        if not p:
            _raise(err)
        self._p = p

    def close(self):
        """Free the scene and its GL context (also when collected)."""
        if self._p:
            _lib.glscene_close(self._p)
            self._p = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _open(self):
        if not self._p:
            raise Error("the player is closed")
        return self._p

    def render(self, camera, outputs=("image", "depth")):
        """Render through camera; a dict of the outputs asked for:
        "image" H x W x 3 uint8 (as glsplay's PNG), "image_float" H x W x 3
        float32 (as its PFM), "depth" H x W float32 Zc (inf: no surface),
        "instance" H x W uint32 (glsplay's instance ids, 0: background;
        instance_path names them), "normals" H x W x 3 float32 camera-frame
        unit normals."""
        if isinstance(outputs, str):
            outputs = (outputs,)
        bad = [o for o in outputs if o not in _OUTPUTS]
        if bad:
            raise ValueError("unknown output %r (outputs: %s)" % (bad[0], ", ".join(_OUTPUTS)))
        h, w = camera.height, camera.width
        arrays, buf = {}, _Buffers()
        for name in outputs:
            field, dtype, ch = _OUTPUTS[name]
            a = np.empty((h, w, ch) if ch > 1 else (h, w), dtype=dtype)
            arrays[name] = a
            setattr(buf, field, a.ctypes.data)
        err = _Error()
        if _lib.glscene_render(self._open(), ctypes.byref(camera._c), ctypes.byref(buf), ctypes.byref(err)):
            _raise(err)
        return arrays

    def move(self, name, R=None, T=None):
        """Pose the named instance (a named call, as glsplay --motion):
        R (3x3), T object-to-parent; R None: back to the identity."""
        err = _Error()
        if _lib.glscene_move_instance(self._open(), name.encode(), _doubles(R, 9, "R"),
                                      _doubles(T if R is not None else None, 3, "T"), ctypes.byref(err)):
            _raise(err)

    def instance_path(self, id):
        """The call path of an instance id, or None."""
        s = _lib.glscene_instance_path(self._open(), int(id))
        return s.decode() if s is not None else None

    @property
    def instance_count(self):
        return _lib.glscene_instance_count(self._open())


def compile(scene, roots=(), out=None):
    """What glsc does: compile the scene (a .scene path or dotted name)
    with the search roots (directories or library bundles) into out
    (default: the scene's name + .glsb); returns out."""
    if out is None:
        out = os.path.splitext(os.path.basename(scene))[0].split(".")[-1] + ".glsb"
    arr = (ctypes.c_char_p * max(len(roots), 1))(*[_path(r) for r in roots])
    err = _Error()
    if _lib.glscene_compile(_path(scene), arr, len(roots), _path(out), ctypes.byref(err)):
        _raise(err)
    return out
