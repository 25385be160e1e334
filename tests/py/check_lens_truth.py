#!/usr/bin/python3
"""Ground truth through a lens (spec/outputs.md "Through a lens"): instance
ids and normals read at each pixel centre's ray like depth, landmarks by the
distortion model.  Compared with cv2.projectPoints and closed-form normals.

usage: check_lens_truth.py BINDIR TMPDIR.  Prints ok NAME / FAIL NAME: why."""
import csv
import os
import subprocess
import sys
import numpy as np
import cv2

from glstest import Checks, undistort_iter

BIN, D = sys.argv[1], sys.argv[2]
CHECKS = Checks('lens_truth_setup')
result = CHECKS.result


# A wall at z = 0 facing -z (the camera looks at it from z < 0), a square
# 0.4 in front of it at (0.3, 0.2, -0.4): a called object, so it has its own
# instance.  Marks: two on the wall, one on the square's centre.
os.makedirs(D + '/pkg', exist_ok=True)
with open(D + '/W.scene', 'w') as f:
    f.write('mark("wall_corner", -1, -1, 0);\nmark("wall_mid", 0.5, 0.25, 0);\nmark("wall_open", -0.8, -0.3, 0);\n'
            'poly { vert(-2, -2, 0); vert(2, -2, 0); vert(2, 2, 0); vert(-2, 2, 0); }\n'
            'push; trans(0.3, 0.2, -0.4); call("pkg.Box"); pop;\n')
with open(D + '/pkg/Box.scene', 'w') as f:
    f.write('mark("centre", 0, 0, 0);\n'
            'poly { vert(-0.2, -0.2, 0); vert(0.2, -0.2, 0); vert(0.2, 0.2, 0); vert(-0.2, 0.2, 0); }\n')
subprocess.run([BIN + '/glsc', '-I', D, '-o', D + '/w.glsb', 'W'], check=True)

W, H = 320, 240
K = np.array([[260.0, 0, 161.3], [0, 258.0, 118.6], [0, 0, 1]])
RVEC = np.array([0.12, -0.18, 0.04])
R = cv2.Rodrigues(RVEC)[0]
C = np.array([-0.2, 0.1, -3.0])  # the camera centre, in front of the wall
T = -R @ C
LENSES = {'brown': ('distortion', [-0.3, 0.08, 0.0012, -0.0008, -0.01], False),
          'fisheye': ('fisheye', [0.05, -0.01, 0.002, -0.0004], True)}


def fmt(v):
    return ' '.join(repr(float(x)) for x in np.ravel(v))


def project(lens, P):
    key, dist, fish = LENSES[lens]
    P = np.asarray(P, np.float64).reshape(-1, 1, 3)
    if fish:
        uv, _ = cv2.fisheye.projectPoints(P, RVEC.reshape(3, 1), T.reshape(3, 1), K, np.array(dist))
    else:
        uv, _ = cv2.projectPoints(P, RVEC, T, K, np.array(dist))
    return uv.reshape(-1, 2)


