"""The road example's clip (examples/road/render.sh: OUTDIR/clip, flow and
boxes with the vehicles moving) against the trajectory: every pixel
outside the 2D boxes of the moving vehicles (the boxes named lead and
oncoming) is static, so its flow is its depth back-projected with frame
t's pose and projected with the next trajectory line's (rig pose composed
with the camera's pose relative to the rig), computed here in numpy.
The vehicles' pixels must move otherwise.  Usage: check_road_flow.py
OUTDIR RIGDIR FIRST LAST (the clip's frames FIRST..LAST-1).  Prints
"ok NAME" / "FAIL NAME: why"."""
import json
import os
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gt_checks  # noqa: E402

result = gt_checks.result


def read_cam(path):
    c = {}
    for line in open(path):
        f = line.split("#")[0].split()
        if f:
            c[f[0]] = [float(x) for x in f[1:]] if f[0] != "pose" else f[1]
    K = np.array([[c["fx"][0], 0, c["cx"][0]], [0, c["fy"][0], c["cy"][0]], [0, 0, 1]])
    return K, np.array(c["R"]).reshape(3, 3), np.array(c["T"]), int(c["width"][0]), int(c["height"][0])


def read_traj(path):
    rows = {}
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        rows[int(v[0])] = (np.array(v[2:11]).reshape(3, 3), np.array(v[11:14]))
    return rows


def main(out, rig, first, last):
    traj = read_traj(os.path.join(out, "road", "trajectory.txt"))
    frames = sorted(traj)
    for cam in ("left", "right"):
        K, Rc, Tc, W, H = read_cam(os.path.join(rig, cam + ".cam"))
        d = os.path.join(out, "clip", cam)
        for k in range(first, last):
            f = "%06d" % k
            nxt = frames[frames.index(k) + 1]
            Rr0, Tr0 = traj[k]
            Rr1, Tr1 = traj[nxt]
            R0, T0 = Rc @ Rr0, Rc @ Tr0 + Tc
            R1, T1 = Rc @ Rr1, Rc @ Tr1 + Tc
            z = cv2.imread(os.path.join(d, "depth_%s.pfm" % f), cv2.IMREAD_UNCHANGED).astype(np.float64)
            flo = cv2.readOpticalFlow(os.path.join(d, "flow_%s.flo" % f))
            kit = cv2.imread(os.path.join(d, "flow_%s.png" % f), cv2.IMREAD_UNCHANGED)
            mask = cv2.imread(os.path.join(d, "flowmask_%s.png" % f), cv2.IMREAD_UNCHANGED)
            boxes = json.load(open(os.path.join(d, "boxes_%s.json" % f)))["boxes"]
            lines = open(os.path.join(d, "boxes_%s.txt" % f)).read().splitlines()
            moving = np.zeros((H, W), bool)
            names = set()
            for b in boxes:
                if b["name"] in ("lead", "oncoming"):
                    names.add(b["name"])
                    l, t, r, bt = [int(x + 0.5) for x in b["bbox"]]
                    moving[t:bt, l:r] = True
            v, u = np.mgrid[0:H, 0:W].astype(np.float64)
            Pc = np.stack([(u - K[0, 2]) / K[0, 0] * z, (v - K[1, 2]) / K[1, 1] * z, z], axis=-1)
            with np.errstate(invalid="ignore"):
                P = (Pc - T0) @ R0
                Q = P @ R1.T + T1
                eu = K[0, 0] * Q[..., 0] / Q[..., 2] + K[0, 2] - u
                ev = K[1, 1] * Q[..., 1] / Q[..., 2] + K[1, 2] - v
            surf = np.isfinite(z)
            st = surf & ~moving & (Q[..., 2] > 0)
            err = np.hypot(flo[..., 0] - eu, flo[..., 1] - ev)
            name = "road_flow_%s_%s" % (cam, f)
            result(name + "_static", st.sum() > 100000 and err[st].max() < 1e-3,
                   "%d px, largest error %.3g px" % (st.sum(), err[st].max()))
            mv = surf & moving & (mask > 0)
            result(name + "_vehicles_move", names == {"lead", "oncoming"} and (err[mv] > 0.5).sum() > 100,
                   "vehicles %s, %d px moving by > 0.5 px" % (sorted(names), (err[mv] > 0.5).sum()))
            vm = kit[..., 0] > 0
            ku = (kit[..., 2].astype(np.float64) - 2 ** 15) / 64
            result(name + "_kitti", (vm == (mask == 1)).all() and np.abs(ku - flo[..., 0])[vm].max() <= 1 / 128,
                   "")
            result(name + "_mask_values", set(np.unique(mask)) <= {0, 1, 2, 3} and (mask[~surf] == 0).all() and
                   (mask == 1).sum() > 100000, "values %s" % np.unique(mask))
            result(name + "_boxes_lines", len(lines) == len(boxes) and all(len(x.split(" ")) == 15 for x in lines),
                   "%d lines, %d boxes" % (len(lines), len(boxes)))
    return 0 if gt_checks.CHECKS.passed else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])))
