#!/usr/bin/python3
"""Checks of glsplay's disparity, disparity16, depth16 and .npy outputs
(spec/outputs.md "Disparity and 16-bit depth", "Float outputs"), with the
readers people use (cv2.imread IMREAD_UNCHANGED, numpy.load) and geometry
computed here in numpy.  Run with /usr/bin/python3.  Prints "ok NAME" /
"FAIL NAME: why" lines.

  check_disparity.py closed OUT LEFT.cam RIGHT.cam
      the scene of outputs_disparity.sh (a wall x in [-3, 3], y in [-4, 1]
      at z = 10 and a ground y = 1 for z in [2, 10], x in [-3, 3]; world =
      camera axes): each camera's disparity against fx B / Zc of the
      surface its pixel ray meets, computed here (not from the player's
      depth); +inf and 0 where the ray meets nothing
  check_disparity.py reproject OUT LEFT.cam RIGHT.cam TAG
      every valid pixel of each camera (OUT/NAME/, NAME the camera file's
      name), unprojected with its depth and projected into the other
      camera: u_other = u -+ d, v_other = v
  check_disparity.py kitti OUT NAME...     disparity16 = floor(256 d + 0.5), 0 where d = +inf
  check_disparity.py depth16 OUT SCALE NAME...   depth16 = floor(Zc S + 0.5), 0 where no surface
  check_disparity.py npy PFMDIR NPYDIR NAME KIND CH   KIND_000000.npy == KIND_000000.pfm bit for bit
"""
import sys
import numpy as np
import cv2

from glstest import Checks, read_cam

result = Checks('disparity_setup').result


def read_pfm(path):
    """cv2.imread reads PFM top row first (it flips Middlebury's
    bottom-to-top rows)."""
    return cv2.imread(path, cv2.IMREAD_UNCHANGED)


def centre(R, T):
    return -R.T @ T


def baseline(left, right):
    """B: the right camera's centre in the left camera's frame, x."""
    _, Rl, Tl, _, _ = left
    _, Rr, Tr, _, _ = right
    return (Rl @ centre(Rr, Tr) + Tl)[0]


def closed_form_z(cam, u, v):
    """Zc of the scene's surface along the ray of pixel (u, v) of a camera
    with R = I (world axes): the wall z = 10, x in [-3, 3], y in [-4, 1],
    and the ground y = 1, z in [2, 10], x in [-3, 3]; inf: nothing."""
    K, R, T, _, _ = cam
    C = centre(R, T)
    dx = (u - K[0, 2] - K[0, 1] * (v - K[1, 2]) / K[1, 1]) / K[0, 0]
    dy = (v - K[1, 2]) / K[1, 1]
    z = np.full(u.shape, np.inf)
    with np.errstate(divide='ignore', invalid='ignore'):
        zg = (1 - C[1]) / dy  # the ground: C_y + dy z = 1
        xg = C[0] + dx * zg
        ground = (dy > 0) & (zg >= 2) & (zg <= 10) & (np.abs(xg) <= 3)
    xw, yw = C[0] + dx * 10, C[1] + dy * 10
    wall = (np.abs(xw) <= 3) & (yw >= -4) & (yw <= 1)
    z[wall] = 10
    z[ground] = np.minimum(z[ground], zg[ground])
    return z


def closed(out, lpath, rpath):
    cams = {'left': read_cam(lpath), 'right': read_cam(rpath)}
    B = baseline(cams['left'], cams['right'])
    for name, cam in cams.items():
        K, R, T, W, H = cam
        d = read_pfm('%s/%s/disparity_000000.pfm' % (out, name))
        if not result('disparity_pfm_read_%s' % name, d is not None and d.shape == (H, W) and d.dtype == np.float32,
                      'cv2.imread gives %r' % ((None if d is None else (d.shape, d.dtype)),)):
            continue
        u, v = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))
        z = closed_form_z(cam, u, v)
        # pixels whose ray meets the same surface (or none) at the corners
        # of a 1.5 px square around the centre: no edge near the centre
        same = np.ones((H, W), bool)
        for a, b in ((-0.75, -0.75), (0.75, -0.75), (-0.75, 0.75), (0.75, 0.75)):
            zn = closed_form_z(cam, u + a, v + b)
            same &= (np.isinf(zn) == np.isinf(z)) & ((zn == 10) == (z == 10))
        want = K[0, 0] * B / z
        surf = same & np.isfinite(z)
        none = same & np.isinf(z)
        rel = np.abs(d[surf] - want[surf]) / want[surf]
        result('disparity_closed_form_%s' % name, surf.sum() > W * H // 4 and rel.max() < 1e-5,
               '%d pixels, largest relative error %g' % (surf.sum(), rel.max() if rel.size else -1))
        result('disparity_positive_%s' % name, (d[np.isfinite(d)] > 0).all(), 'a disparity <= 0')
        result('disparity_invalid_inf_%s' % name, none.sum() > 0 and np.isposinf(d[none]).all(),
               '%d background pixels, not all +inf' % none.sum())
        print('# %s: %d surface pixels, disparity within %.2g relative of fx B / Zc (B = %g)'
              % (name, surf.sum(), rel.max(), B))


def pixels_into(src, dst, z):
    """Each pixel (u, v) of camera src at depth z (finite), unprojected and
    projected into camera dst: (u, v, u_dst, v_dst)."""
    K, R, T, W, H = src
    Kd, Rd, Td, _, _ = dst
    v, u = np.nonzero(np.isfinite(z))
    Z = z[v, u].astype(np.float64)
    Pc = np.linalg.solve(K, np.vstack([u * Z, v * Z, Z]))  # K^-1 (u Z, v Z, Z)
    P = R.T @ (Pc - T[:, None])                           # world
    x = Kd @ (Rd @ P + Td[:, None])
    return u, v, x[0] / x[2], x[1] / x[2]


