#!/usr/bin/python3
"""glsplay --write-calib read back with the readers people use (run with
/usr/bin/python3: cv2, numpy, yaml, json), against geometry computed here
(spec/outputs.md "Calibration files").  Prints "ok NAME" / "FAIL NAME: why".

  check_calib.py export BIN DIR   the exported files (OpenCV, KITTI, ROS, JSON)
  check_calib.py import BIN DIR   cameras written by cv2.FileStorage, rendered and exported again
"""
import json
import math
import sys
import numpy as np
import cv2
import yaml

from glstest import Checks

CHECKS = Checks('calib_setup')
result = CHECKS.result
run = CHECKS.run


def rot(axis, a):
    """rotation by a radians about axis 0 (x), 1 (y) or 2 (z)"""
    c, s = math.cos(a), math.sin(a)
    i, j = [k for k in range(3) if k != axis]
    R = np.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R


def fmt(v):
    return ' '.join(repr(float(x)) for x in np.ravel(v))


def write_cam(path, cam, pose=None):
    with open(path, 'w') as f:
        if pose:
            f.write('pose %s\n' % pose)
        f.write('width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nskew %r\nR %s\nT %s\nnear %r\nfar %r\n' % (
            cam['W'], cam['H'], cam['fx'], cam['fy'], cam['cx'], cam['cy'], cam['skew'], fmt(cam['R']),
            fmt(cam['T']), cam['near'], cam['far']))


def K_of(c):
    return np.array([[c['fx'], c['skew'], c['cx']], [0, c['fy'], c['cy']], [0, 0, 1.0]])


# The rig: left and right rectified (same K and R, 0.4 apart along the
# camera x axis), up looking elsewhere (not rectified with left).
B = 0.4
R0 = rot(1, 0.2) @ rot(0, -0.05)
LEFT = dict(W=80, H=60, fx=70.0, fy=65.0, cx=39.3, cy=29.7, skew=0.5, R=R0, T=np.array([0.3, -0.2, 1.5]),
            near=0.1, far=100.0)
RIGHT = dict(LEFT, T=LEFT['T'] - np.array([B, 0, 0]))  # centre C + R^T (B, 0, 0)
UP = dict(LEFT, fx=75.0, cx=40.0, R=rot(0, 0.1) @ R0, T=np.array([0.1, 0.3, 1.2]))
CAMS = [('left', LEFT), ('right', RIGHT), ('up', UP)]
# a grey wall at z = 10 and a red square on it, centre (0.5, 0.25, 9.9)
SCENE = ('color(0.5, 0.5, 0.5); poly { vert(-30, -30, 10); vert(30, -30, 10); vert(30, 30, 10); vert(-30, 30, 10); }\n'
         'color(1, 0, 0); poly { vert(0, -0.25, 9.9); vert(1, -0.25, 9.9); vert(1, 0.75, 9.9); vert(0, 0.75, 9.9); }\n')
MARK = np.array([0.5, 0.25, 9.9])


def fs_read(path):
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_READ)
    if not fs.isOpened():
        return None
    d = {k: fs.getNode(k).mat() for k in ('camera_matrix', 'distortion_coefficients', 'R', 'T')}
    d['W'] = int(fs.getNode('image_width').real())
    d['H'] = int(fs.getNode('image_height').real())
    d['near'] = fs.getNode('near').real()
    d['far'] = fs.getNode('far').real()
    fs.release()
    return d


def read_pfm_ply(out, name, frame):
    z = cv2.imread('%s/%s/depth_%06d.pfm' % (out, name, frame), cv2.IMREAD_UNCHANGED)
    raw = open('%s/%s/points_%06d.ply' % (out, name, frame), 'rb').read()
    hdr, body = raw.split(b'end_header\n', 1)
    n = int([l for l in hdr.split(b'\n') if l.startswith(b'element vertex')][0].split()[2])
    pts = np.frombuffer(body, dtype=np.dtype([('x', '<f8'), ('y', '<f8'), ('z', '<f8'),
                                              ('r', 'u1'), ('g', 'u1'), ('b', 'u1')]), count=n)
    return z, pts


def project(K, R, T, P):
    x = (K @ np.c_[R, T.reshape(3)]) @ np.c_[P, np.ones(len(P))].T
    return (x[:2] / x[2]).T


