"""libglscene renders every output glsplay writes, with the same values
(issue 29 item 1; docs/api.md "Every output as arrays"), run by
tests/e2e/library_outputs.sh:
    check_library_outputs.py BUILD TMPDIR
Each case renders the same inputs with glsplay (files) and with the
library (glscene_play_render, through the Python binding) and compares
every file of every camera, decoded (cv2 for the PNGs, 16-bit included,
and the PFMs, numpy for .npy, .flo and the PLY, the CSV, TXT and JSON
parsed), with the library's array of the same name, value for value: a
stereo rig with every word a single frame has, a trajectory with --motion
(flow, boxes) and with exposure effects, a lens camera from OpenCV YAML, a lit scene, sensor noise;
and a sequence's frames rendered in one run kept open against fresh runs.
Prints "ok NAME" / "FAIL NAME: why"."""
import glob
import json
import os
import re
import subprocess
import sys

import cv2
import numpy as np

BUILD, TMP = sys.argv[1], sys.argv[2]
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
os.environ["GLSCENE_LIBRARY"] = os.path.join(BUILD, "libglscene.so.0")
import glscene  # noqa: E402
from glscene import player as gp  # noqa: E402

import flow_scene  # noqa: E402
import gt_checks  # noqa: E402

result = gt_checks.result
GLSPLAY = os.path.join(BUILD, "glsplay")
# the file (stem, extension) -> the library's array (output_table.h's KEY)
KEYS = {("flow", "png"): "flow_kitti", ("flow", "flo"): "flow", ("boxes", "json"): "boxes_json"}


def decode(path):
    """A glsplay file as the library's array of it."""
    ext = path.rsplit(".", 1)[1]
    if ext in ("png", "pfm"):
        a = cv2.imread(path, cv2.IMREAD_UNCHANGED)
        return a[..., ::-1] if a is not None and a.ndim == 3 else a  # cv2's BGR
    if ext == "npy":
        return np.load(path)
    if ext == "flo":
        raw = np.fromfile(path, dtype="<f4")
        w, h = np.frombuffer(raw[1:3].tobytes(), dtype="<i4")
        return raw[3:].reshape(h, w, 2)
    with open(path, "rb") as f:
        data = f.read()
    if ext == "ply":
        return gp._points(data)
    text = data.decode()
    if ext == "json":
        return json.loads(text)
    return gp._landmarks(text) if ext == "csv" else gp._boxes(text)


def same(a, b):
    """Equal value for value (NaN equal to NaN), dtype and shape too."""
    if isinstance(a, np.ndarray) and a.dtype.names:
        return isinstance(b, np.ndarray) and a.dtype == b.dtype and a.shape == b.shape and all(
            same(a[n], b[n]) if a[n].dtype != object else list(a[n]) == list(b[n]) for n in a.dtype.names)
    if isinstance(a, np.ndarray):
        return isinstance(b, np.ndarray) and a.dtype == b.dtype and a.shape == b.shape and \
            np.array_equal(a, b, equal_nan=a.dtype.kind == "f")
    return a == b


def compare(case, bundle, cams, words, args=(), frames=(0,), trajectory=None, motion=None, player=()):
    """glsplay's files of each frame and camera against the library's
    arrays: every file has its array, equal; the library has no other."""
    out = os.path.join(TMP, case)
    cmd = [GLSPLAY, bundle, "--outputs", ",".join(words), "-o", out] + list(args) + list(player)
    for c in cams:
        cmd += ["--camera", c]
    if trajectory:
        cmd += ["--trajectory", trajectory, "--frames", "%d:%d" % (frames[0], frames[-1] + 1)]
    else:  # a single frame: its number keys the sensor's noise
        cmd += ["--frame", str(frames[0])]
    for name, f in (motion or {}).items():
        cmd += ["--motion", "%s=%s" % (name, f)]
    p = subprocess.run(cmd, stderr=subprocess.PIPE)
    if p.returncode:
        return result(case, False, "glsplay: " + p.stderr.decode())
    bad, n = [], 0
    with glscene.Player(bundle, options=list(player)) as pl:
        rig = [glscene.Camera.from_file(c) for c in cams]
        for f in frames:
            try:
                got = pl.render(rig, outputs=words, frame=f, trajectory=trajectory, motion=motion, options=args)
            except glscene.Error as e:
                return result(case, False, "frame %d: %s" % (f, e))
            for cam, lib in zip(rig, got):
                files = sorted(glob.glob(os.path.join(out, cam.name, "*_%06d.*" % f)))
                keys = set()
                for path in files:
                    stem, ext = re.match(r"(.*)_\d+\.(\w+)$", os.path.basename(path)).groups()
                    key = KEYS.get((stem, ext), stem)
                    keys.add(key)
                    n += 1
                    if key not in lib or not same(decode(path), lib[key]):
                        bad.append("%s/%s" % (cam.name, os.path.basename(path)))
                if keys != set(lib) or not files:
                    bad.append("%s frame %d: files %s, arrays %s" % (cam.name, f, sorted(keys), sorted(lib)))
    result(case, not bad, "differ: " + ", ".join(bad))
    return n


# a stereo rig: every word of a single frame, anti-aliased (edges, mask)
demo = glscene.compile("examples/demo/Demo.scene", ["examples/demo", os.path.join(BUILD, "textures")],
                       os.path.join(TMP, "demo.glsb"))
ALL = ["image", "depth", "points", "edges", "mask", "disparity", "disparity16", "depth16", "landmarks", "instance",
       "class", "coco", "normals", "boxes"]
