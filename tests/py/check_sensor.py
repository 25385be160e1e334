#!/usr/bin/python3
"""glsplay's sensor effects (spec/camera.md "Sensor effects") against the
model computed here: over a flat wall of known colour the noisy image's
sample mean and variance against mean = G v I and variance
G^2 v I / K + sigma^2 within confidence bounds computed here from the
model's own fourth moment; the photon counts against the Poisson
distribution (chi-square), the read noise against the normal; vignetting
per pixel against cos^4 of the ray angle from K (numpy) and against the
polynomial; the Bayer mosaic against the channels of the colour render;
the same seed, frame and camera give the same bytes, another seed, frame
or camera other noise; ground truth byte-identical with and without the
effects; keys at their neutral values change nothing.  Run with
/usr/bin/python3.  Prints "ok NAME" / "FAIL NAME: why".

  check_sensor.py BIN DIR
"""
import math
import os
import sys
import numpy as np
import cv2

from glstest import Checks

CHECKS = Checks('sensor_setup')
result = CHECKS.result
run = CHECKS.run


BIN, D = sys.argv[1], sys.argv[2]
W, H = 320, 240

# A wall filling the view at Zc = 10, one colour.  Colours are quantised
# to 8 bits per vertex (spec/camera.md), so the intensity is round(255 c) / 255.
COLOUR = (0.4, 0.6, 0.2)
I = np.array([round(255 * c) / 255 for c in COLOUR])
os.makedirs(D + '/src', exist_ok=True)
with open(D + '/src/Wall.scene', 'w') as f:
    f.write('color(%r, %r, %r);\n' % COLOUR)
    f.write('poly { vert(-100, -100, 10); vert(100, -100, 10); vert(100, 100, 10); vert(-100, 100, 10); }\n')
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/wall.glsb', 'Wall'])
BASE = ('width %d\nheight %d\nfx 300\nfy 280\nskew 5\ncx 150.3\ncy 118.7\n'
        'R 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n' % (W, H))
K = np.array([[300, 5, 150.3], [0, 280, 118.7], [0, 0, 1.0]])


def camera(path, extra):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(BASE + extra)
    return path


def render(bundle, cam, out, *opts):
    run([BIN + '/glsplay', bundle, '--camera', cam, '-o', out] + list(opts))
    name = os.path.basename(cam)[:-4]
    return out + '/' + name


def image(d, ext='png'):
    a = cv2.imread(d + '/image_000000.' + ext, cv2.IMREAD_UNCHANGED)
    if a is None:
        raise SystemExit('FAIL sensor_setup: cannot read %s/image_000000.%s' % (d, ext))
    if a.ndim == 3:
        a = a[:, :, ::-1]  # cv2 reads BGR
    return a.astype(np.float64)


def raw(path):
    with open(path, 'rb') as f:
        return f.read()


# ---- moments of the noise: PFM images, no quantisation ------------------
def moments(name, gain, k, sigma):
    extra = 'noise_seed 11\n'
    if gain != 1:
        extra += 'gain %r\n' % gain
    if k:
        extra += 'shot_noise %r\n' % k
    if sigma:
        extra += 'read_noise %r\n' % sigma
    d = render(D + '/wall.glsb', camera(D + '/cams/%s.cam' % name, extra), D + '/out_' + name, '--outputs', 'image',
               '--image-format', 'pfm')
    x = image(d, 'pfm')
    n = W * H
    why = []
    for c in range(3):
        v = x[:, :, c].ravel()
        mean = gain * I[c]
        # cumulants of G/K Poisson(K I) + N(0, sigma^2): k2 = G^2 I / K + sigma^2,
        # k4 = G^4 I / K^3; mu4 = k4 + 3 k2^2
        k2 = (gain * gain * I[c] / k if k else 0) + sigma * sigma
        k4 = gain ** 4 * I[c] / k ** 3 if k else 0
        mu4 = k4 + 3 * k2 * k2
        m, s2 = v.mean(), v.var(ddof=1)
        se_mean = math.sqrt(k2 / n)
        se_var = math.sqrt((mu4 - k2 * k2 * (n - 3) / (n - 1)) / n)
        # 5 standard errors: a failure by chance has probability ~6e-7
        if abs(m - mean) > 5 * se_mean:
            why.append('channel %d: mean %.6g, model %.6g +- %.2g' % (c, m, mean, 5 * se_mean))
        if abs(s2 - k2) > 5 * se_var:
            why.append('channel %d: variance %.6g, model %.6g +- %.2g' % (c, s2, k2, 5 * se_var))
        if v.min() <= 0 or v.max() >= 1:
            why.append('channel %d clipped: the case is badly chosen' % c)
    result('sensor_moments_' + name, not why, '; '.join(why))
    return x


