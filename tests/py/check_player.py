#!/usr/bin/python3
"""OpenCV/numpy checks of glsplay outputs (run with /usr/bin/python3, which
has cv2 and numpy).  Prints "ok NAME" / "FAIL NAME: why" lines.

  check_player.py proj   DIR OUT   projection vs a numpy K [R|t] with skew
  check_player.py orient DIR OUT   PNG/PFM orientation and channels, PLY plane
  check_player.py stereo DIR OUT   the same 3D point in both stereo images
"""
import sys
import numpy as np
import cv2

from glstest import Checks, read_cam

result = Checks('player_setup').result


def project(K, R, T, P):
    """The pinhole model as a plain matrix product: x = K [R|t] P with
    K = [[fx, skew, cx], [0, fy, cy], [0, 0, 1]], then u = x0/x2, v = x1/x2.
    Independent of the player, and of OpenCV: cv2.projectPoints has no skew
    term (it reads fx, fy, cx, cy and ignores K[0, 1])."""
    P = np.asarray(P, dtype=np.float64).reshape(-1, 3)
    x = (K @ np.c_[R, T]) @ np.c_[P, np.ones(len(P))].T
    return (x[:2] / x[2]).T


def check_model_vs_opencv(K, R, T, P):
    """project() with the skew set to 0 against cv2.projectPoints, which
    then computes the same model: they must agree to rounding."""
    K0 = K.copy()
    K0[0, 1] = 0
    rvec, _ = cv2.Rodrigues(R)
    uv, _ = cv2.projectPoints(np.asarray(P, dtype=np.float64).reshape(-1, 1, 3), rvec, T, K0, np.zeros(5))
    err = np.abs(uv.reshape(-1, 2) - project(K0, R, T, P)).max()
    return result('py_proj_model_matches_opencv', err < 1e-9, 'differs from cv2.projectPoints by %g px' % err)


def coverage(q, W, H):
    """Pixels whose centre is strictly inside the convex polygon q."""
    u, v = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))
    pos = np.ones((H, W), bool)
    neg = np.ones((H, W), bool)
    for i in range(len(q)):
        a, b = q[i], q[(i + 1) % len(q)]
        cr = (b[0] - a[0]) * (v - a[1]) - (b[1] - a[1]) * (u - a[0])
        pos &= cr > 0
        neg &= cr < 0
    return pos | neg


def check_proj(d, out):
    K, R, T, W, H = read_cam(d + '/proj.cam')
    # the claim is "including skew": the camera must have some
    ok = result('py_proj_camera_has_skew', abs(K[0, 1]) > 1, 'skew %g' % K[0, 1])
    img = cv2.imread(out + '/proj/image_000000.png', cv2.IMREAD_COLOR)
    if img is None or img.shape != (H, W, 3):
        return result('py_proj_skew_model', False, 'cannot read the PNG or wrong size')
    rgb = img[:, :, ::-1]
    worst_c = worst_m = 0.0
    corners = []
    for line in open(d + '/proj_corners.txt'):
        f = [float(x) for x in line.split()]
        col = np.array(f[:3], np.uint8)
        P = np.array(f[3:]).reshape(4, 3)
        corners.append(P)
        q = project(K, R, T, P)
        ref = coverage(q, W, H)
        lit = np.all(rgb == col, axis=2)
        per = sum(np.hypot(*(q[(i + 1) % 4] - q[i])) for i in range(4))
        worst_m = max(worst_m, np.count_nonzero(lit != ref) / per)
        vv, uu = np.nonzero(lit)
        rv, ru = np.nonzero(ref)
        worst_c = max(worst_c, np.hypot(uu.mean() - ru.mean(), vv.mean() - rv.mean()))
    print('  vs numpy K [R|t] with skew: worst centroid error %.4f px, mismatched pixels per edge pixel %.4f'
          % (worst_c, worst_m))
    ok &= check_model_vs_opencv(K, R, T, np.concatenate(corners))
    return result('py_proj_skew_model', worst_c < 0.05 and worst_m < 0.02,
                  'centroid %.4f px, mismatch %.4f' % (worst_c, worst_m)) and ok


