#!/usr/bin/python3
"""Flow and boxes from a rolling shutter through a lens (spec/outputs.md
"Optical flow", "Boxes", "With a rolling shutter", "Through a lens")
against a solution computed here, independently of the player: each pixel
centre's ray by cv2.undistortPointsIter (cv2.fisheye.undistortPoints), met
with the scene's plane at its row's time; the row of the next frame that
sees the point solved as a fixed point in numpy, the point projected by
cv2.projectPoints (cv2.fisheye.projectPoints) with the camera at each
candidate row's time.  Prints "ok NAME" / "FAIL NAME: why".

  check_lens_rolling.py BIN DIR
"""
import json
import os
import sys
import numpy as np
import cv2

from glstest import Checks, undistort_iter

CHECKS = Checks('lens_rolling_setup')
result, run = CHECKS.result, CHECKS.run


BIN, D = sys.argv[1], sys.argv[2]
os.makedirs(D + '/src', exist_ok=True)
W, H, FX = 96, 48, 60.0
CX, CY = (W - 1) / 2, (H - 1) / 2
KM = np.array([[FX, 0, CX], [0, FX, CY], [0, 0, 1]])
DL = 1.0 / H  # line_delay: the readout takes the whole frame interval
LENSES = {'brown': ('distortion', [-0.12, 0.0, 0.0, 0.0]), 'fisheye': ('fisheye', [0.05, -0.01, 0.002, -0.0004])}
CRIT = (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 200, 1e-14)
# Each pixel's depth is read at the plain fine image's pixel nearest to its
# centre's ray: at least 4 fine pixels an image pixel (spec/camera.md "The
# distorted image"), so up to 1/8 px each way off the centre.
OFF = 1.0 / 8


def camera(path, lens, extra):
    key, k = LENSES[lens]
    with open(path, 'w') as f:
        f.write('width %d\nheight %d\nfx %.17g\nfy %.17g\ncx %.17g\ncy %.17g\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 1000\n'
                '%s %s\npose rig\nline_delay %.17g\n' % (W, H, FX, FX, CX, CY, key, ' '.join("%.17g" % x for x in k), DL)
                + extra)


def rays(lens, u, v):
    """the undistorted rays (x, y) of pixel positions u, v"""
    key, k = LENSES[lens]
    pts = np.stack([u.ravel(), v.ravel()], axis=1).reshape(-1, 1, 2).astype(np.float64)
    if lens == 'fisheye':
        r = cv2.fisheye.undistortPoints(pts, KM, np.array(k), criteria=CRIT)
    else:
        r = undistort_iter(pts, KM, np.array(k), CRIT)
    return r.reshape(u.shape + (2,))


def project(lens, Pc):
    """camera-frame points (..., 3) -> pixels (..., 2) through the lens"""
    key, k = LENSES[lens] if lens != 'none' else ('', [0.0] * 4)
    p = Pc.reshape(-1, 1, 3).astype(np.float64)
    z = np.zeros(3)
    if lens == 'fisheye':
        q, _ = cv2.fisheye.projectPoints(p, z, z, KM, np.array(k))
    else:
        q, _ = cv2.projectPoints(p, z, z, KM, np.array(k))
    return q.reshape(Pc.shape[:-1] + (2,))


u, v = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))

# ---- flow: the camera moves V a frame past the tilted plane
# z = 20 + 0.3 x (camera centre V t at frame t, no rotation); line_delay
# 1/H, bands of one row (each row at its own time).  Pixel (u, v) of frame
# 1 sees the plane at time 1 + v D along its centre's ray; the next frame's
# row v' that sees that point is the fixed point of v' = the row of the
# point's projection with the camera at 2 + v' D (its iteration contracts:
# the point moves far less than a row per row of readout).
V = np.array([0.5, 0.4, 2.0])
with open(D + '/src/Tilt.scene', 'w') as f:
    f.write('color(1, 1, 1);\npoly { vert(-50, -50, 5); vert(50, -50, 35); vert(50, 50, 35); vert(-50, 50, 5); }\n')
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/tilt.glsb', 'Tilt'])
with open(D + '/traj_v.txt', 'w') as f:
    for k in range(5):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %.17g %.17g %.17g\n' % ((k, k) + tuple(-V * k)))


def plane_point(d, C0):
    """the ray d (..., 2) from camera centre C0 (..., 3) met with the plane"""
    s = (20 + 0.3 * C0[..., 0] - C0[..., 2]) / (1 - 0.3 * d[..., 0])
    return C0 + s[..., None] * np.stack([d[..., 0], d[..., 1], np.ones_like(s)], axis=-1)


