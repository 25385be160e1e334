#!/usr/bin/python3
"""Flow and boxes through a lens (spec/outputs.md "Through a lens")
against geometry computed here with cv2 and numpy, never with numbers
glsplay printed.

Flow: the scene of tests/py/flow_scene.py (a wall, a floor, a box moved by
--motion, a box that stays, the rig moving and yawing) seen by a
Brown-Conrady and a fisheye camera.  Each pixel's ray is found by
cv2.undistortPoints / cv2.fisheye.undistortPoints, cast against the planes
and boxes of frame t, the point hit moved by its known motion, projected
at t+1 by cv2.projectPoints / cv2.fisheye.projectPoints.  The player's
depth of a pixel is the nearest sample of a fine render at least 4 fine
pixels per image pixel, so its point lies on the pixel's ray at the depth
of a ray at most 1/8 image pixel away: the bound on each pixel is the
largest change of the flow over the rays 1/8 px away along u and v, plus
1e-3 px (float32 and Newton).  Compared on pixels whose whole footprint
(corners +-0.5 px) sees one surface.  Mask: visible where the ray at t+1
reaches the point, occluded where rays around it meet something nearer by
0.05, out where it leaves the image by a pixel.

Boxes: check_boxes.py's scene (two boxes, the back one crossing the image
edge) through the same lenses: 3D corners and KITTI fields as without a
lens, truncated from the 64-step edge samples projected by cv2 (1e-9),
the 2D box from the ray-cast instance image (within a pixel), the visible
fraction within 0.02.

usage: check_lens_flow_boxes.py BINDIR SCENELIB TMPDIR.  Prints ok NAME /
FAIL NAME: why."""
import json
import os
import struct
import subprocess
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_boxes as B  # noqa: E402
import check_flow  # noqa: E402  (its ray-box slab test)
import flow_scene as S  # noqa: E402
import gt_checks  # noqa: E402
from glstest import undistort_iter  # noqa: E402

BIN, LIB, D = sys.argv[1], sys.argv[2], sys.argv[3]
result = gt_checks.result
LENSES = {'brown': ('distortion', [-0.25, 0.06, 0.001, -0.0008, 0.0], False),
          'fisheye': ('fisheye', [0.05, -0.01, 0.002, -0.0004], True)}
EDGE_STEPS = 64  # GLS_LENS_BOX_EDGE_STEPS


def fmt(v):
    return ' '.join(repr(float(x)) for x in np.ravel(v))


def rays(lens, K, u, v):
    """Camera-frame rays (x, y, 1) of image points by the inverse model."""
    _, dist, fish = LENSES[lens]
    pts = np.column_stack([np.ravel(u), np.ravel(v)]).astype(np.float64).reshape(-1, 1, 2)
    if fish:
        xy = cv2.fisheye.undistortPoints(pts, K, np.array(dist)).reshape(-1, 2)
    else:
        xy = undistort_iter(pts, K, np.array(dist), (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 100, 1e-15)).reshape(-1, 2)
    return np.column_stack([xy, np.ones(len(xy))]).reshape(np.shape(u) + (3,))


def project(lens, K, Pc):
    """Camera-frame points -> pixels by cv2's model."""
    _, dist, fish = LENSES[lens]
    P = np.asarray(Pc, np.float64).reshape(-1, 1, 3)
    z = np.zeros((3, 1))
    if fish:
        uv, _ = cv2.fisheye.projectPoints(P, z, z, K, np.array(dist))
    else:
        uv, _ = cv2.projectPoints(P, z, z, K, np.array(dist))
    return uv.reshape(np.shape(Pc)[:-1] + (2,))


def read_flo(path):
    b = open(path, 'rb').read()
    tag, w, h = struct.unpack('<fii', b[:12])
    return np.frombuffer(b[12:], '<f4').reshape(h, w, 2)


# ---- flow --------------------------------------------------------------