moments('read', 1, 0, 0.03)
moments('shot', 1, 500, 0)
moments('gain_shot_read', 1.2, 1000, 0.01)
x = moments('gain_read', 1.4, 0, 0.02)

# neighbouring pixels and the channels of a pixel are uncorrelated
# (|r| within 5 / sqrt(n))
why = []
r0 = x - x.mean(axis=(0, 1))
for c in range(3):
    a = r0[:, :, c]
    for lbl, p, q in (('horizontal', a[:, 1:], a[:, :-1]), ('vertical', a[1:, :], a[:-1, :]),
                      ('next channel', a, r0[:, :, (c + 1) % 3])):
        r = np.corrcoef(p.ravel(), q.ravel())[0, 1]
        if abs(r) > 5 / math.sqrt(p.size):
            why.append('channel %d %s correlation %.4f' % (c, lbl, r))
result('sensor_noise_uncorrelated', not why, '; '.join(why))

# the read noise is normal: fractions within 1, 2 and 3 sigma (binomial bounds)
v = (x[:, :, 1].ravel() - 1.4 * I[1]) / 0.02
why = []
for z in (0.5, 1, 2, 3):
    p = math.erf(z / math.sqrt(2))
    got = np.mean(np.abs(v) < z)
    if abs(got - p) > 5 * math.sqrt(p * (1 - p) / v.size):
        why.append('within %g sigma: %.5f, normal %.5f' % (z, got, p))
result('sensor_read_noise_normal', not why, '; '.join(why))


# ---- the photon counts are Poisson: chi-square against the pmf ---------
def chi2_limit(df, z=4.75):
    # Wilson-Hilferty: the chi-square quantile at the normal's z (p ~ 1e-6)
    return df * (1 - 2 / (9 * df) + z * math.sqrt(2 / (9 * df))) ** 3


def poisson_check(name, k):
    d = render(D + '/wall.glsb', camera(D + '/cams/%s.cam' % name, 'shot_noise %r\nnoise_seed 3\n' % k),
               D + '/out_' + name, '--outputs', 'image', '--image-format', 'pfm')
    x = image(d, 'pfm')
    why = []
    for c in range(3):
        lam = k * I[c]
        counts = x[:, :, c].ravel() * k
        nint = np.round(counts)
        if np.abs(counts - nint).max() > 1e-5 * max(1, nint.max()):
            why.append('channel %d: value * K is not a whole number of photons' % c)
            continue
        nint = nint.astype(np.int64)
        # the image clips at 1, that is at K photons: counts of K and more
        # read as K, the model's tail P(N >= K) in one bin
        top = int(k)
        obs = np.bincount(nint, minlength=top + 1).astype(np.float64)
        if obs.size > top + 1:
            why.append('channel %d: more than K photons' % c)
            continue
        ks = np.arange(top + 1)
        logp = -lam + ks * math.log(lam) - np.array([math.lgamma(j + 1) for j in ks])
        pmf = np.exp(logp)
        pmf[-1] = max(0.0, 1 - pmf[:-1].sum())
        exp = pmf * nint.size
        # merge bins from both ends until each expects >= 5
        bins_o, bins_e, acc_o, acc_e = [], [], 0.0, 0.0
        for o, e in zip(obs, exp):
            acc_o += o
            acc_e += e
            if acc_e >= 5:
                bins_o.append(acc_o)
                bins_e.append(acc_e)
                acc_o = acc_e = 0.0
        bins_o[-1] += acc_o
        bins_e[-1] += acc_e
        bo, be = np.array(bins_o), np.array(bins_e)
        chi2 = float(((bo - be) ** 2 / be).sum())
        df = len(bo) - 1
        if chi2 > chi2_limit(df):
            why.append('channel %d (mean %.4g): chi-square %.1f over %d bins, limit %.1f' % (c, lam, chi2, df + 1,
                                                                                          chi2_limit(df)))
    result('sensor_poisson_' + name, not why, '; '.join(why))


poisson_check('small_means', 20)   # means 8, 12, 4: the multiplication method and PTRS; 2% clip at 1
poisson_check('large_means', 1000)  # means 400, 600, 200: PTRS

