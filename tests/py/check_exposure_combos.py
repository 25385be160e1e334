#!/usr/bin/python3
"""Motion blur, rolling shutter and depth of field through a distorted lens
(spec/camera.md "Through a lens" under "Motion blur, rolling shutter, depth
of field") against images computed here, independently of the player: each
pixel's area (a dense grid of sub-pixel points) mapped through the inverse
model (cv2.undistortPointsIter) onto the scene's plane, at each sub-frame
time (the midpoints of the exposure's equal sub-intervals) or at each row's
time.  Prints "ok NAME" / "FAIL NAME: why".

  check_exposure_combos.py BIN DIR
"""
import os
import sys
import numpy as np
import cv2

from glstest import Checks, undistort_iter

CHECKS = Checks('exposure_combos_setup')
result, run, grey = CHECKS.result, CHECKS.run, CHECKS.grey


BIN, D = sys.argv[1], sys.argv[2]
os.makedirs(D + '/src', exist_ok=True)
W, H, FX = 96, 48, 60.0
CX, CY = (W - 1) / 2, (H - 1) / 2
DIST = [-0.12, 0.0, 0.0, 0.0]  # barrel: one-to-one over the image
KM = np.array([[FX, 0, CX], [0, FX, CY], [0, 0, 1]])
Z0 = 10.0
SUB = 8  # sub-pixel points per axis for the expected images
# The lens's image reads each anti-aliasing sample bilinearly in a fine
# image of half-pixel boxes (spec/camera.md "The distorted image"): an
# edge is spread by about half a pixel, which moves a pixel beside it by up
# to about 1/8 from the exact box (the sharp lens image shows the same).
# Edges that cross it (a blurred ramp, a spread edge) average that out.
TOL_EDGE = 0.16


def camera(path, extra='', pose=''):
    with open(path, 'w') as f:
        f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 1000\n'
                'distortion %s\n' % (W, H, FX, FX, CX, CY, ' '.join(repr(k) for k in DIST)) + pose + extra)


# the undistorted rays (x, y) of SUB x SUB points spread over every pixel
# (midpoints of equal sub-squares: the box filter), shape (H, W, SUB*SUB)
o = (np.arange(SUB) + 0.5) / SUB - 0.5
ou, ov = np.meshgrid(o, o)
uu = np.arange(W)[None, :, None] + ou.ravel()[None, None, :]
vv = np.arange(H)[:, None, None] + ov.ravel()[None, None, :]
uu, vv = np.broadcast_arrays(uu, vv)
pts = np.stack([uu.ravel(), vv.ravel()], axis=1).reshape(-1, 1, 2).astype(np.float64)
crit = (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 200, 1e-14)
ray = undistort_iter(pts, KM, np.array(DIST), crit).reshape(H, W, SUB * SUB, 2)
RX, RY = ray[..., 0], ray[..., 1]
# the pixel centres' rays
cpts = np.stack(np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64)), axis=2).reshape(-1, 1, 2)
cray = undistort_iter(cpts, KM, np.array(DIST), crit).reshape(H, W, 2)

# ---- motion blur through the lens: a white 4 x 4 square at Z0 moving +x
# one unit per frame.  The expected image: the mean of the distorted sharp
# images at the K sub-frame times of the shutter.
CHECKS.moving_square(BIN, D, Z0)
S, K = 0.5, 16
camera(D + '/lblur.cam', 'shutter %r\nexposure_samples %d\n' % (S, K))
out = D + '/blur'
p = run([BIN + '/glsplay', D + '/moving.glsb', '--camera', D + '/lblur.cam', '--motion', 'mover=' + D + '/mover.txt',
         '--frame', '1', '--aa', '4', '--outputs', 'image,depth', '--image-format', 'png16', '-o', out, '--explain'])
result('lens_motion_blur_explain', 'motion blur: on (key shutter 0.5)' in p.stdout and
       'lens with the exposure: each of the 16 sub-frame renders draws the anti-aliased undistorted image' in p.stdout,
       p.stdout[-900:])


