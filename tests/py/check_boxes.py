"""Boxes outputs (spec/outputs.md "Boxes") against known placements.

  check_boxes.py write DIR    writes the scene (Boxes.scene) and camera
  check_boxes.py check OUTDIR compares OUTDIR/cam/boxes_000000.{txt,json}

Two boxes (objects.Box, x -0.5..0.5, y 0..1, z -0.5..0.5 in its frame),
each placed by trans, a rotation about y and a non-uniform scale: "front"
in front of "back", hiding part of it; "back" crossing the image's right
edge.  A floor drawn by the top object (instance 0) gets no box.  The
camera is the world frame (x right, y down, z forward).  Expected values
are computed here with numpy: corners, projections, pixel-centre
coverage of each box's silhouette (the convex hull of its projected
corners), the KITTI fields.  Prints "ok NAME" / "FAIL NAME: why"."""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gt_checks  # noqa: E402

W, H = 320, 240
FX, FY, CX, CY = 300.0, 300.0, 159.5, 119.5
# name: (translation, degrees about y, scale, object)
BOXES = {
    "front": ((2.2, -0.3, 5.0), 25.0, (0.5, 0.6, 0.4), "objects.BoxRed"),
    "back": ((4.2, -0.9, 9.0), -15.0, (2.0, 1.5, 1.0), "objects.BoxBlue"),
}

SCENE = "// boxes test scene (tests/py/check_boxes.py)\n" \
    "poly { col(0.3, 0.5, 0.3); vert(-50, 2, 1); vert(50, 2, 1); vert(50, 2, 60); vert(-50, 2, 60); }\n" + \
    "".join('push; trans(%r, %r, %r); rot(%r, 0, 1, 0); scale(%r, %r, %r); call("%s", "%s"); pop;\n'
            % (t + (a,) + s + (o, n)) for n, (t, a, s, o) in BOXES.items())

CAM = gt_checks.camera_text("world", W, H, FX, FY, CX, CY)
result = gt_checks.result


def placement(name):
    t, a, s, _ = BOXES[name]
    r = np.radians(a)
    R = np.array([[np.cos(r), 0, np.sin(r)], [0, 1, 0], [-np.sin(r), 0, np.cos(r)]])  # glRotate about +y
    return R @ np.diag(s), np.array(t)


def corners(name):
    A, t = placement(name)
    lo, hi = np.array([-0.5, 0, -0.5]), np.array([0.5, 1, 0.5])
    o = np.array([[hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2]]
                  for k in range(8)])
    return o @ A.T + t


def project(P):
    return np.stack([FX * P[:, 0] / P[:, 2] + CX, FY * P[:, 1] / P[:, 2] + CY], axis=1)


def hull(p):
    p = sorted(map(tuple, p))
    def half(pts):
        h = []
        for q in pts:
            while len(h) >= 2 and (h[-1][0] - h[-2][0]) * (q[1] - h[-2][1]) - (h[-1][1] - h[-2][1]) * (q[0] - h[-2][0]) <= 0:
                h.pop()
            h.append(q)
        return h
    lower, upper = half(p), half(p[::-1])
    return np.array(lower[:-1] + upper[:-1])


def inside(h, u, v):
    """Signed distance-like test: pixel centres (u, v) inside the convex
    counter-clockwise polygon h, and their least margin to an edge."""
    m = np.full(u.shape, np.inf)
    for i in range(len(h)):
        a, b = h[i], h[(i + 1) % len(h)]
        e = b - a
        d = (e[0] * (v - a[1]) - e[1] * (u - a[0])) / np.hypot(*e)
        m = np.minimum(m, d)
    return m


