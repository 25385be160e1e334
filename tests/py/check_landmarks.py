"""glsplay --outputs landmarks (spec/outputs.md "Landmarks"), checked
against geometry computed here: world positions from the scene's
transforms in numpy, (u, v) by cv2.projectPoints, visibility against
known occluders.  Usage: check_landmarks.py BIN TMPDIR.  Prints
"ok NAME" / "FAIL NAME: why"."""
import csv
import math
import os
import sys

import cv2
import numpy as np

from glstest import fail, ok, run, write

BIN, TMP = sys.argv[1], sys.argv[2]
HEADER = ["name", "path", "X", "Y", "Z", "u", "v", "depth", "in_image", "visible"]


def check(name, cond, why):
    ok(name) if cond else fail(name, why)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [dict(zip(rows[0], r)) for r in rows[1:]]


def rot(deg, axis):
    """glRotate's matrix (4x4), as spec/bundle.md 9.2 defines rot."""
    x, y, z = np.array(axis, float) / np.linalg.norm(axis)
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    t = 1 - c
    m = np.eye(4)
    m[:3, :3] = [[x * x * t + c, x * y * t - z * s, x * z * t + y * s],
                 [y * x * t + z * s, y * y * t + c, y * z * t - x * s],
                 [x * z * t - y * s, y * z * t + x * s, z * z * t + c]]
    return m


def trans(x, y, z):
    m = np.eye(4)
    m[:3, 3] = [x, y, z]
    return m


def scale(x, y, z):
    return np.diag([x, y, z, 1.0])


def apply(m, p):
    h = m @ np.array([p[0], p[1], p[2], 1.0])
    return h[:3] / h[3]


def cam_text(w, h, fx, fy, cx, cy, R, T, near=0.1, far=1000):
    f = lambda v: repr(float(v))
    return ("width %d\nheight %d\nfx %s\nfy %s\ncx %s\ncy %s\nR %s\nT %s\nnear %s\nfar %s\n" %
            (w, h, f(fx), f(fy), f(cx), f(cy), " ".join(f(v) for v in np.ravel(R)),
             " ".join(f(v) for v in T), f(near), f(far)))


# --- projection: a rotated, translated camera; marks in the top object
# and in called, transformed objects (two parameters: a path with a comma)
src = os.path.join(TMP, "src")
write(os.path.join(src, "lm", "Sign.scene"),
      "param s = 1;\nparam h = 2;\n"
      "mark(\"foot\", 0, 0, 0);\nmark(\"top\", 0.25, h, -0.125);\n"
      "color(1, 0, 0);\npoly { vert(-0.3, h, 0); vert(0.3, h, 0); vert(0.3, h + 0.6 * s, 0); vert(-0.3, h + 0.6 * s, 0); }\n")
write(os.path.join(src, "Proj.scene"),
      "mark(\"origin\", 0.5, 0.25, 20);\n"
      "mark(\"behind\", 0, 0, -50);\n"
      "mark(\"aside\", 400, 0, 20);\n"
      "push; trans(1.5, -0.5, 18); rot(37, 0.2, 1, 0.1); scale(1.25, 0.75, 1.5); call(\"lm.Sign\"); pop;\n"
      "push; trans(-2, 0.3, 25); rot(-20, 0, 0, 1); call(\"lm.Sign\", s = 2, h = 3); pop;\n"
      "push; trans(0.7, 1.1, 30); call(\"lm.Sign\", \"moved\"); pop;\n"
      "repeat(i, 0, 2) { push; trans(-1 + i, -1, 22 + i); call(\"lm.Sign\"); pop; }\n")
# the expected world positions, from the transforms above
sign = {"foot": (0, 0, 0), "top": (0.25, 2, -0.125)}
sign23 = {"foot": (0, 0, 0), "top": (0.25, 3, -0.125)}
motion_T = np.array([0.5, -0.25, 2.0])
motion_R = rot(90, (0, 1, 0))
want = [("origin", "Proj", np.array([0.5, 0.25, 20.0])),
        ("behind", "Proj", np.array([0, 0, -50.0])),
        ("aside", "Proj", np.array([400, 0, 20.0]))]
