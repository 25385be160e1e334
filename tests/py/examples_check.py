"""Checks that the paper-figure examples (examples/) are usable for what
they are for.  Run with /usr/bin/python3 (numpy, cv2).  Prints
"ok NAME" / "FAIL NAME: why" and the measured figures ("# ..." lines).

    examples_check.py calib CAMDIR OUTDIR [MAX_PX]
        OpenCV's chessboard detector on OUTDIR/viewNN/image_000000.png for
        every CAMDIR/viewNN.cam: all 9 x 6 corners found, and the refined
        corners within MAX_PX (default 0.1) RMS and max of the stated corners
        (0.025 i, 0.025 j, 0) projected through the camera files (own
        projection, cross-checked against cv2.projectPoints); then
        cv2.calibrateCamera on all views recovers fx, fy, cx, cy.
    examples_check.py sgbm CAMDIR OUTDIR [MIN_FRAC1 [MIN_FRAC3]]
        disparity from the left depth map (d = fx B / Z) against OpenCV's
        StereoSGBM on the rectified pair: the fraction of pixels (both valid)
        within 1 px and 3 px is at least MIN_FRAC1 / MIN_FRAC3.
    examples_check.py depth NAME OUTDIR
        every OUTDIR/*/depth_000000.pfm has finite depth, no NaN, and the
        image is not blank.
"""
import glob
import os
import sys

import cv2
import numpy as np


def ok(name):
    print("ok " + name, flush=True)


def fail(name, why):
    print("FAIL %s: %s" % (name, why), flush=True)


def read_cam(path):
    c = {}
    for line in open(path):
        line = line.split("#", 1)[0].split()
        if line:
            c[line[0]] = [float(x) for x in line[1:]]
    K = np.array([[c["fx"][0], c.get("skew", [0])[0], c["cx"][0]], [0, c["fy"][0], c["cy"][0]], [0, 0, 1]])
    return K, np.array(c["R"]).reshape(3, 3), np.array(c["T"]), (int(c["width"][0]), int(c["height"][0]))


def project(K, R, T, P):
    """spec/camera.md: Pc = R P + T, (u, v, 1) ~ K Pc."""
    Pc = P @ R.T + T
    uv = Pc @ K.T
    return uv[:, :2] / uv[:, 2:]


def read_pfm(path):
    with open(path, "rb") as fh:
        data = fh.read()
    parts = data.split(b"\n", 3)
    w, h = (int(x) for x in parts[1].split())
    scale = float(parts[2])
    a = np.frombuffer(parts[3], dtype="<f4" if scale < 0 else ">f4").reshape(h, w)
    return a[::-1]  # PFM rows run bottom to top