def cast(k, Rc, Tc, d):
    """Rays d (camera frame, z = 1; ... x 3) of the camera (Rc, Tc) at frame
    k against the flow scene: camera depth of the first hit and the surface
    (0 none, 1 wall, 2 floor, 3 mover, 4 still box)."""
    C = -Rc.T @ Tc
    Dw = d.reshape(-1, 3) @ Rc  # Rc^T d
    best = np.full(len(Dw), np.inf)
    what = np.zeros(len(Dw), int)
    with np.errstate(divide='ignore', invalid='ignore'):
        t = (20.0 - C[2]) / Dw[:, 2]  # the wall
        p = C + t[:, None] * Dw
        ok = (t > 0) & (np.abs(p[:, 0]) <= 100) & (p[:, 1] >= -5) & (p[:, 1] <= 2)
        best, what = np.where(ok & (t < best), t, best), np.where(ok & (t < best), 1, what)
        t = (2.0 - C[1]) / Dw[:, 1]  # the floor
        p = C + t[:, None] * Dw
        ok = (t > 0) & (np.abs(p[:, 0]) <= 100) & (p[:, 2] >= 0.5) & (p[:, 2] <= 20)
        best, what = np.where(ok & (t < best), t, best), np.where(ok & (t < best), 2, what)
    for code, moving in ((3, True), (4, False)):
        t = check_flow.ray_box_depth(C, Dw, k, moving)
        best, what = np.where(t < best, t, best), np.where(t < best, code, what)
    return best.reshape(d.shape[:-1]), what.reshape(d.shape[:-1])


def move(P, what, k):
    """World points of frame k to frame k + 1 (the mover's by its motion)."""
    Ra, ta = S.box_pose(k, True)
    Rb, tb = S.box_pose(k + 1, True)
    Pm = ((P - ta) @ Ra) @ Rb.T + tb
    return np.where((what == 3)[..., None], Pm, P)


def flow_of(lens, k, d, Z, what):
    """Flow and t+1 camera points of the points Z d (camera of frame k)."""
    R0, T0 = S.rig_pose(k)
    R1, T1 = S.rig_pose(k + 1)
    with np.errstate(invalid='ignore'):  # no surface: Z inf
        P = (Z[..., None] * d - T0) @ R0  # R0^T (Pc - T0)
    Pc1 = move(P, what, k) @ R1.T + T1
    return project(lens, S.K, Pc1), Pc1


