"""Optical flow outputs (spec/outputs.md "Optical flow") against geometry
computed here: each pixel's depth (depth_F.pfm) back-projected with K, R,
T of frame t, moved with the mover's known motion (a translation and a
turn) when the point lies in its box, projected with frame t+1's pose.  Occlusion and view by casting
rays at frame t+1 against the two boxes.  Usage: check_flow.py OUTDIR
(the glsplay output of tests/py/flow_scene.py's scene).  Prints "ok NAME"
/ "FAIL NAME: why"."""
import os
import struct
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flow_scene as S  # noqa: E402
import gt_checks  # noqa: E402

result = gt_checks.result


def in_box(P, k, moving, tol=1e-4):
    """Points P (... x 3, world) inside a box at frame k (within tol: the
    depth is float; the floor meets the box within a millimetre)."""
    R, t = S.box_pose(k, moving)
    Q = (P - t) @ R  # R^T (P - t)
    return np.all((Q >= S.BOX_LO - tol) & (Q <= S.BOX_HI + tol), axis=-1)


def ray_box_depth(C, D, k, moving):
    """Camera depth (the ray's parameter, D having z = 1 in the camera) at
    which rays C + t D (D: N x 3, world) enter a box at frame k (slabs in
    the box's frame); inf where they miss."""
    R, t = S.box_pose(k, moving)
    Cb, Db = R.T @ (C - t), D @ R
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (S.BOX_LO - Cb) / Db
        t2 = (S.BOX_HI - Cb) / Db
    tmin = np.nanmax(np.minimum(t1, t2), axis=1)
    tmax = np.nanmin(np.maximum(t1, t2), axis=1)
    hit = (tmin <= tmax) & (tmax > 0)
    return np.where(hit, np.maximum(tmin, 0), np.inf)


def expected(z, k):
    """Expected flow, Z at t+1 and the moving mask of frame k's pixels."""
    R0, T0 = S.rig_pose(k)
    R1, T1 = S.rig_pose(k + 1)
    v, u = np.mgrid[0:S.H, 0:S.W].astype(np.float64)
    Z = z.astype(np.float64)
    Pc = np.stack([(u - S.CX) / S.FX * Z, (v - S.CY) / S.FY * Z, Z], axis=-1)
    with np.errstate(invalid="ignore"):
        P = (Pc - T0) @ R0  # R0^T (Pc - T0), row vectors
    moving = in_box(P, k, True) & np.isfinite(Z)
    # the mover's points: into its frame at k, out with its pose of k + 1
    Ra, ta = S.box_pose(k, True)
    Rb, tb = S.box_pose(k + 1, True)
    with np.errstate(invalid="ignore"):
        Pm = ((P - ta) @ Ra) @ Rb.T + tb
    P1 = np.where(moving[..., None], Pm, P)
    Pc1 = P1 @ R1.T + T1
    with np.errstate(divide="ignore", invalid="ignore"):
        u1 = S.FX * Pc1[..., 0] / Pc1[..., 2] + S.CX
        v1 = S.FY * Pc1[..., 1] / Pc1[..., 2] + S.CY
    return u1 - u, v1 - v, u1, v1, Pc1[..., 2], moving, P


def occluded_at(k1, u1, v1, Z1):
    """For image points (u1, v1) at depth Z1 in frame k1's camera: 1 where
    rays through all of the point and four points 0.75 px around it meet a
    box more than 0.05 nearer, 0 where none meets one nearer (by 1e-3),
    -1 otherwise (undecided here)."""
    R1, T1 = S.rig_pose(k1)
    C = -R1.T @ T1
    boxes = [True, False]
    hits, clear = [], []
    for du, dv in ((0, 0), (-0.75, -0.75), (0.75, -0.75), (-0.75, 0.75), (0.75, 0.75)):
        d = np.stack([(u1 + du - S.CX) / S.FX, (v1 + dv - S.CY) / S.FY, np.ones_like(u1)], axis=-1) @ R1
        t = np.min([ray_box_depth(C, d, k1, mv) for mv in boxes], axis=0)
        hits.append(t < Z1 - 0.05)
        clear.append(t > Z1 - 1e-3)  # no box in front (a point on a box meets it at itself)
    hits, clear = np.array(hits), np.array(clear)
    return np.where(hits.all(axis=0), 1, np.where(clear.all(axis=0), 0, -1))


