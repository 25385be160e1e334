#!/usr/bin/python3
"""Lens distortion (spec/camera.md "Lens distortion") against OpenCV (run
with /usr/bin/python3: cv2, numpy).  Prints "ok NAME" / "FAIL NAME: why".

  check_distortion.py model BIN DIR   glsplay's model (BIN/distort_project)
                                      against cv2.projectPoints and
                                      cv2.fisheye.projectPoints
"""
import math
import subprocess
import sys
import numpy as np
import cv2

OK = True


def result(name, ok, why=''):
    global OK
    OK &= bool(ok)
    print(('ok %s' % name) if ok else ('FAIL %s: %s' % (name, why)))


def fmt(v):
    return ' '.join(repr(float(x)) for x in np.ravel(v))


# The lenses: strong barrel with tangential terms (k1 = -0.3), the
# rational model, and a fisheye; each with a pose that is not the identity.
W, H = 640, 480
LENSES = {
    'brown': dict(key='distortion', D=[-0.3, 0.08, 0.0012, -0.0008, -0.01], fisheye=False),
    'rational': dict(key='distortion', D=[0.2, -0.05, 0.0005, 0.0007, 0.01, 0.3, -0.02, 0.004], fisheye=False),
    'fisheye': dict(key='fisheye', D=[0.05, -0.01, 0.002, -0.0004], fisheye=True),
}
FX, FY, CX, CY = 500.0, 495.0, 318.7, 241.2
RVEC = np.array([0.1, -0.2, 0.05])
TVEC = np.array([0.3, -0.1, 2.0])


def write_cam(path, lens, fx=FX, fy=FY, cx=CX, cy=CY, rvec=RVEC, tvec=TVEC, w=W, h=H):
    with open(path, 'w') as f:
        f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nrvec %s\nT %s\nnear 0.01\nfar 1000\n%s %s\n' % (
            w, h, fx, fy, cx, cy, fmt(rvec), fmt(tvec), lens['key'], fmt(lens['D'])))


def filter_lines(binary, cam, lines):
    p = subprocess.run([binary, cam], input=''.join(lines), capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit('FAIL distortion_setup: %s: %s' % (cam, p.stderr))
    return [l.split() for l in p.stdout.splitlines()]


def cv_project(lens, P, K=None, rvec=RVEC, tvec=TVEC):
    K = np.array([[FX, 0, CX], [0, FY, CY], [0, 0, 1.0]]) if K is None else K
    D = np.array(lens['D'], dtype=np.float64)
    P = np.asarray(P, dtype=np.float64).reshape(-1, 1, 3)
    if lens['fisheye']:
        uv, _ = cv2.fisheye.projectPoints(P, rvec.reshape(3, 1), tvec.reshape(3, 1), K, D)
    else:
        uv, _ = cv2.projectPoints(P, rvec, tvec, K, D)
    return uv.reshape(-1, 2)


def model(binary, d):
    R, _ = cv2.Rodrigues(RVEC)
    # pixels filling the image: a grid, the border and the outer corners
    us = np.concatenate([np.linspace(-0.5, W - 0.5, 33), [0, W - 1]])
    vs = np.concatenate([np.linspace(-0.5, H - 0.5, 25), [0, H - 1]])
    pix = np.array([(u, v) for u in us for v in vs])
    for name, lens in LENSES.items():
        cam = '%s/%s.cam' % (d, name)
        write_cam(cam, lens)
        # the inverse: each pixel's ray, reprojected by OpenCV, lands on it
        rays = filter_lines(binary, cam, ['p %r %r\n' % (u, v) for u, v in pix])
        its = np.array([int(r[2]) for r in rays])
        xy = np.array([[float(r[0]), float(r[1])] for r in rays])
        if (its < 0).any():
            result('distortion_inverse_%s' % name, False, '%d pixels without a ray' % (its < 0).sum())
            continue
        Pc = np.column_stack([xy, np.ones(len(xy))]) * np.linspace(0.5, 40, len(xy))[:, None]
        Pw = (R.T @ (Pc - TVEC).T).T
        back = cv_project(lens, Pw)
        err = np.abs(back - pix).max()
        result('distortion_inverse_%s' % name, err < 1e-6,
               'ray of a pixel reprojects %.3g px off (cv2), at %s' % (err, pix[np.abs(back - pix).max(1).argmax()]))
        # the forward model: world points whose projections fill the image
        # (the rays above, moved off the pixel a little so that they are not
        # the same numbers), against cv2 to 1e-6 px
        Pw2 = Pw + np.array([0.001, -0.002, 0.0015])
        got = filter_lines(binary, cam, ['w %r %r %r\n' % tuple(p) for p in Pw2])
        got = np.array([[float(a), float(b)] for a, b in got])
        want = cv_project(lens, Pw2)
        err = np.abs(got - want).max()
        inside = ((want[:, 0] >= -0.5) & (want[:, 0] <= W - 0.5) & (want[:, 1] >= -0.5) & (want[:, 1] <= H - 0.5))
        result('distortion_project_%s' % name, err < 1e-6 and inside.sum() > 0.9 * len(pix),
               'max |glsplay - cv2| = %.3g px over %d points (%d inside the image)' % (err, len(pix), inside.sum()))
        print('  %s: %d points, max |project - cv2| %.2g px, inverse max %.2g px, Newton iterations <= %d' % (
            name, len(pix), err, np.abs(back - pix).max(), its.max()))


def main():
    mode, binary, d = sys.argv[1], sys.argv[2], sys.argv[3]
    if mode == 'model':
        model(binary + '/distort_project', d)
    else:
        raise SystemExit('usage: check_distortion.py model BIN DIR')
    sys.exit(0 if OK else 1)


main()