# ---- determinism: seed, frame, camera -----------------------------------
noisy = 'gain 1.3\nshot_noise 300\nread_noise 0.01\nnoise_seed 5\n'
a = render(D + '/wall.glsb', camera(D + '/det/a/cam.cam', noisy), D + '/det_a')
b = render(D + '/wall.glsb', camera(D + '/det/b/cam.cam', noisy), D + '/det_b', '--writer-threads', '0')
s = render(D + '/wall.glsb', camera(D + '/det/s/cam.cam', noisy.replace('seed 5', 'seed 6')), D + '/det_s')
o = render(D + '/wall.glsb', camera(D + '/det/o/other.cam', noisy), D + '/det_o')
f1 = render(D + '/wall.glsb', camera(D + '/det/a/cam.cam', noisy), D + '/det_f1', '--frame', '1')
same = raw(a + '/image_000000.png') == raw(b + '/image_000000.png')
result('sensor_same_seed_same_bytes', same, 'two runs with noise_seed 5 differ')
ia = image(a)
for nm, d, fn in (('seed', s, 'image_000000.png'), ('camera', o, 'image_000000.png'),
                  ('frame', f1, 'image_000001.png')):
    ib = cv2.imread(d + '/' + fn, cv2.IMREAD_UNCHANGED)[:, :, ::-1].astype(np.float64)
    # other noise: the images differ, and their differences are as wide as
    # two independent draws' (variance 2 k2 of the channel)
    frac = np.mean(ia != ib)
    result('sensor_other_%s_other_noise' % nm, frac > 0.9, 'only %.3f of the samples differ' % frac)

# the bands of rows the noise is drawn in, on threads, change nothing:
# tests/unit/test_sensor.c (test_sensor_threads_same_image) passes their
# number to gls_sensor_apply, which no variable of the environment sets

# ---- vignetting against cos^4 of the ray angle (K in numpy) -------------
u, v = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))
rays = np.linalg.solve(K, np.stack([u.ravel(), v.ravel(), np.ones(u.size)]))
cos = rays[2] / np.linalg.norm(rays, axis=0)
cos4 = (cos ** 4).reshape(H, W)
d = render(D + '/wall.glsb', camera(D + '/vig/cos4.cam', 'vignetting cos4\n'), D + '/vig_pfm', '--outputs', 'image',
           '--image-format', 'pfm')
x = image(d, 'pfm')
err = max(np.abs(x[:, :, c] - I[c] * cos4).max() for c in range(3))
result('sensor_vignetting_cos4', err < 1e-6, 'max error %.3g against I cos^4 (float: 1e-6)' % err)
d8 = render(D + '/wall.glsb', D + '/vig/cos4.cam', D + '/vig_png')
x8 = image(d8)
err = max(np.abs(x8[:, :, c] - 255 * I[c] * cos4).max() for c in range(3))
result('sensor_vignetting_cos4_8bit', err <= 0.5 + 1e-4, 'max |pixel - 255 I cos^4| %.4f, over half a level' % err)
da = render(D + '/wall.glsb', D + '/vig/cos4.cam', D + '/vig_aa', '--outputs', 'image', '--image-format', 'pfm',
            '--aa', '4')
result('sensor_vignetting_cos4_aa', np.array_equal(image(da, 'pfm'), x),
       'the anti-aliased flat wall differs from the single pass')
A = (-0.3, 0.05, -0.002)
d = render(D + '/wall.glsb', camera(D + '/vig/poly.cam', 'vignetting poly %r %r %r\n' % A), D + '/vig_poly',
           '--outputs', 'image', '--image-format', 'pfm')
x = image(d, 'pfm')
r2 = ((u - 150.3) ** 2 + (v - 118.7) ** 2) / 300.0 ** 2
fac = np.maximum(0, 1 + A[0] * r2 + A[1] * r2 ** 2 + A[2] * r2 ** 3)
err = max(np.abs(x[:, :, c] - I[c] * fac).max() for c in range(3))
result('sensor_vignetting_poly', err < 1e-6, 'max error %.3g against I (1 + a1 r^2 + a2 r^4 + a3 r^6)' % err)

# ---- Bayer: each sample is its channel of the colour render -------------
run([BIN + '/glsc', '-I', 'examples/demo', '-I', BIN + '/textures', '-o', D + '/demo.glsb',
     'examples/demo/Demo.scene'])
DEMO = open('examples/demo/left.cam').read()


def demo_cam(path, extra):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(DEMO + '\n' + extra)
    return path