def check(out):
    d = os.path.join(out, "cam")
    js = json.load(open(os.path.join(d, "boxes_000000.json")))
    lines = open(os.path.join(d, "boxes_000000.txt")).read().splitlines()
    boxes = {b["name"]: b for b in js["boxes"]}
    result("boxes_json_two_boxes", sorted(boxes) == ["back", "front"] and len(lines) == 2 and
           js["width"] == W and js["height"] == H, "names %s, %d lines" % (sorted(boxes), len(lines)))
    if sorted(boxes) != ["back", "front"]:
        return
    v, u = np.mgrid[0:H, 0:W].astype(np.float64)
    cover, margin = {}, {}
    for n in BOXES:
        h = hull(project(corners(n)))
        margin[n] = inside(h, u, v)
        cover[n] = margin[n] > 0
    assert corners("front")[:, 2].max() < corners("back")[:, 2].min()  # front wholly in front
    visible = {"front": cover["front"], "back": cover["back"] & ~cover["front"]}
    for i, n in enumerate(sorted(BOXES, key=lambda n: boxes[n]["instance"])):
        b = boxes[n]
        P = corners(n)
        err = np.abs(np.array(b["corners"]) - P).max()
        result("boxes_corners_%s" % n, err < 1e-9, "largest error %.3g" % err)
        # 2D: the tight box of the visible pixel centres, pixel edges
        ys, xs = np.nonzero(visible[n])
        want = np.array([xs.min() - 0.5, ys.min() - 0.5, xs.max() + 0.5, ys.max() + 0.5])
        got = np.array(b["bbox"])
        q = project(P)
        # left and right are vertical edges (rotation about y) or the image
        # edge: exact; top and bottom slant: within a pixel
        exact = (got[0] == want[0]) and (got[2] == want[2])
        result("boxes_bbox_%s" % n, exact and np.abs(got - want).max() <= 1,
               "bbox %s, numpy %s" % (got, want))
        clipped = [max(q[:, 0].min(), -0.5), max(q[:, 1].min(), -0.5), min(q[:, 0].max(), W - 0.5),
                   min(q[:, 1].max(), H - 0.5)]
        result("boxes_bbox_vs_projection_%s" % n, np.abs(got - np.array(clipped)).max() <= 1,
               "bbox %s, projected corners clipped %s" % (got, clipped))
        # truncation: the projected corners' rectangle outside the image
        area = (q[:, 0].max() - q[:, 0].min()) * (q[:, 1].max() - q[:, 1].min())
        inarea = (clipped[2] - clipped[0]) * (clipped[3] - clipped[1])
        trunc = 1 - inarea / area
        result("boxes_truncated_%s" % n, abs(b["truncated"] - trunc) < 1e-9 and
               ((trunc > 0.05) if n == "back" else trunc == 0), "%r, numpy %r" % (b["truncated"], trunc))
        # visibility: pixels showing it over the pixels it covers alone
        firm = np.abs(margin[n]) > 1e-3
        nvis, nalone = visible[n].sum(), (cover[n]).sum()
        frac = nvis / nalone
        result("boxes_visible_fraction_%s" % n, abs(b["pixels"] - nvis) <= (~firm).sum() and
               abs(b["pixels_alone"] - nalone) <= (~firm & cover[n]).sum() + 2 * np.sqrt(nalone) and
               abs(b["visible_fraction"] - frac) < 0.01 and ((frac < 0.9) if n == "back" else frac == 1),
               "pixels %d/%d (numpy %d/%d), fraction %.4f (numpy %.4f)" % (b["pixels"], b["pixels_alone"], nvis,
                                                                          nalone, b["visible_fraction"], frac))
        level = 0 if frac >= 0.9 else 1 if frac >= 0.5 else 2
        # KITTI: rotation about y, so up = object y, h = its scale; l the
        # longer of x and z; location: the bottom face's centre (larger y)
        A, t = placement(n)
        s = BOXES[n][2]
        lax = 0 if s[0] >= s[2] else 2
        dvec = A[:, lax]
        ry = np.arctan2(-dvec[2], dvec[0])
        loc = A @ np.array([0, 1, 0]) + t
        alpha = (ry - np.arctan2(loc[0], loc[2]) + np.pi) % (2 * np.pi) - np.pi
        f = lines[i].split(" ")
        vals = [float(x) for x in f[1:]]
        good = (len(f) == 15 and f[0] == "objects" and b["class"] == "objects" and
                vals[0] == b["truncated"] and f[2] == str(level) and b["occluded"] == level and
                abs(vals[2] - alpha) < 1e-9 and vals[3:7] == list(got) and
                np.allclose(vals[7:10], [s[1], min(s[0], s[2]), max(s[0], s[2])], atol=1e-9, rtol=0) and
                np.allclose(vals[10:13], loc, atol=1e-9, rtol=0) and abs(vals[13] - ry) < 1e-9)
        result("boxes_kitti_line_%s" % n, good, "line '%s'; numpy h w l %s, loc %s, ry %r, alpha %r, level %d"
               % (lines[i], [s[1], min(s[0], s[2]), max(s[0], s[2])], loc, ry, alpha, level))


if __name__ == "__main__":
    if sys.argv[1] == "write":
        open(os.path.join(sys.argv[2], "Boxes.scene"), "w").write(SCENE)
        open(os.path.join(sys.argv[2], "cam.cam"), "w").write(CAM)
    else:
        check(sys.argv[2])
        gt_checks.CHECKS.exit()