def main(out):
    d = os.path.join(out, "cam")
    for k in range(S.NFRAMES - 1):
        f = "%06d" % k
        z = cv2.imread(os.path.join(d, "depth_%s.pfm" % f), cv2.IMREAD_UNCHANGED)
        flo_path = os.path.join(d, "flow_%s.flo" % f)
        flo = cv2.readOpticalFlow(flo_path)
        kit = cv2.imread(os.path.join(d, "flow_%s.png" % f), cv2.IMREAD_UNCHANGED)
        mask = cv2.imread(os.path.join(d, "flowmask_%s.png" % f), cv2.IMREAD_UNCHANGED)
        with open(flo_path, "rb") as fh:
            head = fh.read(12)
        result("flow_flo_header_%s" % f, head[:4] == b"PIEH" and struct.unpack("<ii", head[4:]) == (S.W, S.H)
               and os.path.getsize(flo_path) == 12 + 8 * S.W * S.H, repr(head))
        result("flow_files_shapes_%s" % f, flo is not None and flo.shape == (S.H, S.W, 2) and kit.dtype == np.uint16
               and kit.shape == (S.H, S.W, 3) and mask.dtype == np.uint8 and mask.shape == (S.H, S.W),
               "shapes")
        eu, ev, u1, v1, Z1, moving, P = expected(z, k)
        surf = np.isfinite(z)
        front = surf & (Z1 > 0)
        err = np.hypot(flo[..., 0] - eu, flo[..., 1] - ev)
        st = front & ~moving
        mv = front & moving
        result("flow_static_reprojection_%s" % f, st.sum() > 30000 and err[st].max() < 1e-3,
               "%d px, largest error %.3g px" % (st.sum(), err[st].max()))
        # the mover: its known motion, which differs from the static flow
        R1, T1 = S.rig_pose(k + 1)
        Ps = P @ R1.T + T1
        us = S.FX * Ps[..., 0] / Ps[..., 2] + S.CX
        shift = np.abs(us - u1)
        result("flow_moving_instance_%s" % f, mv.sum() > 500 and err[mv].max() < 1e-3 and shift[mv].min() > 5,
               "%d px, largest error %.3g px, motion %.3g px" % (mv.sum(), err[mv].max() if mv.any() else -1,
                                                                  shift[mv].min() if mv.any() else -1))
        none = ~surf
        result("flow_no_surface_unknown_%s" % f, none.sum() > 1000 and (flo[none] > 1e9).all() and
               (mask[none] == 0).all() and (mask[surf] > 0).all(), "%d px" % none.sum())
        # view: out where the point's nearest pixel is outside the image
        m = 1.0
        inside = front & (u1 > -0.5 + m) & (u1 < S.W - 0.5 - m) & (v1 > -0.5 + m) & (v1 < S.H - 0.5 - m)
        outside = surf & ((Z1 <= 0) | (u1 < -0.5 - m) | (u1 > S.W - 0.5 + m) | (v1 < -0.5 - m) |
                          (v1 > S.H - 0.5 + m))
        result("flow_out_of_view_marked_%s" % f, outside.sum() > 100 and (mask[outside] == 3).all(),
               "%d px, %d not 3" % (outside.sum(), (mask[outside] != 3).sum()))
        occ = np.full(z.shape, -1)
        occ[inside] = occluded_at(k + 1, u1[inside], v1[inside], Z1[inside])
        hid = occ == 1
        vis = occ == 0
        result("flow_occluded_marked_%s" % f, hid.sum() > 100 and (mask[hid] == 2).all(),
               "%d px expected occluded, %d not 2" % (hid.sum(), (mask[hid] != 2).sum()))
        result("flow_visible_marked_%s" % f, vis.sum() > 30000 and (mask[vis] == 1).all(),
               "%d px expected visible, %d not 1" % (vis.sum(), (mask[vis] != 1).sum()))
        # behind the mover's new place: the background it now covers
        in_still = in_box(P, k, False)
        bg = hid & ~moving & ~in_still
        result("flow_occluded_behind_moving_box_%s" % f, bg.sum() > 50 and (mask[bg] == 2).all(),
               "%d floor and wall px hidden at t+1" % bg.sum())
        # KITTI PNG as the devkit reads it (R u, G v, B valid; cv2 gives B G R)
        valid = kit[..., 0]
        ku = (kit[..., 2].astype(np.float64) - 2 ** 15) / 64
        kv = (kit[..., 1].astype(np.float64) - 2 ** 15) / 64
        vm = valid > 0
        kerr = np.maximum(np.abs(ku - flo[..., 0]), np.abs(kv - flo[..., 1]))
        result("flow_kitti_png_devkit_%s" % f, (vm == (mask == 1)).all() and (valid <= 1).all() and
               kerr[vm].max() <= 1 / 128 + 1e-6 and (kit[~vm] == 0).all(),
               "valid differs from mask 1 at %d px, largest |png - flo| %.4g" % ((vm != (mask == 1)).sum(),
                                                                               kerr[vm].max()))
        # .flo gives the flow of occluded and out-of-view points too
        oc = (mask == 2) | ((mask == 3) & front)
        result("flow_flo_occluded_given_%s" % f, oc.any() and err[oc].max() < 1e-3, "")
    return 0 if gt_checks.CHECKS.passed else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