def check_flow_lens(lens, out):
    v, u = np.mgrid[0:S.H, 0:S.W].astype(np.float64)
    for k in range(S.NFRAMES - 1):
        R0, T0 = S.rig_pose(k)
        d = rays(lens, S.K, u, v)
        Z, what = cast(k, R0, T0, d)
        # a footprint with one surface: the corners +-0.5 px see the same
        same = np.isfinite(Z)
        for du, dv in ((-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)):
            same &= cast(k, R0, T0, rays(lens, S.K, u + du, v + dv))[1] == what
        uv1, Pc1 = flow_of(lens, k, d, Z, what)
        want = uv1 - np.stack([u, v], axis=-1)
        # the bound: the point on this ray at the depth of rays 1/8 px away
        bound = np.zeros(Z.shape)
        for du, dv in ((-0.125, 0), (0.125, 0), (0, -0.125), (0, 0.125)):
            Zo, wo = cast(k, R0, T0, rays(lens, S.K, u + du, v + dv))
            with np.errstate(invalid='ignore'):
                alt = flow_of(lens, k, d, np.where(np.isfinite(Zo), Zo, Z), what)[0] - np.stack([u, v], axis=-1)
            bound = np.maximum(bound, np.nan_to_num(np.abs(alt - want).max(axis=-1), nan=0.0))
        bound += 1e-3
        got = read_flo('%s/flow_%06d.flo' % (out, k))
        mask = cv2.imread('%s/flowmask_%06d.png' % (out, k), cv2.IMREAD_UNCHANGED)
        inimg = ((uv1[..., 0] >= 0.5) & (uv1[..., 0] < S.W - 1.5) & (uv1[..., 1] >= 0.5) &
                 (uv1[..., 1] < S.H - 1.5) & (Pc1[..., 2] > S.NEAR))
        use = same & inimg & (mask == 1)
        err = np.abs(got - want).max(axis=-1)
        bad = use & (err > bound)
        n = int(use.sum())
        worst = float(err[use].max()) if n else float('nan')
        if n:
            print('  %s frame %d: %d pixels, largest error %.4g px, largest bound %.4g px, median bound %.4g px'
                  % (lens, k, n, worst, float(bound[use].max()), float(np.median(bound[use]))))
        result('lens_flow_%s_%d' % (lens, k), n > 20000 and not bad.any() and (what[use] == 3).sum() > 300,
               '%d of %d pixels beyond their bound (largest error %.4g px, largest bound %.4g)'
               % (int(bad.sum()), n, worst, float(bound[use].max()) if n else float('nan')))
        # the mask: out where the point leaves the image by a pixel
        left = same & (((uv1[..., 0] < -1.5) | (uv1[..., 0] > S.W + 0.5) | (uv1[..., 1] < -1.5) |
                        (uv1[..., 1] > S.H + 0.5)))
        result('lens_flowmask_out_%s_%d' % (lens, k), left.sum() > 100 and (mask[left] == 3).all(),
               '%d of %d pixels leaving the image not marked out' % (int((mask[left] != 3).sum()), int(left.sum())))
        # visible / occluded: rays at t+1 through (u1, v1) and 0.75 px
        # around it against the boxes (the only occluders: the floor never
        # hides the wall), as check_flow.py decides it without a lens
        R1, T1 = S.rig_pose(k + 1)
        C1 = -R1.T @ T1
        cand = same & inimg
        U1, Z1 = uv1[cand], Pc1[cand][:, 2]
        # hidden: rays 1.75 px around it too meet a box nearer (the
        # tolerance reads the depth of the nearest pixel's neighbours, up to
        # 0.5 + 1 + 1/8 px away along u and v)
        hid, clear = np.ones(len(U1), bool), np.ones(len(U1), bool)
        for du, dv in ((0, 0), (-0.75, -0.75), (0.75, -0.75), (-0.75, 0.75), (0.75, 0.75),
                       (-1.75, -1.75), (1.75, -1.75), (-1.75, 1.75), (1.75, 1.75)):
            dd = rays(lens, S.K, U1[:, 0] + du, U1[:, 1] + dv) @ R1
            t = np.min([check_flow.ray_box_depth(C1, dd, k + 1, mv) for mv in (True, False)], axis=0)
            hid &= t < Z1 - 0.05
            if abs(du) < 1:
                clear &= t > Z1 - 1e-3
        m = mask[cand]
        result('lens_flowmask_occluded_%s_%d' % (lens, k), hid.sum() > 50 and (m[hid] == 2).all(),
               '%d of %d hidden points not occluded' % (int((m[hid] != 2).sum()), int(hid.sum())))
        result('lens_flowmask_visible_%s_%d' % (lens, k), clear.sum() > 30000 and (m[clear] == 1).all(),
               '%d of %d clear points not visible (mask %s)'
               % (int((m[clear] != 1).sum()), int(clear.sum()), np.unique(m[clear & (m != 1)])))


# ---- boxes -------------------------------------------------------------

def box_hits(n, d):
    """Camera depth where rays d (camera = world frame) enter box n."""
    A, t = B.placement(n)
    Ai = np.linalg.inv(A)
    Cb = Ai @ (-t)
    Db = d.reshape(-1, 3) @ Ai.T
    lo, hi = np.array([-0.5, 0, -0.5]), np.array([0.5, 1, 0.5])
    with np.errstate(divide='ignore', invalid='ignore'):
        t1, t2 = (lo - Cb) / Db, (hi - Cb) / Db
    tmin = np.nanmax(np.minimum(t1, t2), axis=1)
    tmax = np.nanmin(np.maximum(t1, t2), axis=1)
    return np.where((tmin <= tmax) & (tmax > 0), np.maximum(tmin, 0), np.inf).reshape(d.shape[:-1])


def truncation(lens, K, P):
    """The 64-step edge samples' bounding rectangle through cv2's model,
    outside the image (all corners in front of near here)."""
    pts = []
    for a in range(8):
        for bit in range(3):
            b = a | (1 << bit)
            if b != a:
                s = np.arange(EDGE_STEPS + 1)[:, None] / EDGE_STEPS
                pts.append(P[a] + s * (P[b] - P[a]))
    q = project(lens, K, np.vstack(pts))
    u0, v0, u1, v1 = q[:, 0].min(), q[:, 1].min(), q[:, 0].max(), q[:, 1].max()
    area = (u1 - u0) * (v1 - v0)
    iu = min(u1, B.W - 0.5) - max(u0, -0.5)
    iv = min(v1, B.H - 0.5) - max(v0, -0.5)
    return 1 - (iu * iv if iu > 0 and iv > 0 else 0) / area