def check_projection(tag, out, name, frame, d):
    """the exported K, R, T against what the depth and points outputs imply:
    each point of the cloud projects back onto its own pixel, and the red
    marker's centre projects onto red at the right depth"""
    K, R, T = d['camera_matrix'], d['R'], d['T']
    z, pts = read_pfm_ply(out, name, frame)
    rows, cols = np.nonzero(np.isfinite(z))  # the cloud's order: rows from the top
    P = np.c_[pts['x'], pts['y'], pts['z']]
    uv = project(K, R, T, P)
    err = np.max(np.abs(uv - np.c_[cols, rows])) if len(P) else 1e9
    result('%s_points_%s' % (tag, name), len(P) == z.size and err < 1e-6, '%d points, worst %.3g px' % (len(P), err))
    img = cv2.imread('%s/%s/image_%06d.png' % (out, name, frame), cv2.IMREAD_COLOR)[:, :, ::-1]
    u, v = project(K, R, T, MARK[None, :])[0]
    iu, iv = int(round(u)), int(round(v))
    Zc = (R @ MARK + T.reshape(3))[2]
    good = 0 <= iu < d['W'] and 0 <= iv < d['H'] and tuple(img[iv, iu]) == (255, 0, 0) and \
        abs(z[iv, iu] - Zc) < 1e-2 * Zc  # within half a pixel of the centre, on a slanted view
    result('%s_marker_%s' % (tag, name), good, 'marker at (%.2f, %.2f)' % (u, v))


def kitti_read(path):
    P = {}
    for line in open(path):
        k, v = line.split(':', 1)  # as pykitti's read_calib_file does
        P[k] = np.array([float(x) for x in v.split()]).reshape(3, 4)
    return P


def check_static(tag, out, rig):
    """calib.txt and camera_info.yaml: the rig relative to camera 0"""
    P = kitti_read(out + '/calib.txt')
    result('%s_kitti_keys' % tag, sorted(P) == ['P%d' % i for i in range(len(rig))], str(sorted(P)))
    c0 = rig[0][1]
    for i, (name, c) in enumerate(rig):
        Rrel = c['R'] @ c0['R'].T  # x0 -> xi
        trel = c['T'] - Rrel @ c0['T']
        want = K_of(c) @ np.c_[Rrel, trel]
        err = np.max(np.abs(P['P%d' % i] - want))
        result('%s_kitti_P%d' % (tag, i), err < 1e-9 * np.max(np.abs(want)), 'worst %.3g' % err)
    ros = {name: yaml.safe_load(open('%s/%s/camera_info.yaml' % (out, name))) for name, _ in rig}
    for name, c in rig:
        r = ros[name]
        good = r['image_width'] == c['W'] and r['image_height'] == c['H'] and r['camera_name'] == name and \
            r['distortion_model'] == 'plumb_bob' and r['distortion_coefficients']['data'] == [0.0] * 5 and \
            np.array_equal(np.reshape(r['camera_matrix']['data'], (3, 3)), K_of(c)) and \
            all(isinstance(x, float) for x in r['projection_matrix']['data'])
        result('%s_ros_%s' % (tag, name), good, str(r))
    # the right camera of the rectified pair: Tx = -fx B, B > 0 the baseline
    # (its centre B to the right of the left camera's, along the left's x)
    C = {n: -c['R'].T @ c['T'] for n, c in rig}
    base = (rig[0][1]['R'] @ (C['right'] - C['left']))
    Pr = np.reshape(ros['right']['projection_matrix']['data'], (3, 4))
    Pl = np.reshape(ros['left']['projection_matrix']['data'], (3, 4))
    result('%s_ros_tx_right' % tag, abs(base[0] - B) < 1e-12 and Pr[0, 3] < 0 and
           abs(Pr[0, 3] + RIGHT['fx'] * base[0]) < 1e-9 and Pl[0, 3] == 0 and
           np.array_equal(Pr[:, :3], K_of(RIGHT)), 'P %s, baseline %s' % (Pr, base))
    up = ros['up']
    result('%s_ros_unrectified_mono' % tag,
           np.array_equal(np.reshape(up['projection_matrix']['data'], (3, 4)), np.c_[K_of(UP), np.zeros(3)]) and
           open(out + '/up/camera_info.yaml').readline().startswith('# not rectified with camera 0 (left)'),
           str(up['projection_matrix']))


