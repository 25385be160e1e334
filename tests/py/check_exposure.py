#!/usr/bin/python3
"""Motion blur, rolling shutter and depth of field (spec/camera.md "Motion
blur, rolling shutter, depth of field") against closed forms computed here
in numpy: the box filter of the shutter (a linear ramp of width speed * S),
the slanted edge of a rolling shutter (one column per row), the edge spread
of a uniform circle of confusion of diameter f A |Z - F| / (Z F); the
ground truth at the frame time; off when nothing asks for it.  Prints
"ok NAME" / "FAIL NAME: why".

  check_exposure.py BIN DIR
"""
import csv
import os
import sys
import numpy as np
import cv2

from glstest import Checks

CHECKS = Checks('exposure_setup')
result, run, grey = CHECKS.result, CHECKS.run, CHECKS.grey


BIN, D = sys.argv[1], sys.argv[2]
os.makedirs(D + '/src', exist_ok=True)
FX = 100.0
Z0 = 10.0  # depth of the moving square and of the edges


def camera(path, w, h, extra='', pose=''):
    with open(path, 'w') as f:
        f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 1000\n'
                % (w, h, FX, FX, (w - 1) / 2, (h - 1) / 2) + pose + extra)


def box_pixel(f, u, n=400):
    """f averaged over the pixel [u - 1/2, u + 1/2] (midpoint rule)"""
    x = u[:, None] + (np.arange(n)[None, :] + 0.5) / n - 0.5
    return f(x).mean(axis=1)


