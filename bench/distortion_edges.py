#!/usr/bin/python3
"""make bench-distortion, part 1: the edge accuracy the distorted image
keeps (spec/camera.md "The distorted image").  Run with /usr/bin/python3
(cv2, numpy):  distortion_edges.py BIN DIR

A white half-plane on black, fronto-parallel at Zc = 10, its edge a
straight line in the undistorted image plane at 0.5, 10, 30 and 45 degrees
from the vertical, through three points (left, centre, right of the image),
is rendered through a camera with strong barrel distortion (fx 500,
640x480, k1 -0.3 k2 0.08 p1 0.001 p2 -0.0015) and through the same camera
without distortion, with the same anti-aliasing.  The edge's exact image is
the distorted line (the forward model of spec/camera.md, in double).  Per
pixel row (the edges are within 45 degrees of the vertical), the sum of the
intensities of the 9 pixels around the edge minus the exact covered area
of those pixels is the edge's local displacement in pixels (contrast 1, as
bench/aa measures the pinhole, spec/antialiasing.md); the exact area is
(right end of the window) - (the edge's mean column over the row's band),
the mean taken over 400 points of the band on the curve.  RMS and max over
the rows of the three edges of one angle.
"""
import math
import subprocess
import sys
import numpy as np
import cv2

W, H, FX, CX, CY, Z = 640, 480, 500.0, 319.5, 239.5, 10.0
D = [-0.3, 0.08, 0.001, -0.0015]
ANGLES = (0.5, 10, 30, 45)
CENTRES = ((-0.6, 0.03), (0.02, -0.01), (0.55, 0.04))   # undistorted x, y the edge passes through
SETTINGS = (('--samples 1', 'no anti-aliasing'), ('--samples 64', 'lattice, 64 samples'),
            ('--samples 256', 'lattice, 256 samples'))


def distort(x, y, dist):
    if not dist:
        return FX * x + CX, FX * y + CY
    k1, k2, p1, p2 = D
    r2 = x * x + y * y
    R = 1 + k1 * r2 + k2 * r2 * r2
    xd = x * R + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
    yd = y * R + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
    return FX * xd + CX, FX * yd + CY


def scene(path, ang, c):
    """the half-plane right of the line through c in direction (sin, cos)"""
    t = math.radians(ang)
    d = np.array([math.sin(t), math.cos(t)])
    n = np.array([math.cos(t), -math.sin(t)])
    p0 = np.array(c)
    L = 4.0
    quad = [p0 - L * d, p0 + L * d, p0 + L * d + L * n, p0 - L * d + L * n]
    with open(path, 'w') as f:
        f.write('color(1, 1, 1);\npoly {')
        for q in quad:
            f.write(' vert(%r, %r, %r);' % (q[0] * Z, q[1] * Z, Z))
        f.write(' }\n')


def edge_rows(ang, c, dist):
    """per image row v: the edge's mean column over the row's band"""
    t = math.radians(ang)
    s = np.linspace(-3, 3, 600001)
    x, y = c[0] + s * math.sin(t), c[1] + s * math.cos(t)
    u, v = distort(x, y, dist)
    keep = (v > -2) & (v < H + 1)
    u, v = u[keep], v[keep]
    order = np.argsort(v)
    u, v = u[order], v[order]
    rows = {}
    for row in range(3, H - 3):
        band = row - 0.5 + (np.arange(400) + 0.5) / 400
        rows[row] = float(np.interp(band, v, u).mean())
    return rows


def measure(img, rows):
    e = []
    for row, ue in rows.items():
        a, b = int(math.floor(ue)) - 4, int(math.floor(ue)) + 4
        if a < 0 or b > W - 1:
            continue
        got = img[row, a:b + 1].sum() / 255.0
        exact = (b + 0.5) - ue
        e.append(got - exact)
    return np.array(e)


def write_cams(d):
    """the camera with the lens and without it: {True: path, False: path}"""
    cams = {}
    for dist in (False, True):
        name = 'lens' if dist else 'pinhole'
        with open('%s/%s.cam' % (d, name), 'w') as f:
            f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 1\nfar 100\n'
                    % (W, H, FX, FX, CX, CY))
            if dist:
                f.write('distortion %s\n' % ' '.join(repr(k) for k in D))
        cams[dist] = '%s/%s.cam' % (d, name)
    return cams


def edge_errors(bindir, d, cam, dist, ang, k, c, opts):
    """per-row displacements of edge k (through c at angle ang) rendered
    through cam with glsplay options opts"""
    sc = '%s/e%d_%d.scene' % (d, int(ang * 10), k)
    scene(sc, ang, c)
    subprocess.run([bindir + '/glsc', '-o', sc + '.glsb', sc], check=True, capture_output=True)
    subprocess.run([bindir + '/glsplay', sc + '.glsb', '--camera', cam, '--outputs', 'image', '-o', '%s/o%d' % (d, k)]
                   + opts, check=True, capture_output=True)
    img = cv2.imread('%s/o%d/%s/image_000000.png' % (d, k, 'lens' if dist else 'pinhole'),
                     cv2.IMREAD_GRAYSCALE).astype(np.float64)
    return measure(img, edge_rows(ang, c, dist))


def main():
    bindir, d = sys.argv[1], sys.argv[2]
    cams = write_cams(d)
    print('%-24s %6s  %-22s %-22s' % ('anti-aliasing', 'angle', 'pinhole RMS / max px', 'distorted RMS / max px'))
    for opt, what in SETTINGS:
        for ang in ANGLES:
            res = {}
            for dist in (False, True):
                errs = []
                for k, c in enumerate(CENTRES):
                    errs.append(edge_errors(bindir, d, cams[dist], dist, ang, k, c, opt.split()))
                e = np.concatenate(errs)
                res[dist] = (math.sqrt((e * e).mean()), np.abs(e).max(), len(e))
            print('%-24s %6g  %8.4f / %-11.4f %8.4f / %-11.4f (%d rows)' % (
                what, ang, res[False][0], res[False][1], res[True][0], res[True][1], res[True][2]))


if __name__ == '__main__':
    main()
