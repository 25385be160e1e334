#!/usr/bin/python3
"""glsplay's ground-truth outputs (spec/outputs.md "Instances and classes",
"Normals") read back with the readers people use (cv2.imread, json, numpy;
run with /usr/bin/python3) and compared with geometry computed here: the
footprints of boxes and a tilted wall at known poses, the normals of their
faces, a named instance moved per frame (--motion).  Prints "ok NAME" /
"FAIL NAME: why".

  check_gt.py BIN DIR
"""
import json
import math
import os
import sys
import numpy as np
import cv2

from glstest import Checks

CHECKS = Checks('gt_setup')
result = CHECKS.result
run = CHECKS.run


BIN, D = sys.argv[1], sys.argv[2]
W, H, F, CX, CY = 320, 240, 200.0, 159.5, 119.5

# The scene: a unit box at two places (the second scaled 1.5 in x and
# named "mover"), and a 2 x 1 wall tilted 30 degrees about x.
FACES = []
for axis in range(3):
    for side in (-0.5, 0.5):
        a, b = (axis + 1) % 3, (axis + 2) % 3
        quad = []
        for u, v in ((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)):
            p = [0.0, 0.0, 0.0]
            p[axis], p[a], p[b] = side, u, v
            quad.append(p)
        FACES.append(quad)
os.makedirs(D + '/src/shapes', exist_ok=True)
with open(D + '/src/shapes/Box.scene', 'w') as f:
    f.write('color(0.8, 0.5, 0.2);\n')
    for q in FACES:
        f.write('poly { %s }\n' % ' '.join('vert(%r, %r, %r);' % tuple(p) for p in q))
with open(D + '/src/Wall.scene', 'w') as f:
    f.write('color(0.2, 0.6, 0.9);\npoly { vert(-1, -0.5, 0); vert(1, -0.5, 0); vert(1, 0.5, 0); vert(-1, 0.5, 0); }\n')
with open(D + '/src/Scene.scene', 'w') as f:
    f.write('push; trans(-1.2, 0.2, 6); call("shapes.Box"); pop;\n'
            'push; trans(1, 0, 7); scale(1.5, 1, 1); call("shapes.Box", "mover"); pop;\n'
            'push; trans(0, -1.4, 8); rot(30, 1, 0, 0); call("Wall"); pop;\n')
run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/gt.glsb', 'Scene'])
with open(D + '/cam.cam', 'w') as f:
    f.write('pose rig\nwidth %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n'
            % (W, H, F, F, CX, CY))
# two frames: the rig still (KITTI rows, identity), "mover" 0.5 down in frame 1
with open(D + '/traj.txt', 'w') as f:
    f.write('1 0 0 0 0 1 0 0 0 0 1 0\n' * 2)
MOVE = [0.0, 0.5]
with open(D + '/mover.txt', 'w') as f:
    for dy in MOVE:
        f.write('1 0 0 0 0 1 0 %r 0 0 1 0\n' % dy)


def rot_x(deg):
    a = math.radians(deg)
    return np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])


# id, path, object, class, name, world transform (A, t): x -> A x + t
BOXES = [(1, 'Scene > shapes.Box#1', 'shapes.Box', None, np.eye(3), np.array([-1.2, 0.2, 6.0])),
         (2, 'Scene > shapes.Box#2', 'shapes.Box', 'mover', np.diag([1.5, 1, 1]), np.array([1.0, 0, 7]))]
WALL = (3, 'Scene > Wall#1', 'Wall', None, rot_x(30), np.array([0, -1.4, 8.0]))
CLASSES = ['Wall', 'shapes']  # sorted by strcmp: upper case first
CLASS_OF = {'shapes.Box': 2, 'Wall': 1}

v, u = np.mgrid[0:H, 0:W].astype(np.float64)
RAYS = np.stack([(u - CX) / F, (v - CY) / F, np.ones_like(u)], -1)  # camera = world here


def project(P):
    P = np.asarray(P, np.float64)
    return np.stack([F * P[..., 0] / P[..., 2] + CX, F * P[..., 1] / P[..., 2] + CY], -1)


def hull_distance(pts):
    """signed distance of every pixel centre to the convex hull of pts
    (positive inside)"""
    # the hull's vertices (cv2 takes float32; the distances use the doubles)
    idx = cv2.convexHull(pts.astype(np.float32).reshape(-1, 1, 2), returnPoints=False).ravel()
    h = pts[idx]
    area = sum(h[i][0] * h[(i + 1) % len(h)][1] - h[(i + 1) % len(h)][0] * h[i][1] for i in range(len(h)))
    if area < 0:
        h = h[::-1]
    d = np.full(u.shape, np.inf)
    for i in range(len(h)):
        a, b = h[i], h[(i + 1) % len(h)]
        e = b - a
        d = np.minimum(d, (e[0] * (v - a[1]) - e[1] * (u - a[0])) / np.hypot(*e))
    return d


def corners(A, t, local):
    return np.array([A @ np.asarray(p) + t for p in local])