def check_frame(tag, out, frame, world, rig_rel=None, time=None):
    """NAME/calib_F.yml (cv2.FileStorage) and calib_F.json (json) of one frame"""
    doc = json.load(open('%s/calib_%06d.json' % (out, frame)))
    result('%s_json_frame' % tag, doc['frame'] == frame and doc.get('time') == time and
           [c['name'] for c in doc['cameras']] == [n for n, _ in world], str(doc.get('frame')))
    for i, (name, c) in enumerate(world):
        d = fs_read('%s/%s/calib_%06d.yml' % (out, name, frame))
        if d is None:
            result('%s_opencv_read_%s' % (tag, name), False, 'cv2.FileStorage cannot open it')
            continue
        exact = np.array_equal(d['camera_matrix'], K_of(c)) and d['camera_matrix'].dtype == np.float64 and \
            d['distortion_coefficients'].shape == (1, 5) and not d['distortion_coefficients'].any() and \
            d['T'].shape == (3, 1) and d['W'] == c['W'] and d['H'] == c['H'] and d['near'] == c['near'] and \
            d['far'] == c['far']
        if rig_rel is None:  # the camera file's pose, exactly
            exact = exact and np.array_equal(d['R'], c['R']) and np.array_equal(d['T'].ravel(), c['T'])
        else:  # composed with the rig's pose: close (the order of sums is the player's)
            exact = exact and np.allclose(d['R'], c['R'], rtol=0, atol=1e-14) and \
                np.allclose(d['T'].ravel(), c['T'], rtol=0, atol=1e-13)
        result('%s_opencv_%s' % (tag, name), exact, str(d))
        j = doc['cameras'][i]
        # the JSON holds the same doubles as the YAML
        good = j['K'] == d['camera_matrix'].tolist() and j['R'] == d['R'].tolist() and \
            j['T'] == d['T'].ravel().tolist() and j['dist'] == [0] * 5 and j['pose_frame'] == 'world' and \
            j['image_width'] == c['W'] and j['image_height'] == c['H']
        if rig_rel is not None:
            good = good and j['rig']['R'] == rig_rel[i][1]['R'].tolist() and j['rig']['T'] == rig_rel[i][1]['T'].tolist()
        result('%s_json_%s' % (tag, name), good, str(j))
        check_projection(tag, out, name, frame, d)


def export(bin_dir, t):
    with open(t + '/Wall.scene', 'w') as f:
        f.write(SCENE)
    run([bin_dir + '/glsc', '-I', t, '-o', t + '/wall.glsb', 'Wall'])
    for name, c in CAMS:
        write_cam('%s/%s.cam' % (t, name), c)
    cams = sum([['--camera', '%s/%s.cam' % (t, n)] for n, _ in CAMS], [])
    run([bin_dir + '/glsplay', t + '/wall.glsb', *cams, '--frame', '7', '--write-calib', '-o', t + '/single'])
    check_static('calib', t + '/single', CAMS)
    check_frame('calib', t + '/single', 7, CAMS)
    # an exported file is a camera glsplay reads: the same bytes again
    import filecmp
    run([bin_dir + '/glsplay', t + '/wall.glsb', '--camera', t + '/single/up/calib_000007.yml', '--frame', '7',
         '-o', t + '/again'])
    result('calib_export_reimport', all(filecmp.cmp('%s/single/up/%s_000007.%s' % (t, k, e),
                                                    '%s/again/calib_000007/%s_000007.%s' % (t, k, e), shallow=False)
                                        for k, e in (('image', 'png'), ('depth', 'pfm'), ('points', 'ply'))))
    # a trajectory: the rig moves 0.5 forward and turns a little each frame;
    # the camera files give the poses relative to the rig
    traj = []
    for f in range(3):
        Rr = rot(1, 0.03 * f)
        Tr = np.array([0.0, 0.0, -0.5 * f])
        traj.append((f, 0.1 * f, Rr, Tr))
    with open(t + '/traj.txt', 'w') as fh:
        for f, tm, Rr, Tr in traj:
            fh.write('%d %r %s %s\n' % (f, tm, fmt(Rr), fmt(Tr)))
    for name, c in CAMS:
        write_cam('%s/rig_%s.cam' % (t, name), c, 'rig')
    cams = sum([['--camera', '%s/rig_%s.cam' % (t, n)] for n, _ in CAMS], [])
    run([bin_dir + '/glsplay', t + '/wall.glsb', *cams, '--trajectory', t + '/traj.txt', '--frames', '1:',
         '--write-calib', '-o', t + '/seq'])
    rig = [('rig_' + n, c) for n, c in CAMS]
    result('calib_traj_range', not any(
        __import__('os').path.exists(t + '/seq/' + p) for p in ('calib_000000.json', 'rig_left/calib_000000.yml')),
        'frame 0 is outside --frames 1:')
    for f, tm, Rr, Tr in traj[1:]:
        world = [(n, dict(c, R=c['R'] @ Rr, T=c['R'] @ Tr + c['T'])) for n, c in rig]
        check_frame('calib_traj%d' % f, t + '/seq', f, world, rig, tm)
    # the static files are those of the rig-relative cameras
    same = all(open('%s/single/%s' % (t, a)).read() == open('%s/seq/%s' % (t, b)).read()
               for a, b in (('calib.txt', 'calib.txt'),))
    result('calib_traj_kitti_static', same, 'calib.txt differs between the single render and the sequence')