# ---- motion blur: a white 4 x 4 square at Z0 moving +x one unit (FX/Z0 =
# 10 px) per frame, shutter S: each edge becomes a linear ramp of width
# speed * S, the area under a row is conserved.
CHECKS.moving_square(BIN, D, Z0)
W, H, S, SPEED = 160, 40, 0.5, FX / Z0
camera(D + '/blur.cam', W, H, 'shutter %r\nexposure_samples 64\n' % S)
camera(D + '/sharp.cam', W, H)
cx = (W - 1) / 2
for aa in ('1', '4'):
    out = D + '/blur' + aa
    p = run([BIN + '/glsplay', D + '/moving.glsb', '--camera', D + '/blur.cam', '--camera', D + '/sharp.cam',
             '--motion', 'mover=' + D + '/mover.txt', '--frame', '1', '--aa', aa, '--outputs', 'image,depth',
             '--image-format', 'png16', '-o', out, '--explain'])
    m = 1 if aa == '1' else 16
    result('motion_blur_explain_aa' + aa, 'motion blur: on (key shutter 0.5): exposure [-0.25, 0.25]' in p.stdout and
           'exposure cost: 64 sub-frame renders x %d anti-aliasing sample' % m in p.stdout and
           p.stdout.count('motion blur: on') == 1, p.stdout[-800:])
    row = grey(out + '/blur/image_000001.png')[H // 2]
    sharp = grey(out + '/sharp/image_000001.png')[H // 2]
    # the square spans x in [-2, 2] + 1 + t at frame 1 + t: its edges in u
    uL, uR = cx + SPEED * (-2 + 1), cx + SPEED * (2 + 1)
    L = SPEED * S  # ramp width in pixels

    def blurred(x):
        # fraction of the exposure t in [-S/2, S/2] during which x is covered
        a = np.clip((x - (uL - L / 2)) / L, 0, 1)
        b = np.clip(((uR + L / 2) - x) / L, 0, 1)
        return np.minimum(a, b)
    u = np.arange(W, dtype=np.float64)
    if aa == '1':
        want = blurred(u)  # one sample at each pixel centre
        tol = 1.0 / 64 + 1.0 / 512  # the 64 time samples, 16-bit rounding
    else:
        want = box_pixel(blurred, u)  # the box filter of --aa as well
        tol = 1.0 / 64 + 1.0 / 32  # time samples, 4x4 area samples
    err = np.abs(row - want).max()
    result('motion_blur_ramp_aa' + aa, err <= tol, 'largest error %.4f > %.4f (row %s)' % (err, tol, np.round(row[60:80], 3)))
    # area under the row: the square's width, 40 px, blurred or not
    result('motion_blur_conserves_aa' + aa, abs(row.sum() - sharp.sum()) < 0.05 and abs(sharp.sum() - 40) < 0.05,
           'row sums %.4f (blurred), %.4f (sharp), want 40' % (row.sum(), sharp.sum()))
    zb = cv2.imread(out + '/blur/depth_000001.pfm', cv2.IMREAD_UNCHANGED)
    zs = cv2.imread(out + '/sharp/depth_000001.pfm', cv2.IMREAD_UNCHANGED)
    result('motion_blur_depth_at_frame_time_aa' + aa, zb is not None and np.array_equal(zb, zs),
           'the depth of a blurred frame differs from the unblurred frame\'s')

# ---- rolling shutter: a camera translating +x one unit per frame looks at
# a bright half-plane x >= 0 at Z0; row v is exposed at frame + v D, so the
# edge is at u(v) = cx - SPEED (1 + v D): a slanted line.
with open(D + '/src/Half.scene', 'w') as f:
    f.write('color(1, 1, 1);\npoly { vert(0, -50, %r); vert(100, -50, %r); vert(100, 50, %r); vert(0, 50, %r); }\n'
            % ((Z0,) * 4))
    # landmarks on the plane, 1 unit right of its edge, at rows 10.2 .. 70.2
    MARK_Y = (-2.93, -0.93, 1.07, 3.07)
    for i, y in enumerate(MARK_Y):
        f.write('mark("m%d", 1, %r, %r);\n' % (i, y, Z0))
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/half.glsb', 'Half'])
with open(D + '/traj.txt', 'w') as f:
    for k in range(4):
        f.write('%d %d 1 0 0 0 1 0 0 0 1 %d 0 0\n' % (k, k, -k))  # T = -R C, C = (k, 0, 0)
W, H = 120, 80
DL = 1.0 / H  # the readout takes one frame interval
camera(D + '/rs.cam', W, H, 'line_delay %r\n' % DL, 'pose rig\n')
camera(D + '/gs.cam', W, H, '', 'pose rig\n')
out = D + '/rs'
p = run([BIN + '/glsplay', D + '/half.glsb', '--camera', D + '/rs.cam', '--camera', D + '/gs.cam', '--trajectory',
         D + '/traj.txt', '--frames', '1', '--aa', '8', '--outputs', 'image,depth,instance,landmarks', '--image-format', 'png16',
         '-o', out, '--explain'])
result('rolling_shutter_explain', 'rolling shutter: on (key line_delay' in p.stdout, p.stdout[-600:])
cx = (W - 1) / 2


def edge_columns(img):
    # bright right of the edge: the pixel centres are at u, pixel u spans
    # [u - 1/2, u + 1/2]; the covered length of a row is (W - 1/2) - e
    return (W - 0.5) - img.sum(axis=1)


rs = edge_columns(grey(out + '/rs/image_000001.png'))
gs = edge_columns(grey(out + '/gs/image_000001.png'))
v = np.arange(H, dtype=np.float64)
want = cx - SPEED * (1 + v * DL)
err = np.abs(rs - want)
# bands of at most 1/8 px of motion drawn at their middle row's time: 1/16
# px; the 8x8 box filter and 16-bit rounding: 1/32 px
result('rolling_shutter_edge_per_row', err.max() <= 1.0 / 16 + 1.0 / 32,
       'largest error %.4f px at row %d (edge %.4f, want %.4f)' % (err.max(), err.argmax(), rs[err.argmax()],
                                                                  want[err.argmax()]))
result('rolling_shutter_slope', abs(np.polyfit(v, rs, 1)[0] + SPEED * DL) < 0.002,
       'slope %.5f px/row, want %.5f' % (np.polyfit(v, rs, 1)[0], -SPEED * DL))
result('global_shutter_edge_straight', np.abs(gs - (cx - SPEED)).max() <= 1.0 / 32,
       'the edge without line_delay moves: %s' % np.round(gs[:4], 4))
# a slower readout, D = 1/800: bands of several rows (1/8 px of motion
# each), each at its middle row's time; every row within 1/16 px of its
# own time's edge (+ 1/32 px of filter and rounding)
DL2 = 1.0 / 800
camera(D + '/rs2.cam', W, H, 'line_delay %r\n' % DL2, 'pose rig\n')
run([BIN + '/glsplay', D + '/half.glsb', '--camera', D + '/rs2.cam', '--trajectory', D + '/traj.txt', '--frames', '1',
     '--aa', '8', '--outputs', 'image', '--image-format', 'png16', '-o', out])
rs2 = edge_columns(grey(out + '/rs2/image_000001.png'))
want2 = cx - SPEED * (1 + v * DL2)
err2 = np.abs(rs2 - want2)
levels = len(np.unique(np.round(rs2, 3)))
result('rolling_shutter_bands_per_row', err2.max() <= 1.0 / 16 + 1.0 / 32 and 2 <= levels < H,
       'largest error %.4f px at row %d; %d edge positions over %d rows' % (err2.max(), err2.argmax(), levels, H))
# depth per row at its own time: the plane is at Z0 everywhere it covers;
# the covered columns follow the slanted edge
z = cv2.imread(out + '/rs/depth_000001.pfm', cv2.IMREAD_UNCHANGED)
covered = np.isfinite(z).sum(axis=1).astype(np.float64)  # pixel centres u >= edge
want_cov = W - np.ceil(want)
result('rolling_shutter_depth_per_row', z is not None and np.abs(covered - want_cov).max() <= 1,
       'covered columns per row %s, want %s' % (covered[:4], want_cov[:4]))

ids = cv2.imread(out + '/rs/instance_000001.png', cv2.IMREAD_UNCHANGED)
result('rolling_shutter_ids_per_row', ids is not None and np.array_equal(ids > 0, np.isfinite(z)) and
       np.abs((ids > 0).sum(axis=1) - want_cov).max() <= 1, 'the instance image and the depth disagree')
# landmarks at their band's time: u from the row's time within the band's
# 1/16 px, v and depth exact (the camera moves along x), visible against
# the depth of that row
with open(out + '/rs/landmarks_000001.csv') as f:
    rows = list(csv.DictReader(f))
bad = []
for r, y in zip(rows, MARK_Y):
    vv = (H - 1) / 2 + FX * y / Z0
    uu = cx + FX * 1 / Z0 - SPEED * (1 + np.floor(vv + 0.5) * DL)
    if not (abs(float(r['u']) - uu) <= 1.0 / 16 + 1e-9 and abs(float(r['v']) - vv) < 1e-9 and
            abs(float(r['depth']) - Z0) < 1e-9 and r['in_image'] == '1' and r['visible'] == '1'):
        bad.append((r['name'], r['u'], uu, r['v'], vv, r['visible']))
result('rolling_shutter_landmarks_per_row', len(rows) == len(MARK_Y) and not bad, 'rows %d; %s' % (len(rows), bad))
# points with a rolling shutter: tests/py/check_exposure_combos.py

# ---- depth of field: an edge (a half-plane x >= 0) at depth Z seen
# through a lens of diameter A focused at F.  Lens point l shifts it by
# FX l_x (1/F - 1/Z) px: the edge spread of a uniform disk of diameter
# c = FX A |Z - F| / (Z F) px.  In focus (Z = F): the pinhole's edge.
A, F = 0.5, 5.0


def disk_esf(x, c):
    """fraction of a uniform disk of diameter c left of x (x from its centre)"""
    r = c / 2
    x = np.clip(x / r, -1, 1)
    return (np.arccos(-x) + x * np.sqrt(1 - x * x)) / np.pi


for Z, tag in ((Z0, 'defocus'), (F, 'in_focus')):
    with open(D + '/src/Edge.scene', 'w') as f:
        f.write('color(1, 1, 1);\npoly { vert(0, -50, %r); vert(100, -50, %r); vert(100, 50, %r); vert(0, 50, %r); }\n'
                % ((Z,) * 4))
    run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/edge.glsb', 'Edge'])
    W, H = 120, 8
    camera(D + '/dof.cam', W, H, 'aperture %r\nfocus %r\nexposure_samples 256\n' % (A, F))
    camera(D + '/pin.cam', W, H)
    out = D + '/dof_' + tag
    p = run([BIN + '/glsplay', D + '/edge.glsb', '--camera', D + '/dof.cam', '--camera', D + '/pin.cam', '--aa', '4',
             '--outputs', 'image,depth', '--image-format', 'png16', '-o', out, '--explain'])
    result('depth_of_field_explain_' + tag, 'depth of field: on (keys aperture 0.5, focus 5): 256 lens points' in
           p.stdout and p.stdout.count('depth of field: on') == 1, p.stdout[-800:])
    row = grey(out + '/dof/image_000000.png')[H // 2]
    pin = grey(out + '/pin/image_000000.png')[H // 2]
    cx = (W - 1) / 2
    u = np.arange(W, dtype=np.float64)
    c = FX * A * abs(Z - F) / (Z * F)
    if c > 0:
        # bright right of the edge: a point x sees the edge blurred by the
        # disk: brightness = fraction of the disk left of x - cx
        want = box_pixel(lambda x: disk_esf(x - cx, c), u)
        err = np.abs(row - want).max()
        # 256 lens points (Vogel spiral), 4x4 area samples, 16 bits
        result('depth_of_field_edge_spread', err <= 0.03,
               'circle of confusion %.3f px: largest error %.4f (row %s, want %s)'
               % (c, err, np.round(row[50:70], 3), np.round(want[50:70], 3)))
        # the diameter the profile shows: its 0..1 width is c + 1 (the pixel)
        lit = np.nonzero((row > 0.002) & (row < 0.998))[0]
        width = lit[-1] - lit[0] + 1 if len(lit) else 0
        result('depth_of_field_coc_diameter', abs(width - (c + 1)) <= 1.5,
               'blurred over %d px, c + 1 = %.3f' % (width, c + 1))
    else:
        e_dof = (W - 0.5) - row.sum() - cx
        e_pin = (W - 0.5) - pin.sum() - cx
        result('depth_of_field_in_focus_unchanged', abs(e_dof) <= 1.0 / 16 and abs(e_pin) <= 1.0 / 16 and
               np.abs(row - pin).max() <= 1.0 / 16,
               'edge at %+.4f px (pinhole %+.4f px) from where it projects' % (e_dof, e_pin))
    zd = cv2.imread(out + '/dof/depth_000000.pfm', cv2.IMREAD_UNCHANGED)
    zp = cv2.imread(out + '/pin/depth_000000.pfm', cv2.IMREAD_UNCHANGED)
    result('depth_of_field_depth_pinhole_' + tag, np.array_equal(zd, zp), 'the depth differs from the pinhole\'s')

# ---- off when nothing asks for it: a shutter with nothing moving is a
# note and changes no byte of the image
camera(D + '/still.cam', 64, 48, 'shutter 0.5\nline_delay 0.01\n')
camera(D + '/plain.cam', 64, 48)
out = D + '/still'
p = run([BIN + '/glsplay', D + '/moving.glsb', '--camera', D + '/still.cam', '--camera', D + '/plain.cam', '-o', out,
         '--outputs', 'image'])
with open(out + '/still/image_000000.png', 'rb') as a, open(out + '/plain/image_000000.png', 'rb') as b:
    same = a.read() == b.read()
result('exposure_off_when_nothing_moves', same and p.stderr == 'glsplay: note: camera still: shutter and line_delay '
       'have no effect: nothing moves (no --trajectory, no --motion)\n', 'same bytes %s; stderr %r' % (same, p.stderr))

# ---- the exposure must lie within the rows: refused before anything is
# written, never extrapolated
p = run([BIN + '/glsplay', D + '/moving.glsb', '--camera', D + '/blur.cam', '--motion', 'mover=' + D + '/mover.txt',
         '--frame', '3', '-o', D + '/beyond'], want_rc=1)
want = ('glsplay: error: camera blur, frame 3: its exposure spans frames 2.75 to 3.25, beyond the rows of %s '
        '(frames 0 to 3); sub-frame poses are interpolated between rows, never extrapolated: render fewer --frames '
        'or extend the file\n' % (D + '/mover.txt'))
result('exposure_beyond_rows_refused', p.stderr == want and not os.path.exists(D + '/beyond/blur/image_000003.png'),
       repr(p.stderr))
# --resume: the frame record names the effects; a changed shutter is a
# frame to render again, the same one is complete
args = [BIN + '/glsplay', D + '/moving.glsb', '--camera', D + '/rec.cam', '--motion', 'mover=' + D + '/mover.txt',
        '--frame', '1', '--outputs', 'image', '-o', D + '/rec', '--resume']
camera(D + '/rec.cam', 32, 16, 'shutter 0.5\n')
run(args)
same = run(args).stderr
camera(D + '/rec.cam', 32, 16, 'shutter 0.25\n')
changed = run(args).stderr
with open(D + '/rec/rec/.frame_000001.done') as f:
    rec = f.read()
result('exposure_resume_record', 'glsplay: note: --resume: 1 of 1 frame complete' in same and
       'glsplay: note: --resume: 0 of 1 frame complete' in changed and
       '\neffects shutter 0.25 line_delay 0 aperture 0 focus 0 samples 16\n' in rec,
       'resume notes %r, %r; record %r' % (same, changed, rec[-80:]))

# more sub-frame renders than the exact accumulator holds: refused first
p = run([BIN + '/glsplay', D + '/moving.glsb', '--camera', D + '/blur.cam', '--motion', 'mover=' + D + '/mover.txt',
         '--frame', '1', '--aa', '4', '--filter', 'gauss', '-o', D + '/gauss'], want_rc=1)
want = ('glsplay: error: camera blur: exposure_samples 64 times the anti-aliasing\'s 400 samples exceed what the '
        'accumulator adds exactly (a Gaussian filter: at most 16 sub-frame renders); lower exposure_samples or --aa\n')
result('exposure_accumulator_range_refused', p.stderr == want and not os.path.exists(D + '/gauss/blur'),
       repr(p.stderr))
CHECKS.exit()