def next_row(lens, P, t1, vel):
    """the fixed point: the row of frame t1's readout that sees world point
    P (camera centre vel * t); u', v' and convergence"""
    vp = np.zeros(P.shape[:-1])
    for _ in range(200):
        t = t1 + np.clip(vp, 0, H - 1) * DL
        q = project(lens, P - vel * t[..., None])
        step = np.abs(q[..., 1] - vp)
        vp = q[..., 1]
    return q[..., 0], vp, step.max()


def solve(lens, du=0.0, dv=0.0, vel=V, t1=2.0):
    """the flow of every pixel whose depth is the plane's at the ray of
    (u + du, v + dv), taken along its own centre's ray"""
    C0 = vel[None, None, :] * (1 + v * DL)[..., None]
    d = rays(lens, u, v)
    P = plane_point(d, C0)
    if du or dv:  # the same depth Zc along the centre's ray
        Zo = plane_point(rays(lens, u + du, v + dv), C0)[..., 2] - C0[..., 2]
        P = C0 + Zo[..., None] * np.stack([d[..., 0], d[..., 1], np.ones_like(Zo)], axis=-1)
    up, vp, step = next_row(lens, P, t1, vel)
    return np.stack([up - u, vp - v], axis=2), step


for lens in LENSES:
    camera(D + '/%s.cam' % lens, lens, '')
    out = D + '/flow_' + lens
    p = run([BIN + '/glsplay', D + '/tilt.glsb', '--camera', D + '/%s.cam' % lens, '--trajectory',
             D + '/traj_v.txt', '--frames', '1', '--outputs', 'flow', '-o', out, '--explain'])
    if lens == 'brown':
        result('lens_rolling_flow_explain', 'lens with the rolling shutter: flow: ' in p.stdout, p.stdout[-400:])
    flo = cv2.readOpticalFlow(out + '/%s/flow_000001.flo' % lens)
    fmask = cv2.imread(out + '/%s/flowmask_000001.png' % lens, cv2.IMREAD_UNCHANGED)
    want, step = solve(lens)
    # the bound: the flow of the depth read up to OFF px each way off the
    # centre (the corners of that square, the plane's depth being monotone
    # across it), plus 1e-3 px for the rows' poses linear between whole rows
    dev = np.max([np.abs(solve(lens, a * OFF, b * OFF)[0] - want).max(axis=2)
                  for a in (-1, 1) for b in (-1, 1)], axis=0)
    bound = dev + 1e-3
    if flo is None or fmask is None:
        result('lens_rolling_flow_fixed_point_' + lens, False, 'no flow files')
        continue
    ferr = np.abs(flo - want).max(axis=2)
    up, vp = want[..., 0] + u, want[..., 1] + v
    inside = (np.floor(up + 0.5) >= 0) & (np.floor(up + 0.5) < W) & (np.floor(vp + 0.5) >= 0) & \
        (np.floor(vp + 0.5) < H)
    # a target within the bound of the image's border may fall either side
    edge = (np.minimum(np.abs(up + 0.5), np.abs(up - W + 0.5)) <= bound) | \
        (np.minimum(np.abs(vp + 0.5), np.abs(vp - H + 0.5)) <= bound)
    # what tells the solution apart: the same fixed point through a pinhole
    # (the lens left out), and the global shutter's flow through the lens
    C0 = V[None, None, :] * (1 + v * DL)[..., None]
    P = plane_point(rays(lens, u, v), C0)
    glob = project(lens, P - 2 * V)[..., 1] - v
    pin = np.abs(np.stack(next_row('none', P, 2.0, V)[:2], axis=2) - np.stack([up, vp], axis=2)).max()
    i = np.unravel_index(ferr.argmax(), ferr.shape)
    result('lens_rolling_flow_fixed_point_' + lens,
           step < 1e-9 and (ferr <= bound).all() and np.array_equal((fmask == 1) & ~edge, inside & ~edge) and
           ((fmask == 1) | (fmask == 3)).all() and np.abs(glob - want[..., 1]).max() > 1 and pin > 1,
           'largest error %.3g px at %s (flow %s, want %s, bound %.3g; largest bound %.3g); mask visible %d, '
           'in the image %d, others %s; global shutter differs by %.3f px, a pinhole\'s rows by %.3f px'
           % (ferr.max(), i, flo[i], want[i], bound[i], bound.max(), (fmask == 1).sum(), inside.sum(),
              np.unique(fmask).tolist(), np.abs(glob - want[..., 1]).max(), pin))
    print('# %s: largest error %.3g px, largest bound %.3g px' % (lens, ferr.max(), bound.max()))

