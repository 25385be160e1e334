#!/usr/bin/env python3
"""excams: write the camera files of the examples (examples/*/ except demo/
and road/), deterministically, from the poses listed here.

    python3 tools/excams.py [ROOT]      # ROOT defaults to examples

Standard library only.  The world frame is the scene library's: metres,
y up, +x to the LEFT when looking along +z (scenelib/README.md).  Camera
files follow spec/camera.md: R maps world to the OpenCV camera frame
(x right, y down, z forward), T = -R C for the camera centre C.
tests/e2e/examples.sh checks that the committed files are what this script
writes now.
"""
import math
import os
import sys


def norm(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def look_at(C, target, roll=0.0):
    """R of an OpenCV camera at C looking at target, world +y up, then
    turned by roll degrees about its optical axis (positive: image content
    turns clockwise)."""
    fwd = norm([t - c for t, c in zip(target, C)])
    right = norm(cross(fwd, [0.0, 1.0, 0.0]))   # world -x for fwd = +z
    down = cross(fwd, right)
    R = [right, down, fwd]
    c, s = math.cos(math.radians(roll)), math.sin(math.radians(roll))
    return matmul([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]], R)


def level(yaw=0.0, pitch=0.0):
    """R of a camera looking along +z turned by yaw degrees towards +x (the
    left) and pitched down by pitch degrees; no roll."""
    a, b = math.radians(yaw), math.radians(pitch)
    fwd = [math.sin(a) * math.cos(b), -math.sin(b), math.cos(a) * math.cos(b)]
    right = norm(cross(fwd, [0.0, 1.0, 0.0]))
    return [right, cross(fwd, right), fwd]


def num(x):
    x = round(x, 15)
    return repr(0.0 if x == 0 else x)


def write_cam(path, comment, K, R, C, near, far):
    W, H, fx, fy, cx, cy = K
    T = [-sum(R[i][k] * C[k] for k in range(3)) for i in range(3)]
    with open(path, "w") as fh:
        fh.write("# %s\n" % comment)
        fh.write("# centre C = (%s) m, world frame x left, y up, z forward; written by tools/excams.py\n"
                 % ", ".join("%g" % c for c in C))
        fh.write("width %d\nheight %d\nfx %s\nfy %s\ncx %s\ncy %s\n" % (W, H, num(fx), num(fy), num(cx), num(cy)))
        fh.write("R %s\n" % "  ".join(" ".join(num(x) for x in row) for row in R))
        fh.write("T %s\n" % " ".join(num(x) for x in T))
        fh.write("near %s\nfar %s\n" % (num(near), num(far)))
    return path


def project(K, R, C, P):
    W, H, fx, fy, cx, cy = K
    Pc = [sum(R[i][k] * (P[k] - C[k]) for k in range(3)) for i in range(3)]
    return fx * Pc[0] / Pc[2] + cx, fy * Pc[1] / Pc[2] + cy, Pc[2]


# ---- calibration: calib.Checker9x6_25mm at the world origin, 15 poses --------
# (distance m, yaw deg, pitch deg, roll deg, aim offset x, y in m): the camera
# sits on a sphere of the given radius about the board centre, seen from the
# front (-z), and looks at the board centre plus the aim offset.
CALIB_POSES = [
    (0.55, 4, -3, 7, 0.00, 0.00),
    (0.60, 30, 0, 5, 0.01, 0.00),
    (0.60, -30, 0, -5, -0.01, 0.00),
    (0.58, 3, 28, -6, 0.00, 0.01),
    (0.58, 0, -28, 10, 0.00, -0.01),
    (0.50, 20, 20, 15, 0.02, 0.01),
    (0.50, -20, 20, -15, -0.02, 0.01),
    (0.52, 22, -22, -20, 0.01, -0.02),
    (0.52, -22, -22, 20, -0.01, -0.02),
    (0.70, 10, 5, 30, -0.02, 0.00),
    (0.72, -12, -8, -30, 0.02, 0.01),
    (0.58, 5, 10, 75, 0.00, 0.00),
    (0.62, 34, 12, -8, 0.00, 0.00),
    (0.62, -34, -12, 8, 0.00, 0.00),
    (0.80, 15, -15, 45, 0.00, 0.00),
]
CALIB_K = (640, 480, 700.0, 700.0, 316.0, 243.0)
CALIB_CENTRE = (0.1, 0.0625, 0.0)        # centre of the 9 x 6 inner corners