def square(t):
    """the sharp image at frame 1 + t: the square's area in each pixel"""
    X, Y = RX * Z0, RY * Z0
    inside = (X >= -1 + t) & (X <= 3 + t) & (Y >= -2) & (Y <= 2)
    return inside.mean(axis=2)


times = S * ((np.arange(K) + 0.5) / K - 0.5)
want = np.mean([square(t) for t in times], axis=0)
sharp = square(0.0)
img = grey(out + '/lblur/image_000001.png')
err = np.abs(img - want)
# the rows between the square's top and bottom edges (v 11.5 .. 35.5):
# only the blurred ramps, the fine image's spread averaged over them; the
# 4x4 lattice against the dense box
mid = slice(15, 33)
result('lens_motion_blur_image', err[mid].max() <= 0.03 and err.max() <= TOL_EDGE and
       np.abs(sharp - want)[mid].max() > 0.3,
       'largest error %.4f at %s, %.4f in rows 15..32 (the blur changes pixels by %.3f)'
       % (err.max(), np.unravel_index(err.argmax(), err.shape), err[mid].max(), np.abs(sharp - want).max()))
# the area of each of those rows is the blurred row's whatever the ramps
row_err = np.abs(img.sum(axis=1) - want.sum(axis=1))[mid].max()
result('lens_motion_blur_row_area', row_err <= 0.05, 'row sums differ by %.4f px' % row_err)
# depth: at the frame time through the lens, never blurred
z = cv2.imread(out + '/lblur/depth_000001.pfm', cv2.IMREAD_UNCHANGED)
X, Y = cray[..., 0] * Z0, cray[..., 1] * Z0
cov = (X >= -1) & (X <= 3) & (Y >= -2) & (Y <= 2)
zok = np.isfinite(z)
edge = np.zeros_like(cov)
for dx in (-1, 0, 1):
    for dy in (-1, 0, 1):
        edge |= np.roll(np.roll(cov, dx, 1), dy, 0) != cov
result('lens_motion_blur_depth_frame_time', z is not None and np.array_equal(zok[~edge], cov[~edge]) and
       np.abs(z[zok] - Z0).max() < 1e-3, 'the depth is not the frame time\'s square at Z0')

# ---- rolling shutter through the lens: a camera translating +x one unit
# per frame looks at a bright half-plane x >= 0 at Z0; distorted row v is
# exposed at frame 1 + v D.
with open(D + '/src/Half.scene', 'w') as f:
    f.write('color(1, 1, 1);\npoly { vert(0, -50, %r); vert(100, -50, %r); vert(100, 50, %r); vert(0, 50, %r); }\n'
            % ((Z0,) * 4))
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/half.glsb', 'Half'])
with open(D + '/traj.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %d 0 0\n' % (k, k, -k))  # T = -R C, C = (k, 0, 0)
DL = 1.0 / H
camera(D + '/lrs.cam', 'line_delay %r\n' % DL, 'pose rig\n')
out = D + '/rs'
p = run([BIN + '/glsplay', D + '/half.glsb', '--camera', D + '/lrs.cam', '--trajectory', D + '/traj.txt', '--frames',
         '1', '--aa', '4', '--outputs', 'image,depth', '--image-format', 'png16', '-o', out, '--explain'])
result('lens_rolling_explain', 'rolling shutter: on (key line_delay' in p.stdout and
       'lens with the exposure: ground truth per band of rows' in p.stdout, p.stdout[-900:])
tv = 1 + np.arange(H) * DL  # each row's time: the camera centre's x
want = ((RX * Z0 + tv[:, None, None]) >= 0).mean(axis=2)
glob = ((RX * Z0 + 1) >= 0).mean(axis=2)  # a global shutter at the frame time
img = grey(out + '/lrs/image_000001.png')
# the edge's column per row: the covered length of the row
got_e, want_e, glob_e = (W - img.sum(axis=1)), (W - want.sum(axis=1)), (W - glob.sum(axis=1))
err = np.abs(got_e - want_e)
# bands of at most 1/8 px of motion at their middle row's time (1/16 px),
# the box filters and 16-bit rounding (1/32 px)
result('lens_rolling_edge_per_row', err.max() <= 1.0 / 16 + 1.0 / 32 and np.abs(glob_e - want_e).max() > 0.5,
       'largest error %.4f px at row %d (edge %.4f, want %.4f); global shutter differs by %.3f px'
       % (err.max(), err.argmax(), got_e[err.argmax()], want_e[err.argmax()], np.abs(glob_e - want_e).max()))