calls = [("Proj > lm.Sign#1", trans(1.5, -0.5, 18) @ rot(37, (0.2, 1, 0.1)) @ scale(1.25, 0.75, 1.5), sign),
         ("Proj > lm.Sign(s=2,h=3)#1", trans(-2, 0.3, 25) @ rot(-20, (0, 0, 1)), sign23),
         ("Proj > lm.Sign#2", trans(0.7, 1.1, 30) @ np.vstack([np.hstack([motion_R[:3, :3], motion_T[:, None]]),
                                                               [0, 0, 0, 1]]), sign),
         ("Proj > lm.Sign#3", trans(-1, -1, 22), sign),
         ("Proj > lm.Sign#4", trans(0, -1, 23), sign)]
for path, m, marks in calls:
    for name in ("foot", "top"):
        want.append((name, path, apply(m, marks[name])))

rvec = np.array([0.08, -0.15, 0.03])
R, _ = cv2.Rodrigues(rvec)
T = np.array([0.3, -0.2, 1.7])
W, H, fx, fy, cx, cy = 640, 480, 520.5, 515.25, 318.75, 241.125
write(os.path.join(TMP, "cams", "rot.cam"), cam_text(W, H, fx, fy, cx, cy, R, T))
motion = os.path.join(TMP, "moved.txt")
write(motion, "# glsroad motion 1\n0 0 %s %s\n" % (" ".join(repr(float(v)) for v in motion_R[:3, :3].ravel()),
                                                   " ".join(repr(float(v)) for v in motion_T)))
try:
    run(os.path.join(BIN, "glsc"), "-I", src, "-o", os.path.join(TMP, "proj.glsb"), os.path.join(src, "Proj.scene"))
    run(os.path.join(BIN, "glsplay"), os.path.join(TMP, "proj.glsb"), "--camera", os.path.join(TMP, "cams", "rot.cam"),
        "--outputs", "image,landmarks", "--motion", "moved=" + motion, "-o", os.path.join(TMP, "out"))
    header, rows = read_csv(os.path.join(TMP, "out", "rot", "landmarks_000000.csv"))
except (RuntimeError, OSError) as e:
    fail("landmarks_run", str(e))
    sys.exit(0)
check("landmarks_csv_header", header == HEADER, "header %r" % header)
check("landmarks_rows", [(r["name"], r["path"]) for r in rows] == [(n, p) for n, p, _ in want],
      "rows %r" % [(r["name"], r["path"]) for r in rows])
if len(rows) == len(want):
    X = np.array([w[2] for w in want])
    got = np.array([[float(r[k]) for k in "XYZ"] for r in rows])
    check("landmarks_world", np.max(np.abs(got - X)) <= 1e-12 * max(1, np.max(np.abs(X))),
          "world positions off by %g" % np.max(np.abs(got - X)))
    # in front of the camera: (u, v) by OpenCV's projection, depth by R X + T
    pc = X @ R.T + T
    front = pc[:, 2] > 0
    K = np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]])
    uv, _ = cv2.projectPoints(X[front].reshape(-1, 1, 3), rvec, T, K, np.zeros(5))
    uv = uv.reshape(-1, 2)
    g = np.array([[float(r["u"]), float(r["v"])] for r in rows])[front]
    err = np.max(np.abs(g - uv))
    check("landmarks_projectpoints", err <= 1e-6, "max |(u, v) - cv2.projectPoints| = %g px" % err)
    dz = max(abs(float(r["depth"]) - z) / abs(z) for r, z in zip(rows, pc[:, 2]))
    check("landmarks_depth", dz <= 1e-12, "depth off by %g relative" % dz)
    inside = [(-0.5 <= u < W - 0.5 and -0.5 <= v < H - 0.5) for u, v in
              np.array([[float(r["u"]), float(r["v"])] for r in rows])]
    want_in = [int(f and i and z > 0.1) for f, i, z in zip(front, inside, pc[:, 2])]
    check("landmarks_in_image", [int(r["in_image"]) for r in rows] == want_in,
          "in_image %r, expected %r" % ([r["in_image"] for r in rows], want_in))
    by = {(r["name"], r["path"]): r for r in rows}
    check("landmarks_out_of_view", by[("behind", "Proj")]["in_image"] == "0" and by[("aside", "Proj")]["in_image"] == "0"
          and by[("behind", "Proj")]["visible"] == "0" and float(by[("aside", "Proj")]["u"]) > W,
          "behind: %r, aside: %r" % (by[("behind", "Proj")], by[("aside", "Proj")]))
    check("landmarks_all_in_view", sum(want_in) == len(rows) - 2, "%d of %d in the image" % (sum(want_in), len(rows)))