def calib(camdir, outdir, max_px=0.1):
    cols, rows, s = 9, 6, 0.025
    obj = np.array([(i * s, j * s, 0.0) for j in range(rows) for i in range(cols)])
    cams = sorted(glob.glob(os.path.join(camdir, "view*.cam")))
    errs, objpts, imgpts, size, Ks, proj_diff = [], [], [], None, [], 0.0
    missing = []
    for cam in cams:
        name = os.path.basename(cam)[:-4]
        K, R, T, size = read_cam(cam)
        Ks.append(K)
        want = project(K, R, T, obj)
        cvp, _ = cv2.projectPoints(obj.reshape(-1, 1, 3), cv2.Rodrigues(R)[0], T, K, np.zeros(5))
        proj_diff = max(proj_diff, float(np.abs(cvp.reshape(-1, 2) - want).max()))
        img = cv2.imread(os.path.join(outdir, name, "image_000000.png"), cv2.IMREAD_GRAYSCALE)
        if img is None:
            missing.append(name + " (no image)")
            continue
        found, corners = cv2.findChessboardCorners(img, (cols, rows))
        if not found or len(corners) != cols * rows:
            missing.append(name)
            continue
        corners = cv2.cornerSubPix(img, corners, (7, 7), (-1, -1),
                                   (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 100, 1e-6)).reshape(-1, 2)
        # match each stated corner to its nearest detection (one-to-one)
        d = np.linalg.norm(want[:, None, :] - corners[None, :, :], axis=2)
        nn = d.argmin(1)
        if len(set(nn.tolist())) != len(want):
            missing.append(name + " (ambiguous matching)")
            continue
        e = d[np.arange(len(want)), nn]
        errs.append(e)
        objpts.append(obj.astype(np.float32))
        imgpts.append(corners[nn].astype(np.float32).reshape(-1, 1, 2))
        print("# %s: %d corners, RMS %.4f px, max %.4f px" % (name, len(e), np.sqrt((e ** 2).mean()), e.max()))
    test = "examples_calibration_corners"
    if not cams:
        fail(test, "no view*.cam in " + camdir)
        return
    if proj_diff > 1e-6:
        fail("examples_calibration_projection", "own projection and cv2.projectPoints differ by %.3g px" % proj_diff)
    else:
        ok("examples_calibration_projection")
    if missing:
        fail(test, "no full 9x6 board found in %d of %d views: %s" % (len(missing), len(cams), " ".join(missing)))
        return
    e = np.concatenate(errs)
    rms, mx = float(np.sqrt((e ** 2).mean())), float(e.max())
    print("# chessboard corners, %d views, %d corners: RMS %.4f px, max %.4f px (limit %g)"
          % (len(errs), len(e), rms, mx, max_px))
    if rms > max_px or mx > max_px:
        fail(test, "refined corners vs projected corners: RMS %.4f px, max %.4f px > %g px" % (rms, mx, max_px))
    else:
        ok(test)
    # calibration recovers the intrinsics
    test = "examples_calibration_recovery"
    K0 = Ks[0]
    if any(np.abs(K - K0).max() > 0 for K in Ks):
        fail(test, "views have different K")
        return
    truth = (K0[0, 0], K0[1, 1], K0[0, 2], K0[1, 2])
    nodist = cv2.CALIB_ZERO_TANGENT_DIST | cv2.CALIB_FIX_K1 | cv2.CALIB_FIX_K2 | cv2.CALIB_FIX_K3
    why = []
    for what, flags in (("5 distortion terms free", 0), ("no distortion (k1 k2 k3 p1 p2 fixed at 0)", nodist)):
        rep, K, dist, _, _ = cv2.calibrateCamera(objpts, imgpts, size, None, None, flags=flags)
        got = (K[0, 0], K[1, 1], K[0, 2], K[1, 2])
        print("# calibrateCamera, %d views, %s: reprojection RMS %.4f px" % (len(objpts), what, rep))
        for n, t, g in zip(("fx", "fy", "cx", "cy"), truth, got):
            print("#   %s %.3f (truth %.3f, error %+.3f)" % (n, g, t, g - t))
        print("#   distortion k1 k2 p1 p2 k3: %s (truth 0)" % " ".join("%.2g" % x for x in dist.ravel()))
        bad = [n for n, t, g in zip(("fx", "fy", "cx", "cy"), truth, got) if abs(g - t) > 1.0]
        if bad or rep > max_px:
            why.append("%s: %s off by more than 1 px, reprojection RMS %.4f" % (what, ",".join(bad) or "none", rep))
    if why:
        fail(test, "; ".join(why))
    else:
        ok(test)