for lens, (key, dist, fish) in LENSES.items():
    cam = '%s/%s.cam' % (D, lens)
    with open(cam, 'w') as f:
        f.write('width %d\nheight %d\nK %s\nR %s\nT %s\nnear 0.1\nfar 100\n%s %s\n' % (
            W, H, fmt(K), fmt(R), fmt(T), key, fmt(dist)))
    p = subprocess.run([BIN + '/glsplay', D + '/w.glsb', '--camera', cam, '--outputs',
                        'depth,instance,normals,landmarks', '-o', D + '/out'], capture_output=True, text=True)
    if p.returncode:
        result('lens_truth_render_%s' % lens, False, p.stderr.strip())
        continue
    o = '%s/out/%s/' % (D, lens)
    z = cv2.imread(o + 'depth_000000.pfm', cv2.IMREAD_UNCHANGED)
    ids = cv2.imread(o + 'instance_000000.png', cv2.IMREAD_UNCHANGED)
    n = cv2.imread(o + 'normals_000000.pfm', cv2.IMREAD_UNCHANGED)[:, :, ::-1]
    # ids and depth come from the same nearest fine sample: a surface
    # exactly where there is an id
    result('lens_instance_where_depth_%s' % lens, np.array_equal(ids > 0, np.isfinite(z)),
           '%d pixels differ' % int(np.count_nonzero((ids > 0) != np.isfinite(z))))
    # two instances: the wall (the top object) and the square in front
    vals = sorted(int(v) for v in np.unique(ids) if v)
    result('lens_instance_two_%s' % lens, len(vals) == 2, 'ids %s' % vals)
    # the square's pixels: where each pixel's ray (by the inverse model,
    # cv2.undistortPoints) meets the plane z = -0.4 inside the square
    uu, vv = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))
    pts = np.column_stack([uu.ravel(), vv.ravel()]).reshape(-1, 1, 2)
    if fish:
        xy = cv2.fisheye.undistortPoints(pts, K, np.array(dist)).reshape(-1, 2)
    else:
        xy = undistort_iter(pts, K, np.array(dist), (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 100, 1e-14)).reshape(-1, 2)
    ray = (R.T @ np.column_stack([xy, np.ones(len(xy))]).T).T
    s = (-0.4 - C[2]) / ray[:, 2]
    hit = C + s[:, None] * ray
    inside = (np.abs(hit[:, 0] - 0.3) < 0.2 - 1e-3) & (np.abs(hit[:, 1] - 0.2) < 0.2 - 1e-3)
    outside = (np.abs(hit[:, 0] - 0.3) > 0.2 + 1e-3) | (np.abs(hit[:, 1] - 0.2) > 0.2 + 1e-3)
    sq = (ids.ravel() == vals[-1]) if vals else np.zeros(W * H, bool)
    bad = int(np.count_nonzero(sq & outside) + np.count_nonzero(~sq & inside))
    result('lens_instance_footprint_%s' % lens, bad == 0 and inside.sum() > 500,
           '%d of %d pixels off the square\'s footprint through the lens' % (bad, int(inside.sum())))
    # normals: both planes face -z in the world; in the camera frame R (0, 0, -1)
    want = R @ np.array([0.0, 0.0, -1.0])
    got = n[np.isfinite(z)]
    e = float(np.abs(got - want).max())
    result('lens_normals_%s' % lens, e < 1e-5, 'max |n - R (0, 0, -1)| = %.3g' % e)
    # landmarks: (u, v) by the distortion model = cv2's projection
    rows = list(csv.DictReader(open(o + 'landmarks_000000.csv')))
    X = np.array([[float(r['X']), float(r['Y']), float(r['Z'])] for r in rows])
    uv = np.array([[float(r['u']), float(r['v'])] for r in rows])
    e = float(np.abs(uv - project(lens, X)).max())
    want_X = {'wall_corner': (-1, -1, 0), 'wall_mid': (0.5, 0.25, 0), 'wall_open': (-0.8, -0.3, 0),
              'centre': (0.3, 0.2, -0.4)}
    placed = all(np.allclose(X[i], want_X[r['name']], atol=1e-12) for i, r in enumerate(rows)) and len(rows) == 4
    result('lens_landmarks_%s' % lens, e < 1e-6 and placed, 'max |uv - cv2| = %.3g px; rows %s' % (e, rows))
    # in the image by cv2's (u, v); hidden when the segment from the camera
    # to the mark crosses the square (z = -0.4) before reaching it
    want, got = {}, {}
    for (u, v), x, r in zip(project(lens, X), X, rows):
        inside = -0.5 <= u < W - 0.5 and -0.5 <= v < H - 0.5
        f = (-0.4 - C[2]) / (x[2] - C[2])
        q = C + f * (x - C)
        hidden = x[2] > -0.4 + 1e-9 and abs(q[0] - 0.3) < 0.2 and abs(q[1] - 0.2) < 0.2
        want[r['name']] = (int(inside), int(inside and not hidden))
        got[r['name']] = (int(r['in_image']), int(r['visible']))
    cases = sorted(set(want.values()))
    result('lens_landmarks_visible_%s' % lens, got == want and len(cases) == 3,
           'got %s, want %s (in_image, visible)' % (got, want))
CHECKS.exit()