result('lens_rolling_image', np.abs(img - want).max() <= TOL_EDGE, 'largest pixel error %.4f' % np.abs(img - want).max())
# depth per row at the row's time through the lens: the pixel centres on
# the plane (those within a quarter pixel of the edge left out: the band's
# time and the nearest fine pixel)
z = cv2.imread(out + '/lrs/depth_000001.pfm', cv2.IMREAD_UNCHANGED)
cov = (cray[..., 0] * Z0 + tv[:, None]) >= 0
near = np.abs(cray[..., 0] * Z0 + tv[:, None]) < 0.25 * Z0 / FX
bad = np.nonzero(((np.isfinite(z) != cov) & ~near).any(axis=1))[0]
result('lens_rolling_depth_per_row', z is not None and len(bad) == 0,
       'rows whose covered pixels are not those of the row\'s time: %s' % bad[:8])

# ---- depth of field through the lens: an edge in the plane of focus is
# where the lens without aperture puts it (the shear acts on the
# undistorted ray, which the plane Zc = focus does not see); an edge
# beyond it is spread, about the same place.
A, F = 0.5, 5.0
for Z, tag in ((F, 'in_focus'), (Z0, 'defocus')):
    with open(D + '/src/Edge.scene', 'w') as f:
        f.write('color(1, 1, 1);\npoly { vert(0, -50, %r); vert(100, -50, %r); vert(100, 50, %r); vert(0, 50, %r); }\n'
                % ((Z,) * 4))
    run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/edge.glsb', 'Edge'])
    camera(D + '/ldof.cam', 'aperture %r\nfocus %r\nexposure_samples 64\n' % (A, F))
    out = D + '/dof_' + tag
    p = run([BIN + '/glsplay', D + '/edge.glsb', '--camera', D + '/ldof.cam', '--aa', '4', '--outputs', 'image',
             '--image-format', 'png16', '-o', out, '--explain'])
    img = grey(out + '/ldof/image_000000.png')
    want = (RX >= 0).mean(axis=2)  # the sharp edge through the lens
    e_err = np.abs(img.sum(axis=1) - want.sum(axis=1)).max()
    if tag == 'in_focus':
        result('lens_depth_of_field_explain', 'depth of field: on (keys aperture 0.5, focus 5)' in p.stdout and
               'and lens point (sheared before the lens model)' in p.stdout, p.stdout[-900:])
        err = np.abs(img - want).max()
        # a sharp edge: the lens's spread of up to half a pixel, about 1/16
        # beside an edge on a pixel border (no ramp to average it out)
        result('lens_depth_of_field_in_focus_unchanged', err <= 0.08 and e_err <= 1.0 / 16,
               'largest pixel error %.4f, edge moved %.4f px' % (err, e_err))
    else:
        # the circle of confusion, undistorted pixels: FX A |Z - F| / (Z F)
        c = FX * A * abs(Z - F) / (Z * F)
        mid = img[H // 2]
        lit = np.nonzero((mid > 0.01) & (mid < 0.99))[0]
        width = lit[-1] - lit[0] + 1 if len(lit) else 0
        result('lens_depth_of_field_spread', e_err <= 0.1 and abs(width - (c + 1)) <= 1.5,
               'edge moved %.4f px; blurred over %d px, c + 1 = %.3f' % (e_err, width, c + 1))

# ---- points with a rolling shutter (spec/outputs.md): a camera moving
# (0.5, 0, 2) a frame towards a tilted plane z = 20 + 0.3 x; each row's
# depth is in the camera frame of its own time, and the PLY's world points
# unprojected with that pose lie on the plane (float depth: 1e-6 relative);
# with the frame's pose for every row they would miss it by up to the
# readout's 2 units of travel.


def read_ply(path):
    with open(path, 'rb') as f:
        data = f.read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    rec = np.frombuffer(data[end:], dtype=np.dtype([('p', '<f8', 3), ('c', 'u1', 3)]))
    return rec['p']


with open(D + '/src/Tilt.scene', 'w') as f:
    f.write('color(1, 1, 1);\npoly { vert(-50, -50, 5); vert(50, -50, 35); vert(50, 50, 35); vert(-50, 50, 5); }\n')
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/tilt.glsb', 'Tilt'])
with open(D + '/traj_z.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %r 0 %r\n' % (k, k, -0.5 * k, -2.0 * k))  # C = (0.5 k, 0, 2 k)
with open(D + '/prs.cam', 'w') as f:
    f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 1000\n'
            'pose rig\nline_delay %r\n' % (W, H, FX, FX, CX, CY, 1.0 / H))