CH = {'R': 0, 'G': 1, 'B': 2}
for fmt, ext in (('png8', 'png'), ('png16', 'png'), ('pfm', 'pfm')):
    for noise in ('', 'read_noise 0.02\nshot_noise 2000\nnoise_seed 9\n'):
        tag = fmt + ('_noisy' if noise else '')
        rgb = image(render(D + '/demo.glsb', demo_cam(D + '/bay/rgb_%s/left.cam' % tag, noise), D + '/bay_rgb_' + tag,
                           '--outputs', 'image', '--image-format', fmt, '--aa', '2'), ext)
        why = []
        for pat in (('RGGB', 'BGGR', 'GRBG', 'GBRG') if fmt == 'png8' else ('RGGB',)):
            dd = render(D + '/demo.glsb', demo_cam(D + '/bay/%s_%s/left.cam' % (pat, tag), noise + 'bayer ' + pat + '\n'),
                        D + '/bay_%s_%s' % (pat, tag), '--outputs', 'image', '--image-format', fmt, '--aa', '2')
            m = image(dd, ext)
            want = np.empty(m.shape)
            for yy in range(2):
                for xx in range(2):
                    want[yy::2, xx::2] = rgb[yy::2, xx::2, CH[pat[2 * yy + xx]]]
            if m.ndim != 2 or not np.array_equal(m, want):
                why.append('%s: %s' % (pat, 'not one channel' if m.ndim != 2 else
                                       '%d samples differ' % np.count_nonzero(m != want)))
        result('sensor_bayer_' + tag, not why, '; '.join(why))
dd = D + '/bay_RGGB_png16/left'
m = cv2.imread(dd + '/image_000000.png', cv2.IMREAD_UNCHANGED)
result('sensor_bayer_png16_is_16bit', m is not None and m.dtype == np.uint16 and m.ndim == 2,
       'not a one-channel 16-bit PNG')

# OpenCV demosaics the mosaics by its own names for them (it names a
# pattern by the second row's second and third pixels): over the flat wall
# every demosaiced pixel away from the border is the wall's colour
CV = {'RGGB': cv2.COLOR_BayerBG2BGR, 'BGGR': cv2.COLOR_BayerRG2BGR, 'GRBG': cv2.COLOR_BayerGB2BGR,
      'GBRG': cv2.COLOR_BayerGR2BGR}
why = []
for pat, code in CV.items():
    dd = render(D + '/wall.glsb', camera(D + '/cv/%s/cam.cam' % pat, 'bayer %s\n' % pat), D + '/cv_' + pat,
                '--outputs', 'image')
    m = cv2.imread(dd + '/image_000000.png', cv2.IMREAD_UNCHANGED)
    bgr = cv2.cvtColor(m, code)[2:-2, 2:-2].reshape(-1, 3)
    want = np.round(255 * I[::-1])
    if not (bgr == want).all():
        why.append('%s: demosaiced %s, the wall is %s' % (pat, bgr[0], want))
result('sensor_bayer_opencv_demosaic', not why, '; '.join(why))

# ---- ground truth is untouched ------------------------------------------
GT = 'depth,points,edges,normals,instance,class,depth16'
allfx = 'vignetting cos4\ngain 1.7\nshot_noise 50\nread_noise 0.05\nnoise_seed 1\nbayer GRBG\n'
p = render(D + '/demo.glsb', demo_cam(D + '/gt/plain/left.cam', ''), D + '/gt_plain', '--outputs', 'image,' + GT,
           '--aa', '2')
q = render(D + '/demo.glsb', demo_cam(D + '/gt/fx/left.cam', allfx), D + '/gt_fx', '--outputs', 'image,' + GT, '--aa',
           '2')
why = [n for n in sorted(os.listdir(p)) if not n.startswith('.') and not n.startswith('image_') and
       raw(p + '/' + n) != raw(q + '/' + n)]
files = [n for n in os.listdir(p) if not n.startswith('.') and not n.startswith('image_')]
result('sensor_ground_truth_unchanged', not why and len(files) >= 7, 'differ: %s (of %s)' % (why, files))
result('sensor_image_changed', raw(p + '/image_000000.png') != raw(q + '/image_000000.png'),
       'the image with every effect is the plain one')

# ---- neutral values switch nothing on -----------------------------------
n = render(D + '/demo.glsb', demo_cam(D + '/gt/neutral/left.cam', 'gain 1\nread_noise 0\nvignetting poly 0 0 0\n'
                                       'noise_seed 4\n'), D + '/gt_neutral', '--outputs', 'image,' + GT, '--aa', '2')
# every file the same; the frame records too, but for their last line, the
# digest of the inputs (the camera files differ: spec/road.md)


def sans_inputs(b):
    return b.rsplit(b'\ninputs ', 1)[0] if b.startswith(b'glsplay frame record') else b


why = [nm for nm in sorted(os.listdir(p)) if sans_inputs(raw(p + '/' + nm)) != sans_inputs(raw(n + '/' + nm))]
result('sensor_neutral_keys_change_nothing', not why, 'differ: %s' % why)

CHECKS.exit()