def check_orient(d, out):
    ok = True
    img = cv2.imread(out + '/orient/image_000000.png', cv2.IMREAD_COLOR)  # BGR
    H, W = img.shape[:2]
    # red square at X in [-1.9,-0.6], Y in [-1.4,-0.4], Z=4: u 32..64, v 24..49
    ok &= result('py_png_red_top_left', tuple(img[35, 45]) == (0, 0, 255), 'pixel (45,35) is %s' % (img[35, 45],))
    # green at X [0.9,1.8] Y [0.5,1.3]: u 102..124, v 72..92
    ok &= result('py_png_green_bottom_right', tuple(img[80, 110]) == (0, 255, 0), 'pixel (110,80) is %s' % (img[80, 110],))
    z = cv2.imread(out + '/orient/depth_000000.pfm', cv2.IMREAD_UNCHANGED)
    good = z is not None and z.shape == (H, W) and abs(z[35, 45] - 4) < 4e-5 and abs(z[80, 110] - 4) < 4e-5 \
        and np.isinf(z[2, 2])
    ok &= result('py_pfm_opencv_orientation', good,
                 'depth at red/green/corner: %s' % (str((z[35, 45], z[80, 110], z[2, 2])) if z is not None else 'unreadable'))
    # PLY: header, then double xyz + uchar rgb
    raw = open(out + '/orient/points_000000.ply', 'rb').read()
    hdr, body = raw.split(b'end_header\n', 1)
    n = int([l for l in hdr.split(b'\n') if l.startswith(b'element vertex')][0].split()[2])
    pts = np.frombuffer(body, dtype=np.dtype([('x', '<f8'), ('y', '<f8'), ('z', '<f8'),
                                              ('r', 'u1'), ('g', 'u1'), ('b', 'u1')]), count=n)
    ok &= result('py_ply_count', n == np.count_nonzero(np.isfinite(z)) and len(body) == 27 * n)
    blue = pts[(pts['b'] == 255) & (pts['r'] == 0)]
    # the blue plane through (-3,1.35,2) (3,1.35,2) (3,1.6,12): y = 1.35 + 0.025 (z - 2)
    resid = np.abs(blue['y'] - (1.35 + 0.025 * (blue['z'] - 2)))
    rng = np.sqrt(blue['x'] ** 2 + blue['y'] ** 2 + blue['z'] ** 2)
    ok &= result('py_ply_plane', len(blue) > 500 and np.max(resid / rng) < 1e-5,
                 '%d blue points, worst %.3g' % (len(blue), np.max(resid / rng) if len(blue) else -1))
    red = pts[(pts['r'] == 255) & (pts['g'] == 0)]
    ok &= result('py_ply_red_square', len(red) > 100 and np.all(np.abs(red['z'] - 4) < 1e-4)
                 and np.all(red['x'] < -0.5) and np.all(red['y'] < -0.3))
    return ok


def check_stereo(d, out):
    ok = True
    for name in ('left', 'right'):
        K, R, T, W, H = read_cam(d + '/%s.cam' % name)
        img = cv2.imread(out + '/%s/image_000000.png' % name, cv2.IMREAD_COLOR)[:, :, ::-1]
        z = cv2.imread(out + '/%s/depth_000000.pfm' % name, cv2.IMREAD_UNCHANGED)
        # the centre of the red square, (-1.25, -0.9, 4): where each model
        # puts it, the image must show red at depth ~4
        P = np.array([[-1.25, -0.9, 4.0]])
        u, v = project(K, R, T, P)[0]
        iu, iv = int(round(u)), int(round(v))
        Zc = (R @ P[0] + T)[2]
        ok &= result('py_stereo_%s' % name, tuple(img[iv, iu]) == (255, 0, 0) and abs(z[iv, iu] - Zc) < 1e-4 * Zc,
                     'at (%d,%d): %s depth %s vs %s' % (iu, iv, img[iv, iu], z[iv, iu], Zc))
    return ok


if __name__ == '__main__':
    mode, d, out = sys.argv[1:4]
    fn = {'proj': check_proj, 'orient': check_orient, 'stereo': check_stereo}[mode]
    sys.exit(0 if fn(d, out) else 1)