camera(D + '/plrs.cam', 'line_delay %r\n' % (1.0 / H), 'pose rig\n')
out = D + '/pts'
run([BIN + '/glsplay', D + '/tilt.glsb', '--camera', D + '/prs.cam', '--camera', D + '/plrs.cam', '--trajectory',
     D + '/traj_z.txt', '--frames', '1', '--outputs', 'depth,points', '-o', out])
for cam, tol, why in (('prs', 1e-4, 'float depth'),
                      ('plrs', 0.02, 'the nearest fine pixel\'s depth, up to 1/8 px each way off the ray, on a '
                                     'plane whose depth changes 0.1 a pixel')):
    P = read_ply(out + '/%s/points_000001.ply' % cam)
    z = cv2.imread(out + '/%s/depth_000001.pfm' % cam, cv2.IMREAD_UNCHANGED)
    off = np.abs(P[:, 2] - (20 + 0.3 * P[:, 0])) / np.sqrt(1 + 0.09) if len(P) else np.array([np.inf])
    # the depth rows do change with the row's time: the camera moved 2
    # units closer over the readout
    zr = np.nanmean(np.where(np.isfinite(z), z, np.nan)[:, W // 2 - 2:W // 2 + 3], axis=1)
    result('rolling_shutter_points_on_plane_' + ('lens' if cam == 'plrs' else 'pinhole'),
           len(P) == np.isfinite(z).sum() and off.max() <= tol and zr[0] - zr[-1] > 1.5,
           'points %d (depth %d), largest distance from the plane %.3g (tolerance %g: %s); depth rows %.3f..%.3f'
           % (len(P), np.isfinite(z).sum(), off.max(), tol, why, zr[0], zr[-1]))

# ---- flow with a rolling shutter (spec/outputs.md "Optical flow", "With a
# rolling shutter"): the camera moves V = (0.5, 0.4, 2) a frame past the
# tilted plane z = 20 + 0.3 x; line_delay 1/H (bands of one row: each row
# at its own time).  numpy: pixel (u, v) of frame 1 sees the plane at its
# row's time 1 + v D (the ray met with the plane); the next frame's row v'
# that sees that point solves v' = fy (Y - Vy t) / (Z - Vz t) + cy with
# t = 2 + v' D, a quadratic in v' (the root nearest the frame time's
# projection); u' from the camera at that time.  The rows are
# interpolated linearly between the poses of whole rows: within 1e-3 px.
import json
V = np.array([0.5, 0.4, 2.0])
with open(D + '/traj_v.txt', 'w') as f:
    for k in range(5):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %r %r %r\n' % ((k, k) + tuple(-V * k)))
with open(D + '/frs.cam', 'w') as f:
    f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 1000\n'
            'pose rig\nline_delay %r\n' % (W, H, FX, FX, CX, CY, 1.0 / H))
out = D + '/flow'
p = run([BIN + '/glsplay', D + '/tilt.glsb', '--camera', D + '/frs.cam', '--trajectory', D + '/traj_v.txt',
         '--frames', '1', '--outputs', 'flow', '-o', out, '--explain'])
result('rolling_shutter_flow_explain', 'rolling shutter: flow from each row\'s time to the row of frame t+1' in p.stdout,
       p.stdout[-600:])
flo = cv2.readOpticalFlow(out + '/frs/flow_000001.flo')
fmask = cv2.imread(out + '/frs/flowmask_000001.png', cv2.IMREAD_UNCHANGED)
DL = 1.0 / H
u, v = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))
C0 = V[None, None, :] * (1 + v * DL)[..., None]
dx, dy = (u - CX) / FX, (v - CY) / FX
sl = (20 + 0.3 * C0[..., 0] - C0[..., 2]) / (1 - 0.3 * dx)
X, Y, Z = C0[..., 0] + sl * dx, C0[..., 1] + sl * dy, C0[..., 2] + sl
a = -V[2] * DL
b = Z - 2 * V[2] + FX * V[1] * DL + CY * V[2] * DL
c = -(FX * (Y - 2 * V[1]) + CY * (Z - 2 * V[2]))
disc = np.sqrt(b * b - 4 * a * c)
r1, r2 = (-b + disc) / (2 * a), (-b - disc) / (2 * a)
v_frame = FX * (Y - 2 * V[1]) / (Z - 2 * V[2]) + CY  # the frame time's projection
vp = np.where(np.abs(r1 - v_frame) < np.abs(r2 - v_frame), r1, r2)
# above the first row or below the last, no row's time sees it: the
# readout's first or last time (poses are never extrapolated); the point
# is then out of view
for edge_row, sel in ((0, vp < 0), (H - 1, vp > H - 1)):
    te = 2 + edge_row * DL
    vp = np.where(sel, FX * (Y - V[1] * te) / (Z - V[2] * te) + CY, vp)