def calibration(root):
    d = os.path.join(root, "calibration")
    out = []
    for n, (dist, yaw, pitch, roll, ax, ay) in enumerate(CALIB_POSES):
        a, b = math.radians(yaw), math.radians(pitch)
        C = [CALIB_CENTRE[0] + dist * math.sin(a) * math.cos(b), CALIB_CENTRE[1] + dist * math.sin(b),
             -dist * math.cos(a) * math.cos(b)]
        aim = [CALIB_CENTRE[0] + ax, CALIB_CENTRE[1] + ay, 0.0]
        R = look_at(C, aim, roll)
        # every point of the board (white margin included) at least 8 px inside
        for P in [(-0.025, -0.025, 0), (0.25, -0.025, 0), (0.25, 0.175, 0), (-0.025, 0.175, 0)]:
            u, v, z = project(CALIB_K, R, C, P)
            if not (8 <= u <= CALIB_K[0] - 9 and 8 <= v <= CALIB_K[1] - 9 and z > 0):
                sys.exit("excams: calibration pose %d: board corner %s at (%.1f, %.1f) leaves the image" % (n, P, u, v))
        out.append(write_cam(os.path.join(d, "view%02d.cam" % n),
                             "calibration view %d: %.2f m from the board centre, yaw %g, pitch %g, roll %g deg"
                             % (n, dist, yaw, pitch, roll), CALIB_K, R, C, 0.05, 5.0))
    return out


# ---- stereo: a canonical binocular rig and a verged trinocular rig ----------
STEREO_K = (640, 480, 600.0, 600.0, 319.5, 239.5)


def stereo(root):
    d = os.path.join(root, "stereo")
    out = []
    R = level(0, 11)
    for name, x in (("left", 0.15), ("right", -0.15)):
        out.append(write_cam(os.path.join(d, "bino_%s.cam" % name),
                             "binocular rig, %s camera: 0.30 m baseline, 1.8 m high, pitched down 11 deg, "
                             "canonical (parallel axes)" % name, STEREO_K, R, [x, 1.8, 0.0], 0.1, 200.0))
    fix = [0.0, 0.5, 8.5]
    for name, C in (("left", [0.3, 1.8, 0.0]), ("right", [-0.3, 1.8, 0.0]), ("top", [0.0, 2.2, 0.0])):
        out.append(write_cam(os.path.join(d, "tri_%s.cam" % name),
                             "trinocular rig, %s camera: verged at (0, 0.5, 8.5) (general geometry)" % name,
                             STEREO_K, look_at(C, fix), C, 0.1, 200.0))
    return out


# ---- dense stereo: a rectified pair ------------------------------------------
DENSE_K = (640, 480, 600.0, 600.0, 319.5, 239.5)
DENSE_BASELINE = 0.2


def dense_stereo(root):
    d = os.path.join(root, "dense_stereo")
    R = level(0, 0)
    return [write_cam(os.path.join(d, "%s.cam" % name),
                      "rectified pair, %s camera: baseline %g m along the camera x axis, 1.5 m high, "
                      "identical K and R" % (name, DENSE_BASELINE),
                      DENSE_K, R, [x, 1.5, 0.0], 0.1, 100.0)
            for name, x in (("left", DENSE_BASELINE / 2), ("right", -DENSE_BASELINE / 2))]


# ---- grouping, lane, signs ------------------------------------------------------
def grouping(root):
    d = os.path.join(root, "grouping")
    R = level(0, 14)
    return [write_cam(os.path.join(d, "%s.cam" % name),
                      "grouping rig, %s camera: 0.30 m baseline, 2.5 m high, pitched down 14 deg" % name,
                      STEREO_K, R, [x, 2.5, 0.0], 0.1, 200.0)
            for name, x in (("left", 0.15), ("right", -0.15))]


def lighting(root):
    d = os.path.join(root, "lighting")
    R = level(0, 14)
    return [write_cam(os.path.join(d, "left.cam"),
                      "lighting: the grouping rig's left camera, 2.5 m high, pitched down 14 deg",
                      STEREO_K, R, [0.15, 2.5, 0.0], 0.1, 200.0)]


def lane(root):
    d = os.path.join(root, "lane")
    R = level(0, 4)
    return [write_cam(os.path.join(d, "%s.cam" % name),
                      "driver's stereo rig, %s camera: right lane (x = -1.75), 1.3 m high, "
                      "0.30 m baseline, pitched down 4 deg" % name,
                      STEREO_K, R, [-1.75 + x, 1.3, 0.0], 0.1, 500.0)
            for name, x in (("left", 0.15), ("right", -0.15))]


def signs(root):
    d = os.path.join(root, "signs")
    R = level(0, 3)
    return [write_cam(os.path.join(d, "%s.cam" % name),
                      "driver's stereo rig, %s camera: right lane (x = -1.75), 1.3 m high, "
                      "0.30 m baseline, pitched down 3 deg" % name,
                      STEREO_K, R, [-1.75 + x, 1.3, 0.0], 0.1, 500.0)
            for name, x in (("left", 0.15), ("right", -0.15))]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "examples"
    for f in (calibration, stereo, dense_stereo, grouping, lane, signs, lighting):
        os.makedirs(os.path.join(root, f.__name__), exist_ok=True)
        for p in f(root):
            print(p)


if __name__ == "__main__":
    main()
