#!/usr/bin/python3
"""The README's ground-truth gallery row: colour views of glsplay's answer-key files.

usage: gt_gallery.py ROADDIR FRAME STEREODIR DOCSDIR

ROADDIR is examples/road/render.sh's output (left/ with image, instance, normals,
flow, boxes, landmarks of FRAME), STEREODIR the stereo example's (bino_left/
disparity).  Writes DOCSDIR/gt_image.png, gt_instance.png, gt_normals.png,
gt_flow.png, gt_boxes.png and gt_disparity.png, each 320 px wide.  The views are
for people, not for tests: the files themselves are what tools read."""
import colorsys, csv, json, os, sys
import cv2
import numpy as np

WIDTH = 320


def small(img):
    h, w = img.shape[:2]
    return cv2.resize(img, (WIDTH, round(h * WIDTH / w)), interpolation=cv2.INTER_AREA)


def ids_view(ids):
    """Each id its own colour (golden-ratio hues), 0 black."""
    out = np.zeros(ids.shape + (3,), np.uint8)
    for i in np.unique(ids):
        if i == 0:
            continue
        r, g, b = colorsys.hsv_to_rgb((i * 0.618034) % 1.0, 0.65, 0.95)
        out[ids == i] = (int(b * 255), int(g * 255), int(r * 255))
    return out


def flow_view(u, v, valid):
    """Middlebury's convention: hue = direction, saturation = speed over the frame's largest."""
    mag = np.hypot(u, v)
    m = np.percentile(mag[valid], 99) if valid.any() else 1.0
    hsv = np.zeros(u.shape + (3,), np.uint8)
    hsv[..., 0] = ((np.arctan2(-v, -u) / np.pi + 1) * 90).astype(np.uint8) % 180
    hsv[..., 1] = np.clip(mag / max(m, 1e-9) * 255, 0, 255).astype(np.uint8)
    hsv[..., 2] = 255
    out = cv2.cvtColor(hsv, cv2.COLOR_HSV2BGR)
    out[~valid] = 0
    return out


def main():
    road, frame, stereo, docs = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
    f = "%06d" % frame
    L = os.path.join(road, "left")
    img = cv2.imread(os.path.join(L, "image_%s.png" % f))
    cv2.imwrite(os.path.join(docs, "gt_image.png"), small(img))
    ids = cv2.imread(os.path.join(L, "instance_%s.png" % f), cv2.IMREAD_UNCHANGED)
    cv2.imwrite(os.path.join(docs, "gt_instance.png"), small(ids_view(ids)))
    n = cv2.imread(os.path.join(L, "normals_%s.pfm" % f), cv2.IMREAD_UNCHANGED)  # z y x
    nv = np.where(np.abs(n).sum(axis=2, keepdims=True) > 0, (n * -0.5 + 0.5) * 255, 0)
    cv2.imwrite(os.path.join(docs, "gt_normals.png"), small(nv.astype(np.uint8)))
    fl = cv2.readOpticalFlow(os.path.join(L, "flow_%s.flo" % f))
    u, v = fl[..., 0], fl[..., 1]
    cv2.imwrite(os.path.join(docs, "gt_flow.png"), small(flow_view(u, v, np.abs(u) < 1e9)))
    over = img.copy()
    with open(os.path.join(L, "boxes_%s.json" % f)) as fh:
        boxes = json.load(fh)
    for b in boxes.get("objects", boxes.get("boxes", [])):
        l, t, r, btm = b["bbox"]
        cv2.rectangle(over, (int(l), int(t)), (int(r), int(btm)), (0, 255, 255), 2)
    with open(os.path.join(L, "landmarks_%s.csv" % f)) as fh:
        for row in csv.DictReader(fh):
            if row["visible"] == "1":
                cv2.circle(over, (round(float(row["u"])), round(float(row["v"]))), 3, (255, 0, 255), -1)
    cv2.imwrite(os.path.join(docs, "gt_boxes.png"), small(over))
    d = cv2.imread(os.path.join(stereo, "bino_left", "disparity_000000.pfm"), cv2.IMREAD_UNCHANGED)
    ok = np.isfinite(d)
    dv = np.zeros(d.shape, np.uint8)
    if ok.any():
        dv[ok] = np.clip(d[ok] / d[ok].max() * 255, 0, 255).astype(np.uint8)
    dc = cv2.applyColorMap(dv, cv2.COLORMAP_TURBO)
    dc[~ok] = 0
    cv2.imwrite(os.path.join(docs, "gt_disparity.png"), small(dc))


if __name__ == "__main__":
    main()