def check_boxes_lens(lens, out):
    K = np.array([[B.FX, 0, B.CX], [0, B.FY, B.CY], [0, 0, 1.0]])
    js = json.load(open(os.path.join(out, 'boxes_000000.json')))
    lines = open(os.path.join(out, 'boxes_000000.txt')).read().splitlines()
    boxes = {b['name']: b for b in js['boxes']}
    result('lens_boxes_two_%s' % lens, sorted(boxes) == ['back', 'front'] and len(lines) == 2,
           'names %s, %d lines' % (sorted(boxes), len(lines)))
    if sorted(boxes) != ['back', 'front']:
        return
    v, u = np.mgrid[0:B.H, 0:B.W].astype(np.float64)
    d = rays(lens, K, u, v)
    t = {n: box_hits(n, d) for n in B.BOXES}
    shown = {'front': np.isfinite(t['front']), 'back': np.isfinite(t['back']) & (t['back'] < t['front'])}
    for n in sorted(B.BOXES, key=lambda n: boxes[n]['instance']):
        b = boxes[n]
        P = B.corners(n)
        err = np.abs(np.array(b['corners']) - P).max()
        ys, xs = np.nonzero(shown[n])
        want = np.array([xs.min() - 0.5, ys.min() - 0.5, xs.max() + 0.5, ys.max() + 0.5])
        got = np.array(b['bbox'])
        trunc = truncation(lens, K, P)
        frac = shown[n].sum() / np.isfinite(t[n]).sum()
        result('lens_boxes_%s_%s' % (lens, n),
               err < 1e-9 and np.abs(got - want).max() <= 1 and abs(b['truncated'] - trunc) < 1e-9 and
               ((trunc > 0.05) if n == 'back' else trunc == 0) and abs(b['visible_fraction'] - frac) < 0.02,
               'corners off by %.3g; bbox %s, cv2 rays %s; truncated %r, cv2 %r; visible %.4f, rays %.4f'
               % (err, got, want, b['truncated'], trunc, b['visible_fraction'], frac))
        # the KITTI line: the same fields as the JSON (bbox, truncated, level)
        f = lines[sorted(boxes, key=lambda m: boxes[m]['instance']).index(n)].split(' ')
        vals = [float(x) for x in f[1:]]
        result('lens_boxes_kitti_%s_%s' % (lens, n), vals[0] == b['truncated'] and vals[3:7] == list(got) and
               int(f[2]) == b['occluded'], 'line %s' % ' '.join(f))


for lens, (key, dist, fish) in LENSES.items():
    d = '%s/%s' % (D, lens)
    os.makedirs(d, exist_ok=True)
    S.write(d)
    subprocess.run([BIN + '/glsc', '-I', LIB, '-o', d + '/f.glsb', d + '/Flow.scene'], check=True)
    cam = d + '/lens.cam'
    open(cam, 'w').write(open(d + '/cam.cam').read() + '%s %s\n' % (key, fmt(dist)))
    p = subprocess.run([BIN + '/glsplay', d + '/f.glsb', '--camera', cam, '--trajectory', d + '/trajectory.txt',
                        '--motion', 'mover=' + d + '/mover.txt', '--outputs', 'flow', '-o', d + '/o'],
                       capture_output=True, text=True)
    if p.returncode:
        result('lens_flow_render_%s' % lens, False, p.stderr.strip())
    else:
        check_flow_lens(lens, d + '/o/lens')
    open(d + '/Boxes.scene', 'w').write(B.SCENE)
    subprocess.run([BIN + '/glsc', '-I', LIB, '-o', d + '/b.glsb', d + '/Boxes.scene'], check=True)
    open(d + '/bl.cam', 'w').write(B.CAM + '%s %s\n' % (key, fmt(dist)))
    p = subprocess.run([BIN + '/glsplay', d + '/b.glsb', '--camera', d + '/bl.cam', '--outputs', 'boxes',
                        '-o', d + '/ob'], capture_output=True, text=True)
    if p.returncode:
        result('lens_boxes_render_%s' % lens, False, p.stderr.strip())
    else:
        check_boxes_lens(lens, d + '/ob/bl')
gt_checks.CHECKS.exit()