BOX_CORNERS = [[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
WALL_CORNERS = [[-1, -0.5, 0], [1, -0.5, 0], [1, 0.5, 0], [-1, 0.5, 0]]


def expected_ids(frame):
    """ids from the footprints (the three do not overlap in the image);
    the band within 1e-3 px of an outline is left out (-1)"""
    ids = np.zeros((H, W), np.int64)
    band = np.zeros((H, W), bool)
    parts = [(b[0], corners(b[4], b[5] + (np.array([0, MOVE[frame], 0]) if b[3] else 0), BOX_CORNERS))
             for b in BOXES] + [(WALL[0], corners(WALL[4], WALL[5], WALL_CORNERS))]
    for i, c in parts:
        d = hull_distance(project(c))
        ids[d > 0] = i
        band |= np.abs(d) < 1e-3
    ids[band] = -1
    return ids


def box_normals(A, t):
    """per pixel: the camera-frame normal of the face of box (A, t) its
    ray enters first (nan where it misses or is within 1e-6 of an edge)"""
    Ai = np.linalg.inv(A)
    o = -Ai @ t  # the camera centre (origin) in the box frame
    d = RAYS @ Ai.T
    with np.errstate(divide='ignore', invalid='ignore'):
        t0 = (-0.5 - o) / d
        t1 = (0.5 - o) / d
    tin3 = np.minimum(t0, t1)
    tin, tout = tin3.max(-1), np.maximum(t0, t1).min(-1)
    ax = tin3.argmax(-1)
    srt = np.sort(tin3, -1)
    n_local = np.zeros(d.shape)
    sign = -np.sign(np.take_along_axis(d, ax[..., None], -1)[..., 0])
    np.put_along_axis(n_local, ax[..., None], sign[..., None], -1)
    n = n_local @ Ai  # normals transform by A^-T: n_world = A^-T n_local
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    bad = ~(tin < tout) | (srt[..., 2] - srt[..., 1] < 1e-6 * tin)
    n[bad] = np.nan
    return n


def read_pfm(path):
    """PFM as the format defines it: header, scale < 0 little-endian, rows
    bottom to top; returned top row first"""
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), '<f4' if scale < 0 else '>f4')
    c = 3 if kind == b'PF' else 1
    return kind, scale, data.reshape(h, w, c)[::-1]


out = D + '/o'
p = run([BIN + '/glsplay', D + '/gt.glsb', '--camera', D + '/cam.cam', '-o', out, '--trajectory', D + '/traj.txt',
         '--motion', 'mover=' + D + '/mover.txt', '--outputs', 'image,depth,instance,class,coco,normals',
         '--explain'])
result('gt_explain', 'ground truth: one extra pass (instance ids, normals)' in p.stdout, p.stdout[-400:])