def fs_write(path, c, rvec=None, extra=True):
    """a camera as cv2.FileStorage writes it: a calibration's keys, R and T
    (or rvec and tvec), and glsplay's near and far"""
    fs = cv2.FileStorage(path, cv2.FILE_STORAGE_WRITE)
    if extra:  # what a calibration also writes, which glsplay skips
        fs.write('calibration_time', 'Mon Jan  1 00:00:00 2024')
        fs.write('nr_of_frames', 12)
        fs.write('avg_reprojection_error', 0.25)
        fs.write('per_view_reprojection_errors', np.arange(12, dtype=np.float32).reshape(12, 1) / 7)
    fs.write('image_width', c['W'])
    fs.write('image_height', c['H'])
    fs.write('camera_matrix', K_of(c))
    fs.write('distortion_coefficients', np.zeros((1, 5)))
    if rvec is None:
        fs.write('R', c['R'])
        fs.write('T', c['T'].reshape(3, 1))
    else:
        fs.write('rvec', rvec)
        fs.write('tvec', c['T'].reshape(3, 1))
    fs.write('near', c['near'])
    fs.write('far', c['far'])
    fs.release()


def same_files(a, b, name):
    import filecmp
    files = ('image_000000.png', 'depth_000000.pfm', 'points_000000.ply')
    return all(filecmp.cmp('%s/%s/%s' % (a, name, f), '%s/%s/%s' % (b, name, f), shallow=False) for f in files)


def import_(bin_dir, t):
    import os
    with open(t + '/Wall.scene', 'w') as f:
        f.write(SCENE)
    run([bin_dir + '/glsc', '-I', t, '-o', t + '/wall.glsb', 'Wall'])
    for d in ('yml', 'cam', 'rvec', 'rvecyml', 'rcam'):
        os.makedirs('%s/%s' % (t, d), exist_ok=True)
    # R and T: the cv2 file and the equivalent .cam render the same bytes
    fs_write(t + '/yml/cv.yml', UP)
    write_cam(t + '/cam/cv.cam', UP)
    play = [bin_dir + '/glsplay', t + '/wall.glsb', '--camera']
    run(play + [t + '/yml/cv.yml', '--write-calib', '-o', t + '/o_yml'])
    run(play + [t + '/cam/cv.cam', '-o', t + '/o_cam'])
    result('calib_import_yml_renders_as_cam', same_files(t + '/o_yml', t + '/o_cam', 'cv'))
    # cv2 -> glsplay -> export -> cv2: the same values, exactly
    d = fs_read(t + '/o_yml/cv/calib_000000.yml')
    good = d is not None and np.array_equal(d['camera_matrix'], K_of(UP)) and np.array_equal(d['R'], UP['R']) and \
        np.array_equal(d['T'], UP['T'].reshape(3, 1)) and np.array_equal(d['distortion_coefficients'], np.zeros((1, 5))) \
        and (d['W'], d['H'], d['near'], d['far']) == (UP['W'], UP['H'], UP['near'], UP['far'])
    result('calib_import_roundtrip_exact', good, str(d))
    # rvec and tvec: R is cv2.Rodrigues(rvec), a .cam with K and rvec renders
    # the same bytes as the cv2 file
    rvec = np.array([[0.3], [-0.2], [0.05]])
    fs_write(t + '/rvecyml/rv.yml', LEFT, rvec, extra=False)
    with open(t + '/rvec/rv.cam', 'w') as f:
        f.write('width %d\nheight %d\nK %s\nrvec %s\nT %s\nnear %r\nfar %r\n' % (
            LEFT['W'], LEFT['H'], fmt(K_of(LEFT)), fmt(rvec), fmt(LEFT['T']), LEFT['near'], LEFT['far']))
    run(play + [t + '/rvecyml/rv.yml', '--write-calib', '-o', t + '/o_rvecyml'])
    run(play + [t + '/rvec/rv.cam', '-o', t + '/o_rvec'])
    result('calib_import_rvec_renders_as_cam', same_files(t + '/o_rvecyml', t + '/o_rvec', 'rv'))
    d = fs_read(t + '/o_rvecyml/rv/calib_000000.yml')
    Rcv = cv2.Rodrigues(rvec)[0]
    err = np.max(np.abs(d['R'] - Rcv))
    result('calib_import_rvec_is_rodrigues', err < 1e-15 and np.array_equal(d['T'], LEFT['T'].reshape(3, 1)),
           'R differs from cv2.Rodrigues by %.3g' % err)
    # and the exported R, given as R in a .cam, renders the same bytes again
    write_cam(t + '/rcam/rv.cam', dict(LEFT, R=d['R']))
    run(play + [t + '/rcam/rv.cam', '-o', t + '/o_rcam'])
    result('calib_import_rvec_renders_as_r', same_files(t + '/o_rvecyml', t + '/o_rcam', 'rv'))


if __name__ == '__main__':
    mode, bin_dir, t = sys.argv[1:4]
    {'export': export, 'import': import_}[mode](bin_dir, t)
    CHECKS.exit()
