#!/usr/bin/python3
"""Effect keys in OpenCV YAML cameras (spec/camera.md "OpenCV camera
files"): a .cam file with every sensor and exposure effect and its YAML
twin written by cv2.FileStorage render byte-identical images; glsplay
--write-calib writes the effects into calib_F.yml, cv2.FileStorage reads
them back with the .cam file's values, and the file given back to glsplay
renders the same bytes again.

The scene is tests/py/flow_scene.py's (a box moved by --motion, the rig
moving along a trajectory), so that shutter and line_delay have something
to blur.  usage: check_camera_yaml_effects.py BINDIR SCENELIB TMPDIR.
Prints ok NAME / FAIL NAME: why."""
import filecmp
import os
import subprocess
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flow_scene as S  # noqa: E402
import gt_checks  # noqa: E402

BIN, LIB, D = sys.argv[1], sys.argv[2], sys.argv[3]
result = gt_checks.result
W, H = 96, 72
K = np.array([[90.0, 0, 47.5], [0, 90.0, 35.5], [0, 0, 1]])
SEED = 18446744073709551615  # above 2^31: a string in cv2's files
# two cameras between them giving every effect key; values as the .cam
# file writes them (words, numbers)
CAMS = {
    'sens': [('vignetting', 'poly 0.1 -0.05 0.02'), ('gain', 1.3), ('shot_noise', 2000.0), ('read_noise', 0.01),
             ('noise_seed', SEED), ('bayer', 'GRBG'), ('shutter', 0.5), ('exposure_samples', 3)],
    'expo': [('vignetting', 'cos4'), ('read_noise', 0.02), ('noise_seed', 7), ('line_delay', 0.002),
             ('aperture', 0.05), ('focus', 8.0), ('exposure_samples', 2)],
}


def cam_text(pose, effects):
    t = 'pose %s\nwidth %d\nheight %d\nK %s\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n' % (
        pose, W, H, ' '.join(repr(float(x)) for x in K.ravel()))
    return t + ''.join('%s %s\n' % (k, v) for k, v in effects)


def yaml_twin(path, pose, effects):
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_WRITE)
    fs.write('image_width', W)
    fs.write('image_height', H)
    fs.write('camera_matrix', K)
    fs.write('R', np.eye(3))
    fs.write('T', np.zeros((3, 1)))
    fs.write('near', 0.1)
    fs.write('far', 100.0)
    fs.write('pose', pose)
    for k, v in effects:
        # a seed above 2^31 - 1 goes as a string: cv2 keeps ints in 32 bits
        fs.write(k, str(v) if k == 'noise_seed' and v > 2 ** 31 - 1 else v)
    fs.release()


def play(cams, extra, out):
    args = [BIN + '/glsplay', D + '/f.glsb']
    for c in cams:
        args += ['--camera', c]
    p = subprocess.run(args + extra + ['--outputs', 'image', '-o', out], capture_output=True, text=True)
    return p.returncode, p.stderr.strip()


S.write(D)
subprocess.run([BIN + '/glsc', '-I', LIB, '-o', D + '/f.glsb', D + '/Flow.scene'], check=True)
MOVE = ['--motion', 'mover=' + D + '/mover.txt']
# frame 1 only: the exposure of frame 0 reaches before the first row
SEQ = ['--trajectory', D + '/trajectory.txt', '--frames', '1:2'] + MOVE
for d in ('cam', 'yml', 'plain'):
    os.makedirs('%s/%s' % (D, d), exist_ok=True)
for name, fx in CAMS.items():
    open('%s/cam/%s.cam' % (D, name), 'w').write(cam_text('rig', fx))
    yaml_twin('%s/yml/%s.yml' % (D, name), 'rig', fx)
    open('%s/plain/%s.cam' % (D, name), 'w').write(cam_text('rig', []))
names = sorted(CAMS)
rc1, e1 = play(['%s/cam/%s.cam' % (D, n) for n in names], SEQ, D + '/o_cam')
rc2, e2 = play(['%s/yml/%s.yml' % (D, n) for n in names], SEQ, D + '/o_yml')
rc3, e3 = play(['%s/plain/%s.cam' % (D, n) for n in names], SEQ, D + '/o_plain')
ok = rc1 == 0 and rc2 == 0 and rc3 == 0
result('camera_yaml_effects_render', ok, 'exit %d %d %d: %s | %s | %s' % (rc1, rc2, rc3, e1, e2, e3))
if ok:
    for n in names:
        files = sorted(os.listdir('%s/o_cam/%s' % (D, n)))
        imgs = [f for f in files if f.startswith('image_')]
        same = all(filecmp.cmp('%s/o_cam/%s/%s' % (D, n, f), '%s/o_yml/%s/%s' % (D, n, f), shallow=False)
                   for f in imgs)
        # the effects are on: every frame differs from the plain camera's
        on = all(not filecmp.cmp('%s/o_cam/%s/%s' % (D, n, f), '%s/o_plain/%s/%s' % (D, n, f), shallow=False)
                 for f in imgs)
        result('camera_yaml_effects_same_%s' % n, same and on and len(imgs) == 1,
               '%d images; same bytes as the .cam: %s; differ from no effects: %s' % (len(imgs), same, on))

# --write-calib: the effects in calib_F.yml, read back by cv2; a world-pose
# camera (no trajectory: the exported pose is the world pose anyway) given
# back to glsplay renders the same bytes
os.makedirs(D + '/world', exist_ok=True)
os.makedirs(D + '/back', exist_ok=True)
for n in names:
    open('%s/world/%s.cam' % (D, n), 'w').write(cam_text('world', CAMS[n]))
rc, e = play(['%s/world/%s.cam' % (D, n) for n in names], MOVE + ['--frame', '1', '--write-calib'], D + '/o_w')
result('camera_yaml_effects_write_calib', rc == 0, e)
if rc == 0:
    for n in names:
        path = '%s/o_w/%s/calib_000001.yml' % (D, n)
        fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
        bad = []
        for k, v in CAMS[n]:
            node = fs.getNode(k)
            if isinstance(v, str):
                got = node.string() if node.isString() else None
            elif k == 'noise_seed':
                got = int(node.string()) if node.isString() else None
            else:
                got = node.real() if node.isReal() or node.isInt() else None
            if got != v:
                bad.append('%s: %r, wanted %r' % (k, got, v))
        fs.release()
        text = open(path).read()
        result('camera_yaml_effects_cv2_reads_%s' % n, not bad, '; '.join(bad) or text)
        # given back (the same output name: the noise is keyed by it)
        back = '%s/back/%s.yml' % (D, n)
        open(back, 'w').write(text)
    rc, e = play(['%s/back/%s.yml' % (D, n) for n in names], MOVE + ['--frame', '1'], D + '/o_back')
    same = rc == 0 and all(filecmp.cmp('%s/o_w/%s/image_000001.png' % (D, n), '%s/o_back/%s/image_000001.png'
                                       % (D, n), shallow=False) for n in names)
    result('camera_yaml_effects_reimport', same, 'exit %d: %s' % (rc, e))
gt_checks.CHECKS.exit()