# ---- a moving instance under a still rolling camera through the lens: the
# square (4 x 4 at Z0, in front of a wall at 30) moves M = (1, 0.5, 0) a
# frame.  A pixel on it at frame 1 sees its point at time 1 + v D; the
# point is at P + (t - 1 - v D) M at time t; the row v' of frame 2 that
# sees it is the fixed point as above.  The still wall has no flow, and is
# occluded (mask 2) where the square covers it in frame 2's readout: its
# pixel's ray at Z0 on the square at 2 + v D (pixels within a pixel of the
# square's edge, read at their nearest fine pixel, left out).
Z0 = 10.0
M = np.array([1.0, 0.5, 0.0])
with open(D + '/src/Sq.scene', 'w') as f:
    f.write('color(1, 1, 1);\npoly { vert(-2, -2, 0); vert(2, -2, 0); vert(2, 2, 0); vert(-2, 2, 0); }\n')
with open(D + '/src/MovWall.scene', 'w') as f:
    f.write('poly { vert(-50, -50, 30); vert(50, -50, 30); vert(50, 50, 30); vert(-50, 50, 30); }\n'
            'push; trans(0, 0, %.17g); call("Sq", "mover"); pop;\n' % Z0)
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/movwall.glsb', 'MovWall'])
with open(D + '/mover.txt', 'w') as f:
    f.write('# glsroad motion 1\n')
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %.17g %.17g 0\n' % ((k, k) + tuple(M[:2] * k)))
with open(D + '/still.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 0 0 0\n' % (k, k))
lens = 'brown'
out = D + '/movflow'
run([BIN + '/glsplay', D + '/movwall.glsb', '--camera', D + '/%s.cam' % lens, '--trajectory', D + '/still.txt',
     '--motion', 'mover=' + D + '/mover.txt', '--frames', '1', '--outputs', 'flow,instance', '-o', out])
flo = cv2.readOpticalFlow(out + '/%s/flow_000001.flo' % lens)
fmask = cv2.imread(out + '/%s/flowmask_000001.png' % lens, cv2.IMREAD_UNCHANGED)
ids = cv2.imread(out + '/%s/instance_000001.png' % lens, cv2.IMREAD_UNCHANGED)
if flo is None or fmask is None or ids is None:
    result('lens_rolling_flow_moving_instance', False, 'no flow or instance files')
else:
    d = rays(lens, u, v)
    sq = ids == ids.max()
    t0 = 1 + v * DL
    P = Z0 * np.stack([d[..., 0], d[..., 1], np.ones_like(t0)], axis=-1)
    up, vp, step = next_row(lens, P - t0[..., None] * M + 2 * M, 0.0, -M)
    want = np.stack([up - u, vp - v], axis=2)
    e_sq = np.abs(flo[sq] - want[sq]).max() if sq.any() else np.inf
    e_bg = np.abs(flo[(ids > 0) & ~sq]).max()
    # the wall behind the square in frame 2's readout
    off = Z0 * d - (2 + v * DL)[..., None] * M[:2]
    cov2 = (np.abs(off) <= 2).all(axis=2)
    amb = (np.abs(np.abs(off) - 2) <= Z0 / FX * 1.5).any(axis=2) & (np.abs(off) <= 2 + Z0 / FX * 1.5).all(axis=2)
    wall = (ids > 0) & ~sq & ~amb
    occ_ok = np.array_equal(fmask[wall] == 2, cov2[wall]) and (fmask[wall & ~cov2] == 1).all()
    # a pinhole's rows or the global shutter would put the square elsewhere
    glob = project(lens, P + (1 - t0[..., None]) * M)[..., 1] - v
    result('lens_rolling_flow_moving_instance',
           sq.sum() > 100 and step < 1e-9 and e_sq <= 1e-3 and e_bg <= 1e-6 and (fmask[sq] == 1).all() and occ_ok and
           (fmask[wall] == 2).sum() > 50 and np.abs(glob[sq] - want[sq][:, 1]).max() > 0.05,
           'square %d px, flow off by %.3g; still wall off by %.3g; square visible %s; wall occluded %d, want %d '
           '(mismatched %d); global shutter differs by %.3f px'
           % (sq.sum(), e_sq, e_bg, (fmask[sq] == 1).all(), (fmask[wall] == 2).sum(), cov2[wall].sum(),
              ((fmask[wall] == 2) != cov2[wall]).sum(), np.abs(glob[sq] - want[sq][:, 1]).max()))