t = 2 + np.clip(vp, 0, H - 1) * DL
up = FX * (X - V[0] * t) / (Z - V[2] * t) + CX
want = np.stack([up - u, vp - v], axis=2)
inside = (np.floor(up + 0.5) >= 0) & (np.floor(up + 0.5) < W) & (np.floor(vp + 0.5) >= 0) & (np.floor(vp + 0.5) < H)
ferr = np.abs(flo - want).max(axis=2)
# a global shutter's flow (frame 1 to frame 2 at the frame times) differs
# by the readout: how much the test tells them apart
gl_v = FX * (Y - 2 * V[1]) / (Z - 2 * V[2]) + CY - v
result('rolling_shutter_flow_fixed_point', flo is not None and ferr.max() <= 1e-3 and
       np.array_equal(fmask == 1, inside) and np.abs(gl_v - want[..., 1]).max() > 1,
       'largest error %.3g px at %s (flow %s, want %s); mask visible %d, in the image %d'
       % (ferr.max(), np.unravel_index(ferr.argmax(), ferr.shape), flo[np.unravel_index(ferr.argmax(), ferr.shape)]
          if flo is not None else None, want[np.unravel_index(ferr.argmax(), ferr.shape)], (fmask == 1).sum(),
          inside.sum()))
# the next frame's readout must lie within the trajectory's rows: frame 3's
# flow needs frame 4's rows up to 4 + (H - 1) D, beyond the last row (4)
p = run([BIN + '/glsplay', D + '/tilt.glsb', '--camera', D + '/frs.cam', '--trajectory', D + '/traj_v.txt', '--frames',
         '3', '--outputs', 'flow', '-o', D + '/flow_beyond'], want_rc=1)
result('rolling_shutter_flow_beyond_rows_refused', p.stderr == 'glsplay: error: camera frs, frame 3: its flow needs '
       'the poses of the rolling readout of frame 4, at frame 4.020833333333333 beyond the rows of the trajectory or '
       'a motion file; sub-frame poses are interpolated between rows, never extrapolated: render fewer --frames or '
       'extend the file\n' and not os.path.exists(D + '/flow_beyond/frs/flow_000003.flo'), repr(p.stderr))

