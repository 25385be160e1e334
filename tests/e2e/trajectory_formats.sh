#!/bin/sh
# glsplay --trajectory in KITTI and TUM form (spec/road.md, "Trajectory
# file"): the road demo rendered along glsroad's own trajectory.txt, along
# its poses_tum.txt (the rig's camera-to-world poses, with times) and along
# a KITTI file written here from trajectory.txt by numpy (camera-to-world
# [R|c] rows in the world frame), must give the same images and depth.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh

"$B/glsroad" examples/road/demo.road -o "$t/road" >/dev/null 2>"$t/err" &&
    "$B/glsc" -I "$t/road" -I "$B/scenelib.glsb" -o "$t/r.glsb" "$t/road/road.scene" 2>>"$t/err" ||
    { fail traj_formats_setup "$(head -3 "$t/err")"; exit 0; }
# KITTI rows from the glsroad rows: Rw = R^T, c = -R^T T
"$PY" - "$t/road/trajectory.txt" "$t/kitti.txt" <<'PYEOF' || fail traj_formats_kitti_written "numpy"
import sys
import numpy as np
out = open(sys.argv[2], "w")
for line in open(sys.argv[1]):
    if line.startswith("#") or not line.strip():
        continue
    v = np.array([float(x) for x in line.split()])
    R = v[2:11].reshape(3, 3)
    T = v[11:14]
    P = np.hstack([R.T, (-R.T @ T).reshape(3, 1)])
    out.write(" ".join("%.17g" % x for x in P.ravel()) + "\n")
PYEOF
render() { # NAME TRAJECTORY (--aa 1: the poses are under test, not the anti-aliasing)
    "$B/glsplay" "$t/r.glsb" --camera examples/road/rig/left.cam --trajectory "$2" --frames 0:3 --aa 1 \
        --outputs image,depth -o "$t/$1" >/dev/null 2>"$t/err_$1" || fail "traj_formats_render_$1" "$(head -3 "$t/err_$1")"
}
render glsroad "$t/road/trajectory.txt"
render tum "$t/road/poses_tum.txt"
render kitti "$t/kitti.txt"
for f in tum kitti; do
    "$PY" - "$t/glsroad/left" "$t/$f/left" <<'PYEOF' >"$t/cmp_$f" 2>&1 && ok "traj_formats_$f" || fail "traj_formats_$f" "$(cat "$t/cmp_$f")"
import sys
import cv2
import numpy as np
a, b = sys.argv[1], sys.argv[2]
for k in range(3):
    ia = cv2.imread("%s/image_%06d.png" % (a, k), cv2.IMREAD_UNCHANGED)
    ib = cv2.imread("%s/image_%06d.png" % (b, k), cv2.IMREAD_UNCHANGED)
    da = cv2.imread("%s/depth_%06d.pfm" % (a, k), cv2.IMREAD_UNCHANGED)
    db = cv2.imread("%s/depth_%06d.pfm" % (b, k), cv2.IMREAD_UNCHANGED)
    if ia is None or ib is None or da is None or db is None:
        sys.exit("frame %d: missing output" % k)
    # poses round-trip through another form: at most float rounding, so
    # at most a few edge pixels may change
    diff = int((np.abs(ia.astype(int) - ib.astype(int)).max(axis=2) > 0).sum())
    fin = np.isfinite(da) & np.isfinite(db)
    if (np.isfinite(da) != np.isfinite(db)).sum() > 10 or diff > 10:
        sys.exit("frame %d: %d pixels differ, %d depth coverage" % (k, diff, (np.isfinite(da) != np.isfinite(db)).sum()))
    rel = float(np.max(np.abs(da[fin] - db[fin]) / da[fin])) if fin.any() else 0.0
    if rel > 1e-5:
        sys.exit("frame %d: depth differs by %g relative" % (k, rel))
PYEOF
done
# the format is told by the first line; a later line of another count is
# an error at that line
{ head -1 "$t/kitti.txt"; echo "0 1 2 3 0 0 0 1"; } >"$t/mixed.txt"
"$B/glsplay" "$t/r.glsb" --camera examples/road/rig/left.cam --trajectory "$t/mixed.txt" -o "$t/m" >/dev/null 2>"$t/err"
rc=$?
want="$t/mixed.txt:2: error: expected 12 values (KITTI, like the first line: [R|t] row-major), got 8"
if [ $rc -eq 1 ] && grep -qxF "$want" "$t/err"; then ok traj_formats_mixed_refused; else fail traj_formats_mixed_refused "rc=$rc $(cat "$t/err")"; fi