# ---- boxes: the square (at x -9 .. -5, Z0), the camera moving +x 2 a
# frame (frame 1's at x 2): the 2D box from the rolling instance image
# through the lens (each pixel centre's ray at its row's time on the
# square; a pixel whose ray passes within OFF px of an edge may go either
# way), the 3D corners in the frame time's camera, truncated through the
# model at the frame time (cv2.projectPoints on the edges' 64 steps: the
# square crosses the image's left border), the visible fraction the rolling
# pixels over the frame time's (no occluder; 0.02 for the nearest fine
# pixels along the edges).
SX = -7.0
with open(D + '/src/Boxed.scene', 'w') as f:
    f.write('push; trans(%.17g, 0, %.17g); call("Sq", "sq"); pop;\n' % (SX, Z0))
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/boxed.glsb', 'Boxed'])
with open(D + '/traj_x.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %.17g 0 0\n' % (k, k, -2.0 * k))  # C = (2 k, 0, 0)


def on_square(lens, du, dv, t):
    d = rays(lens, u + du, v + dv)
    return (np.abs(Z0 * d[..., 0] + 2 * t - SX) <= 2) & (np.abs(Z0 * d[..., 1]) <= 2)


def bbox(cov):
    if not cov.any():
        return np.array([np.inf, np.inf, -np.inf, -np.inf])
    return np.array([u[cov].min() - 0.5, v[cov].min() - 0.5, u[cov].max() + 0.5, v[cov].max() + 0.5])


for lens in LENSES:
    out = D + '/boxes_' + lens
    p = run([BIN + '/glsplay', D + '/boxed.glsb', '--camera', D + '/%s.cam' % lens, '--trajectory', D + '/traj_x.txt',
             '--frames', '1', '--outputs', 'boxes,instance', '-o', out, '--explain'])
    if lens == 'brown':
        result('lens_rolling_boxes_explain', 'lens with the rolling shutter: boxes: ' in p.stdout, p.stdout[-400:])
    with open(out + '/%s/boxes_000001.json' % lens) as f:
        bx = json.load(f)['boxes']
    tr = 1 + v * DL  # each row's time
    cov = on_square(lens, 0, 0, tr)
    corners = [on_square(lens, a * OFF, b * OFF, tr) for a in (-1, 1) for b in (-1, 1)]
    sure, maybe = np.logical_and.reduce(corners), np.logical_or.reduce(corners)
    bs, bm = bbox(sure), bbox(maybe)
    want_c = np.array([[SX + (2 if k & 1 else -2) - 2, 2 if k & 2 else -2, Z0] for k in range(8)])
    pts = []
    for a in range(8):
        for bit in range(3):
            b = a | (1 << bit)
            if b != a:
                st = np.arange(65)[:, None] / 64
                pts.append(want_c[a] + st * (want_c[b] - want_c[a]))
    q = project(lens, np.vstack(pts))
    u0, v0, u1, v1 = q[:, 0].min(), q[:, 1].min(), q[:, 0].max(), q[:, 1].max()
    iu, iv = min(u1, W - 0.5) - max(u0, -0.5), min(v1, H - 0.5) - max(v0, -0.5)
    trunc = 1 - (iu * iv if iu > 0 and iv > 0 else 0) / ((u1 - u0) * (v1 - v0))
    frac = cov.sum() / on_square(lens, 0, 0, 1.0).sum()
    # a global shutter's box (the frame time's) differs: its rows are not sheared
    glob = bbox(on_square(lens, 0, 0, np.ones_like(tr)))
    if len(bx) != 1:
        result('lens_rolling_boxes_' + lens, False, 'boxes %s' % bx)
        continue
    got = np.array(bx[0]['bbox'])
    lo, hi = np.minimum(bs, bm), np.maximum(bs, bm)
    result('lens_rolling_boxes_' + lens,
           (got >= lo).all() and (got <= hi).all() and np.abs(np.array(bx[0]['corners']) - want_c).max() < 1e-9 and
           abs(bx[0]['truncated'] - trunc) < 1e-9 and trunc > 0.05 and abs(bx[0]['visible_fraction'] - frac) < 0.02
           and np.abs(glob - bbox(cov)).max() >= 1,
           'bbox %s, want between %s and %s (global shutter %s); corners %s, want %s; truncated %r, cv2 %r; '
           'visible %.4f, rays %.4f' % (got.tolist(), bs.tolist(), bm.tolist(), glob.tolist(), bx[0]['corners'],
                                         want_c.tolist(), bx[0]['truncated'], trunc, bx[0]['visible_fraction'], frac))
CHECKS.exit()