def sgbm(camdir, outdir, min1=0.85, min3=0.9):
    test = "examples_dense_stereo_sgbm"
    KL, RL, TL, (W, H) = read_cam(os.path.join(camdir, "left.cam"))
    KR, RR, TR, _ = read_cam(os.path.join(camdir, "right.cam"))
    # rectified: identical K and R, centres apart along the camera x axis only
    CL, CR = -RL.T @ TL, -RR.T @ TR
    base = RL @ (CR - CL)          # right centre in the left camera frame
    if np.abs(KL - KR).max() > 0 or np.abs(RL - RR).max() > 0 or abs(base[1]) > 1e-12 or abs(base[2]) > 1e-12 \
            or base[0] <= 0:
        fail(test, "the pair is not rectified: K, R differ or baseline %s is not along +x" % base)
        return
    B, f = base[0], KL[0, 0]
    left = cv2.imread(os.path.join(outdir, "left", "image_000000.png"), cv2.IMREAD_GRAYSCALE)
    right = cv2.imread(os.path.join(outdir, "right", "image_000000.png"), cv2.IMREAD_GRAYSCALE)
    Z = read_pfm(os.path.join(outdir, "left", "depth_000000.pfm"))
    if left is None or right is None:
        fail(test, "missing images")
        return
    gt = f * B / Z                 # +inf depth -> 0 disparity: invalid below
    ndisp = int(np.ceil(np.nanmax(gt[np.isfinite(Z)]) / 16.0 + 1)) * 16
    bs = 5
    m = cv2.StereoSGBM_create(minDisparity=0, numDisparities=ndisp, blockSize=bs, P1=8 * bs * bs, P2=32 * bs * bs,
                              disp12MaxDiff=1, uniquenessRatio=10, speckleWindowSize=100, speckleRange=2,
                              mode=cv2.STEREO_SGBM_MODE_HH)
    disp = m.compute(left, right).astype(np.float64) / 16.0
    valid = np.isfinite(Z) & (gt > 0) & (disp >= 0)
    # SGBM leaves the leftmost ndisp columns undefined
    valid[:, :ndisp] = False
    err = np.abs(disp - gt)[valid]
    frac1, frac3 = float((err <= 1).mean()), float((err <= 3).mean())
    cover = valid.sum() / float((np.isfinite(Z)[:, ndisp:]).sum())
    print("# SGBM (blockSize %d, %d disparities) vs ground truth f B / Z (f %g px, B %g m, d %.1f..%.1f px): "
          "%d pixels valid in both (%.1f%% of the surface pixels right of column %d); within 1 px: %.4f, "
          "within 3 px: %.4f, median error %.3f px"
          % (bs, ndisp, f, B, gt[valid].min(), gt[valid].max(), valid.sum(), 100 * cover, ndisp, frac1, frac3,
             float(np.median(err))))
    if frac1 < min1 or frac3 < min3 or cover < 0.5:
        fail(test, "within 1 px %.4f (want >= %g), within 3 px %.4f (want >= %g), coverage %.2f"
             % (frac1, min1, frac3, min3, cover))
    else:
        ok(test)


def depth(name, outdir):
    test = "examples_render_" + name
    pfms = sorted(glob.glob(os.path.join(outdir, "*", "depth_000000.pfm")))
    if not pfms:
        fail(test, "no depth maps in " + outdir)
        return
    why = []
    for p in pfms:
        cam = os.path.basename(os.path.dirname(p))
        Z = read_pfm(p)
        fin = np.isfinite(Z)
        img = cv2.imread(os.path.join(os.path.dirname(p), "image_000000.png"))
        if np.isnan(Z).any():
            why.append(cam + ": NaN depth")
        elif fin.mean() < 0.05:
            why.append(cam + ": only %.1f%% finite depth" % (100 * fin.mean()))
        elif (Z[fin] <= 0).any():
            why.append(cam + ": depth <= 0")
        if img is None or img.std() < 5:
            why.append(cam + ": image missing or blank")
    if why:
        fail(test, "; ".join(why))
    else:
        ok(test)


if __name__ == "__main__":
    a = sys.argv[1:]
    if a and a[0] == "calib" and len(a) in (3, 4):
        calib(a[1], a[2], *(float(x) for x in a[3:]))
    elif a and a[0] == "sgbm" and len(a) in (3, 4, 5):
        sgbm(a[1], a[2], *(float(x) for x in a[3:]))
    elif a and a[0] == "depth" and len(a) == 3:
        depth(a[1], a[2])
    else:
        sys.exit(__doc__)