# --- visibility: a wall in front of one landmark, landmarks on surfaces
write(os.path.join(src, "Vis.scene"),
      "color(0.5, 0.5, 0.5);\n"
      "poly { vert(-2, -1, 5); vert(0, -1, 5); vert(0, 1, 5); vert(-2, 1, 5); }\n"      # wall, z = 5
      "poly { vert(-50, 1, 1); vert(50, 1, 1); vert(50, 1, 200); vert(-50, 1, 200); }\n"  # ground, y = 1
      "mark(\"hidden\", -1, 0.2, 8);\n"
      "mark(\"behind.wall\", -0.9876, 0.3456, 5.01);\n"
      "mark(\"on.wall\", -0.9876, 0.3456, 5);\n"
      "mark(\"free\", 0.5, -0.2, 8);\n"
      "mark(\"on.ground\", 0.37, 1, %r);\n"
      "mark(\"under.ground\", 0.37, 1.05, 30);\n" % (300 / 10.2))
write(os.path.join(TMP, "cams", "front.cam"),
      cam_text(480, 480, 300, 300, 239.5, 239.5, np.eye(3), [0, 0, 0], near=0.1, far=1000))
try:
    run(os.path.join(BIN, "glsc"), "-I", src, "-o", os.path.join(TMP, "vis.glsb"), os.path.join(src, "Vis.scene"))
    for aa in ("1", "4"):
        run(os.path.join(BIN, "glsplay"), os.path.join(TMP, "vis.glsb"), "--camera",
            os.path.join(TMP, "cams", "front.cam"), "--outputs", "image,landmarks", "--aa", aa,
            "-o", os.path.join(TMP, "vis" + aa))
    _, vis1 = read_csv(os.path.join(TMP, "vis1", "front", "landmarks_000000.csv"))
    _, vis4 = read_csv(os.path.join(TMP, "vis4", "front", "landmarks_000000.csv"))
except (RuntimeError, OSError) as e:
    fail("landmarks_visibility_run", str(e))
    sys.exit(0)
v = {r["name"]: r for r in vis1}
expect = {"hidden": 0, "behind.wall": 0, "on.wall": 1, "free": 1, "on.ground": 1, "under.ground": 0}
got = {n: int(v[n]["visible"]) for n in expect}
check("landmarks_visible", got == expect and all(v[n]["in_image"] == "1" for n in expect),
      "visible %r, expected %r" % (got, expect))
# the grazing case is one where the pixel centre is nearer than the mark:
# the ground's depth changes by Z^2/fy per row there
vg = float(v["on.ground"]["v"])
check("landmarks_grazing_case", round(vg) > vg and abs(round(vg) - vg) > 0.25,
      "v = %r: the nearest pixel centre is not below the mark" % vg)
check("landmarks_centre_sample_with_aa", vis1 == vis4, "--aa 4 changes the landmarks")
