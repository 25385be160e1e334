"""The library itself: libglscene found and loaded, its functions' ctypes
signatures, and the error type (include/glscene.h, docs/api.md).  Internal
to the package: glscene/__init__.py is its face.

The library is looked for in this order: $GLSCENE_LIBRARY (a path), beside
this package, the lib/ directory of the prefix it is installed in
(PREFIX/lib/python3/dist-packages/glscene -> PREFIX/lib), the build/ of the
checkout it is in (python/glscene -> build/), then the system's
(ctypes.util.find_library)."""
import ctypes
import ctypes.util
import os

import numpy as np

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


class _Array(ctypes.Structure):
    _fields_ = [("dtype", ctypes.c_int), ("ndim", ctypes.c_uint32), ("dims", ctypes.c_size_t * 3),
                ("data", ctypes.c_void_p), ("bytes", ctypes.c_size_t)]


_lib.glscene_play_new.restype = _P
_lib.glscene_play_new.argtypes = []
_lib.glscene_play_free.restype = None
_lib.glscene_play_free.argtypes = [_P]
_lib.glscene_play_arg.argtypes = [_P, ctypes.c_char_p, ctypes.c_char_p, _E]
_lib.glscene_play_camera_text.argtypes = [_P, ctypes.c_char_p, ctypes.c_char_p, _E]
_lib.glscene_play_render.restype = _P
_lib.glscene_play_render.argtypes = [_P, ctypes.c_uint64, _E]
_lib.glscene_play_trajectory_frames.restype = ctypes.c_longlong
_lib.glscene_play_trajectory_frames.argtypes = [_P, ctypes.POINTER(ctypes.c_uint64), ctypes.c_size_t, _E]
_lib.glscene_result_cameras.restype = ctypes.c_size_t
_lib.glscene_result_cameras.argtypes = [_P]
_lib.glscene_result_camera.restype = ctypes.c_char_p
_lib.glscene_result_camera.argtypes = [_P, ctypes.c_size_t]
_lib.glscene_result_count.restype = ctypes.c_size_t
_lib.glscene_result_count.argtypes = [_P, ctypes.c_size_t]
_lib.glscene_result_name.restype = ctypes.c_char_p
_lib.glscene_result_name.argtypes = [_P, ctypes.c_size_t, ctypes.c_size_t]
_lib.glscene_result_array.argtypes = [_P, ctypes.c_size_t, ctypes.c_char_p, ctypes.POINTER(_Array), _E]
_lib.glscene_result_free.restype = None
_lib.glscene_result_free.argtypes = [_P]


def _path(p):
    return os.fsencode(p)


def _doubles(a, n, what):
    if a is None:
        return None
    v = np.ascontiguousarray(np.asarray(a, dtype=np.float64).reshape(-1))
    if v.size != n:
        raise ValueError("%s needs %d numbers, got %d" % (what, n, v.size))
    return (ctypes.c_double * n)(*v.tolist())