LR = ["examples/demo/left.cam", "examples/demo/right.cam"]
compare("library_stereo_every_output", demo, LR, ALL, player=["--aa", "2"])
compare("library_stereo_formats", demo, LR, ["image", "depth", "disparity", "normals"],
        args=["--image-format", "png16", "--float-format", "npy", "--depth-scale", "tum"])
compare("library_image_pfm", demo, LR[:1], ["image", "depth"], args=["--image-format", "pfm"])

# a trajectory with --motion: flow and boxes, each frame (the last has no flow)
flow_scene.write(TMP)
fb = os.path.join(TMP, "flow.glsb")
glscene.compile(os.path.join(TMP, "Flow.scene"), [os.path.join(BUILD, "scenelib.glsb")], fb)
compare("library_trajectory_motion_flow", fb, [os.path.join(TMP, "cam.cam")],
        ["image", "depth", "flow", "boxes", "instance"], frames=(0, 1, 2),
        trajectory=os.path.join(TMP, "trajectory.txt"), motion={"mover": os.path.join(TMP, "mover.txt")})



def kept_against_fresh(case, bundle, cams, words, frames, trajectory, motion):
    """The frames of one player's sequence, rendered in one run kept open
    (one glscene_play, which loads the scene once), against each frame
    rendered by a fresh player: the same arrays."""
    rig = [glscene.Camera.from_file(c) for c in cams]
    with glscene.Player(bundle) as pl:
        kept, runs = [], set()
        for f, got in pl.sequence(rig, trajectory, outputs=words, motion=motion, frames=frames):
            kept.append(got)
            runs.add(getattr(pl, "_run", None))
    bad = [] if len(runs) == 1 and None not in runs else ["the frames' runs: %r" % (runs,)]
    for f, k in zip(frames, kept):
        with glscene.Player(bundle) as pl:
            fresh = pl.render(rig, outputs=words, frame=f, trajectory=trajectory, motion=motion)
        for cam, a, b in zip(rig, k, fresh):
            if set(a) != set(b) or not all(same(b[w], a[w]) for w in a):
                bad.append("%s frame %d" % (cam.name, f))
    result(case, not bad, "differ: " + ", ".join(bad))


kept_against_fresh("library_kept_run_frames_same_as_fresh", fb, [os.path.join(TMP, "cam.cam")],
                   ["image", "depth", "flow", "boxes", "instance", "landmarks"], (0, 1, 2),
                   os.path.join(TMP, "trajectory.txt"), {"mover": os.path.join(TMP, "mover.txt")})

# exposure effects along it: motion blur and a rolling shutter, depth of field
with open(os.path.join(TMP, "cam.cam")) as f:
    rig_cam = f.read()
with open(os.path.join(TMP, "blur.cam"), "w") as f:
    f.write(rig_cam + "shutter 0.5\nline_delay 0.002\naperture 0.05\nfocus 8\nexposure_samples 4\n")
compare("library_trajectory_exposure_effects", fb, [os.path.join(TMP, "blur.cam")],
        ["image", "depth", "instance", "boxes", "landmarks"], frames=(1,), trajectory=os.path.join(TMP, "trajectory.txt"),
        motion={"mover": os.path.join(TMP, "mover.txt")}, player=["--aa", "2"])

# a lens camera from OpenCV YAML (cv2.FileStorage), and a fisheye
left = glscene.Camera.from_file(LR[0])
for model, D in (("plumb_bob", [-0.2, 0.05, 0.001, -0.0005, 0.0]), ("fisheye", [0.05, -0.01, 0.002, -0.001])):
    y = os.path.join(TMP, "lens_%s.yml" % model)
    fs = cv2.FileStorage(y, cv2.FILE_STORAGE_WRITE)
    fs.write("image_width", left.width)
    fs.write("image_height", left.height)
    fs.write("camera_matrix", left.K)
    fs.write("distortion_coefficients", np.array([D]))
    fs.write("distortion_model", model)
    fs.write("R", left.R)
    fs.write("T", left.T.reshape(3, 1))
    fs.write("near", 0.1)
    fs.write("far", 500.0)
    fs.release()
    compare("library_lens_opencv_yaml_" + model, demo, [y], ["image", "depth", "instance", "normals", "boxes"])

# a lit scene, and sensor noise (keyed by the camera's name and frame)
lit = glscene.compile("examples/lighting/Lighting.scene", ["examples/lighting", os.path.join(BUILD, "textures"),
                                                           os.path.join(BUILD, "scenelib.glsb")],
                      os.path.join(TMP, "lit.glsb"))
compare("library_lit_scene", lit, ["examples/lighting/left.cam"], ["image", "depth", "normals"],
        player=["--aa", "2"])
compare("library_sensor_noise", demo, ["examples/demo/left_sensor.cam"], ["image", "depth"], frames=(7,))
compare("library_sensor_noise_aa", demo, ["examples/demo/left_sensor.cam"], ["image"], player=["--aa", "3"])

# landmarks: marks seen and hidden (the scene as text)
marks = glscene.compile("""mark("origin", 0, 0, 10);
mark("hidden", 0, 0, 14);
color(1, 0, 0);
poly { vert(-1, -1, 12); vert(1, -1, 12); vert(1, 1, 12); vert(-1, 1, 12); }
mark("behind", 0, 0, -3);
""", out=os.path.join(TMP, "marks.glsb"))
with open(os.path.join(TMP, "m.cam"), "w") as f:
    f.write(gt_checks.camera_text("world", 64, 48, 50.0, 50.0, 31.5, 23.5))
compare("library_landmarks", marks, [os.path.join(TMP, "m.cam")], ["landmarks", "depth"])
gt_checks.CHECKS.exit()