def cam_name(path):
    return path.rsplit('/', 1)[-1].rsplit('.', 1)[0]


def reproject(out, lpath, rpath, tag):
    left, right = read_cam(lpath), read_cam(rpath)
    for name, src, dst, sign in ((cam_name(lpath), left, right, -1), (cam_name(rpath), right, left, 1)):
        z = read_pfm('%s/%s/depth_000000.pfm' % (out, name))
        d = read_pfm('%s/%s/disparity_000000.pfm' % (out, name))
        if not result('reproject_read_%s_%s' % (tag, name), z is not None and d is not None, 'cannot read'):
            continue
        u, v, ud, vd = pixels_into(src, dst, z)
        du = np.abs(ud - (u + sign * d[v, u]))
        dv = np.abs(vd - v)
        result('reproject_%s_%s_u' % (tag, name), len(u) > 100 and du.max() < 1e-3,
               '%d pixels, |u_other - (u %s d)| up to %g px' % (len(u), '-' if sign < 0 else '+', du.max() if len(u) else -1))
        result('reproject_%s_%s_v' % (tag, name), len(u) > 100 and dv.max() < 1e-3,
               '|v_other - v| up to %g px' % (dv.max() if len(u) else -1))
        result('reproject_%s_%s_invalid' % (tag, name), np.array_equal(np.isposinf(d), ~np.isfinite(z)),
               'disparity +inf not exactly where the depth has no surface')
        print('# %s %s: %d pixels, u within %.2g px, v within %.2g px' % (tag, name, len(u), du.max(), dv.max()))


def kitti(out, names):
    for name in names:
        d = read_pfm('%s/%s/disparity_000000.pfm' % (out, name))
        k = cv2.imread('%s/%s/disparity16_000000.png' % (out, name), cv2.IMREAD_UNCHANGED)
        if not result('kitti_read_%s' % name, k is not None and k.dtype == np.uint16 and k.ndim == 2,
                      'cv2.imread gives %r' % ((None if k is None else (k.shape, k.dtype)),)):
            continue
        want = np.where(np.isfinite(d), np.floor(d.astype(np.float64) * 256 + 0.5), 0)
        result('kitti_equals_round_256d_%s' % name, np.array_equal(k.astype(np.float64), want) and (k == 0).any()
               and (k > 0).any(), '%d pixels differ' % (k != want).sum())


def depth16(out, scale, names):
    S = float(scale)
    for name in names:
        z = read_pfm('%s/%s/depth_000000.pfm' % (out, name))
        k = cv2.imread('%s/%s/depth16_000000.png' % (out, name), cv2.IMREAD_UNCHANGED)
        if not result('depth16_read_%s_%s' % (scale, name), k is not None and k.dtype == np.uint16 and k.ndim == 2,
                      'cv2.imread gives %r' % ((None if k is None else (k.shape, k.dtype)),)):
            continue
        want = np.where(np.isfinite(z), np.floor(z.astype(np.float64) * S + 0.5), 0)
        result('depth16_equals_round_zs_%s_%s' % (scale, name), np.array_equal(k.astype(np.float64), want)
               and (k == 0).any() and (k > 0).any(), '%d pixels differ' % (k != want).sum())


def npy(pfmdir, npydir, name, kind, ch):
    import io
    ch = int(ch)
    f = '%s/%s/%s_000000' % ('%s', name, kind)
    p = cv2.imread(f % pfmdir + '.pfm', cv2.IMREAD_UNCHANGED)
    try:
        a = np.load(f % npydir + '.npy', allow_pickle=False)
    except Exception as e:
        result('npy_load_%s' % kind, False, 'numpy.load(allow_pickle=False): %s' % e)
        return
    shape = p.shape[:2] + ((ch,) if ch > 1 else ())
    result('npy_load_%s' % kind, a.dtype == np.dtype('<f4') and a.shape == shape,
           'dtype %s shape %s, want <f4 %s' % (a.dtype, a.shape, shape))
    if ch == 3:
        p = p[:, :, ::-1]  # cv2 gives BGR; the .npy holds R, G, B
    same = a.shape == p.shape and np.array_equal(a.view(np.uint32), np.ascontiguousarray(p).view(np.uint32))
    result('npy_equals_pfm_bits_%s' % kind, same, 'the .npy and the PFM hold different floats')
    # the bytes numpy.save writes for the same array: header and data
    b = io.BytesIO()
    np.save(b, a)
    raw = open(f % npydir + '.npy', 'rb').read()
    result('npy_bytes_as_numpy_saves_%s' % kind, raw == b.getvalue(),
           'header %r, numpy writes %r' % (raw[:80], b.getvalue()[:80]))
    if kind != 'image':
        result('npy_inf_invalid_%s' % kind, np.isposinf(a).any() and np.array_equal(np.isposinf(a), np.isposinf(p)),
               '+inf not where the PFM has it')


def main():
    m = sys.argv[1]
    if m == 'closed':
        closed(*sys.argv[2:5])
    elif m == 'reproject':
        reproject(*sys.argv[2:6])
    elif m == 'kitti':
        kitti(sys.argv[2], sys.argv[3:])
    elif m == 'depth16':
        depth16(sys.argv[2], sys.argv[3], sys.argv[4:])
    elif m == 'npy':
        npy(*sys.argv[2:7])
    else:
        sys.exit('unknown mode ' + m)


if __name__ == '__main__':
    try:
        main()
    except Exception as e:  # a crash is a failure the count sees
        result('check_disparity_' + sys.argv[1], False, '%s: %s' % (type(e).__name__, e))