# a moving instance under a still rolling camera: the square (at Z0, in
# front of a wall at 30) moves (1, 0.5) a frame, 6 and 3 px; its row in
# the next frame is later by dv rows, so it has moved for 1 + dv D frame
# intervals: dv = 3 (1 + dv D), dv = 3 / (1 - 3 D), du = 6 (1 + dv D)
with open(D + '/src/MovWall.scene', 'w') as f:
    f.write('poly { vert(-50, -50, 30); vert(50, -50, 30); vert(50, 50, 30); vert(-50, 50, 30); }\n'
            'push; trans(0, 0, %r); call("Sq", "mover"); pop;\n' % Z0)
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/movwall.glsb', 'MovWall'])
with open(D + '/mover2.txt', 'w') as f:
    f.write('# glsroad motion 1\n')
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %r %r 0\n' % (k, k, 1.0 * k, 0.5 * k))
with open(D + '/still.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 0 0 0\n' % (k, k))
run([BIN + '/glsplay', D + '/movwall.glsb', '--camera', D + '/frs.cam', '--trajectory', D + '/still.txt', '--motion',
     'mover=' + D + '/mover2.txt', '--frames', '1', '--outputs', 'flow,instance', '-o', D + '/movflow'])
flo = cv2.readOpticalFlow(D + '/movflow/frs/flow_000001.flo')
ids = cv2.imread(D + '/movflow/frs/instance_000001.png', cv2.IMREAD_UNCHANGED)
sq = ids == ids.max()
dv = 3 / (1 - 3 * DL)
du = 6 * (1 + dv * DL)
e_sq = np.abs(flo[sq] - [du, dv]).max() if sq.any() else np.inf
e_bg = np.abs(flo[(ids > 0) & ~sq]).max()
result('rolling_shutter_flow_moving_instance', sq.sum() > 100 and e_sq <= 1e-3 and e_bg <= 1e-3,
       'square %d px, flow off by %.3g (want %.4f, %.4f); still wall off by %.3g' % (sq.sum(), e_sq, du, dv, e_bg))

# ---- boxes with a rolling shutter: the 2D box from the rolling instance
# image (the square's slanted sides), the 3D corners at the frame time
with open(D + '/src/Boxed.scene', 'w') as f:
    f.write('push; trans(0, 0, %r); call("Sq", "sq"); pop;\n' % Z0)
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/boxed.glsb', 'Boxed'])
with open(D + '/traj_x.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %r 0 0\n' % (k, k, -2.0 * k))  # C = (2 k, 0, 0)
run([BIN + '/glsplay', D + '/boxed.glsb', '--camera', D + '/frs.cam', '--trajectory', D + '/traj_x.txt', '--frames',
     '1', '--outputs', 'boxes,instance', '-o', D + '/boxes'])
with open(D + '/boxes/frs/boxes_000001.json') as f:
    bx = json.load(f)['boxes']
Cx = 2 * (1 + v * DL)  # each row's camera centre
cov = (np.abs(Z0 * dx + Cx) <= 2) & (np.abs(Z0 * dy) <= 2)  # pixel centres on the square at the row's time
us, vs = u[cov], v[cov]
want_bb = [us.min() - 0.5, vs.min() - 0.5, us.max() + 0.5, vs.max() + 0.5]
want_c = np.array([[(2 if k & 1 else -2) - 2, 2 if k & 2 else -2, Z0] for k in range(8)])  # frame 1: C = (2, 0, 0)
ok = len(bx) == 1 and np.allclose(bx[0]['bbox'], want_bb, atol=0) and \
    np.abs(np.array(bx[0]['corners']) - want_c).max() < 1e-9
result('rolling_shutter_boxes', ok, 'boxes %s; want bbox %s, corners %s' % (
    [(b['bbox'], b['corners']) for b in bx], want_bb, want_c.tolist()))
CHECKS.exit()