for frame in (0, 1):
    base = '%s/cam/%%s_%06d.%%s' % (out, frame)
    inst = cv2.imread(base % ('instance', 'png'), cv2.IMREAD_UNCHANGED)
    cls = cv2.imread(base % ('class', 'png'), cv2.IMREAD_UNCHANGED)
    result('gt_instance_png_%d' % frame, inst is not None and inst.dtype == np.uint16 and inst.shape == (H, W),
           'not a 16-bit grey %dx%d PNG: %r' % (W, H, None if inst is None else (inst.dtype, inst.shape)))
    if inst is None or cls is None:
        continue
    want = expected_ids(frame)
    m = want >= 0
    wrong = np.count_nonzero(inst[m] != want[m])
    result('gt_instance_footprints_%d' % frame,
           wrong == 0 and all(np.count_nonzero(want == i) > 500 for i in (1, 2, 3)) and np.count_nonzero(~m) < 60,
           '%d of %d pixels differ from the footprints (ids %s)' % (wrong, np.count_nonzero(m), np.unique(inst)))
    # depth: background exactly where no id
    z = cv2.imread(base % ('depth', 'pfm'), cv2.IMREAD_UNCHANGED)
    result('gt_instance_depth_%d' % frame, np.array_equal(inst == 0, ~np.isfinite(z)), 'ids and depth disagree')
    # the class image: the instance's class id
    lut = np.array([0, CLASS_OF['shapes.Box'], CLASS_OF['shapes.Box'], CLASS_OF['Wall']], np.uint16)
    result('gt_class_png_%d' % frame, cls.dtype == np.uint16 and np.array_equal(cls, lut[inst]),
           'class ids are not the instances\' classes')
    # the JSON table
    with open(base % ('instances', 'json')) as f:
        js = json.load(f)
    rows = {r['id']: r for r in js['instances']}
    good = js['frame'] == frame and js['camera'] == 'cam' and js['width'] == W and js['height'] == H
    good &= js['classes'] == [{'id': i + 1, 'name': n} for i, n in enumerate(CLASSES)]
    for i, path, obj, name, A, t in BOXES + [WALL]:
        r = rows.get(i, {})
        good &= (r.get('path') == path and r.get('object') == obj and r.get('name') == name and
                 r.get('class') == CLASSES[CLASS_OF[obj] - 1] and r.get('class_id') == CLASS_OF[obj] and
                 r.get('pixels') == int(np.count_nonzero(inst == i)))
    result('gt_instances_json_%d' % frame, good and len(rows) == 3, json.dumps(js)[:600])
    # COCO: the RLE decoded from COCO's definition is the instance mask
    with open(base % ('coco', 'json')) as f:
        coco = json.load(f)
    good = coco['images'] == [{'id': frame, 'file_name': 'image_%06d.png' % frame, 'width': W, 'height': H}]
    good &= coco['categories'] == [{'id': i + 1, 'name': n} for i, n in enumerate(CLASSES)]
    why = 'header %s' % json.dumps({k: coco[k] for k in ('images', 'categories')})
    for a in coco['annotations']:
        cnt = a['segmentation']['counts']
        flat = np.zeros(H * W, np.uint8)
        pos, val = 0, 0
        for c in cnt:
            flat[pos:pos + c] = val
            pos, val = pos + c, 1 - val
        mask = flat.reshape((H, W), order='F').astype(bool)  # column-major
        ys, xs = np.nonzero(mask)
        ok1 = (pos == H * W and a['segmentation']['size'] == [H, W] and a['iscrowd'] == 1 and
               a['image_id'] == frame and np.array_equal(mask, inst == a['id']) and
               a['area'] == int(mask.sum()) and a['category_id'] == lut[a['id']] and
               a['bbox'] == [int(xs.min()), int(ys.min()), int(xs.max() - xs.min() + 1), int(ys.max() - ys.min() + 1)])
        if not ok1:
            why = 'annotation %d: %s' % (a['id'], json.dumps(a)[:300])
        good &= ok1
    result('gt_coco_rle_%d' % frame, good and sorted(a['id'] for a in coco['annotations']) == [1, 2, 3], why)
    # normals: the faces' closed form
    kind, scale, n = read_pfm(base % ('normals', 'pfm'))
    ncv = cv2.imread(base % ('normals', 'pfm'), cv2.IMREAD_UNCHANGED)
    result('gt_normals_pfm_%d' % frame, kind == b'PF' and scale == -1.0 and n.shape == (H, W, 3) and
           ncv is not None and np.array_equal(ncv[..., ::-1], n),
           'not a 3-channel little-endian PFM that cv2.imread reads as (z, y, x): %r %r' % (kind, scale))
    want_n = np.full((H, W, 3), np.nan)
    for i, path, obj, name, A, t in BOXES:
        tt = t + (np.array([0, MOVE[frame], 0]) if name else 0)
        bn = box_normals(A, tt)
        sel = want == i
        want_n[sel] = bn[sel]
    # the wall: its plane's normal, turned to the camera
    nw = WALL[4] @ np.array([0, 0, 1.0])
    if nw @ WALL[5] > 0:
        nw = -nw
    want_n[want == 3] = nw
    sel = np.isfinite(want_n[..., 0])
    err = np.abs(n[sel] - want_n[sel]).max()
    result('gt_normals_faces_%d' % frame, err <= 1e-5 and np.count_nonzero(sel) > 3000 and
           np.all(n[inst == 0] == 0) and np.allclose(np.linalg.norm(n[inst > 0], axis=-1), 1, atol=1e-6),
           'largest error %.3g over %d pixels' % (err, np.count_nonzero(sel)))

# anti-aliasing blends the image, never the ground truth: the same files
run([BIN + '/glsplay', D + '/gt.glsb', '--camera', D + '/cam.cam', '-o', D + '/aa', '--trajectory', D + '/traj.txt',
     '--frames', '0:1', '--motion', 'mover=' + D + '/mover.txt', '--outputs', 'image,instance,class,coco,normals',
     '--aa', '3'])
same = []
for kind, ext in (('instance', 'png'), ('class', 'png'), ('instances', 'json'), ('coco', 'json'),
                  ('normals', 'pfm')):
    with open('%s/cam/%s_000000.%s' % (out, kind, ext), 'rb') as a, open('%s/aa/cam/%s_000000.%s' % (D, kind, ext),
                                                                       'rb') as b:
        same.append(a.read() == b.read())
with open('%s/cam/image_000000.png' % out, 'rb') as a, open('%s/aa/cam/image_000000.png' % D, 'rb') as b:
    blended = a.read() != b.read()
result('gt_not_blended_by_aa', all(same) and blended, 'same files: %r, image anti-aliased: %r' % (same, blended))

# the named instance keeps its id and moves: its centroid 0.5 * f / z down
c = []
for frame in (0, 1):
    inst = cv2.imread('%s/cam/instance_%06d.png' % (out, frame), cv2.IMREAD_UNCHANGED)
    ys, xs = np.nonzero(inst == 2)
    c.append((xs.mean(), ys.mean()))
result('gt_motion_keeps_id', abs(c[1][0] - c[0][0]) < 0.5 and 10 < c[1][1] - c[0][1] < 16,
       'centroids %r' % c)
CHECKS.exit()
