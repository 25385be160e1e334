#!/bin/sh
# glsplay's disparity, disparity16, depth16 and --float-format npy outputs
# (spec/outputs.md "Disparity and 16-bit depth", "Float outputs"): values
# against geometry computed in numpy (tests/py/check_disparity.py), the
# refusals (a rig that is not rectified, a value a 16-bit PNG cannot hold)
# verbatim, and --resume against the new settings.  Prints ok/FAIL lines.
. tests/e2e/lib.sh
PLAY=$B/glsplay
CHECK=tests/py/check_disparity.py
[ -x "$PLAY" ] || { fail outputs_disparity "no $PLAY"; exit 0; }
need_cv2 outputs_disparity

# The scene: a wall x in [-3, 3], y in [-4, 1] at z = 10 and a ground y = 1,
# z in [2, 10], x in [-3, 3] (the sky around them has no surface).
mkdir -p "$t/s"
cat >"$t/s/Wall.scene" <<'SCENE'
color(0.8, 0.3, 0.2);
poly { vert(-3, -4, 10); vert(3, -4, 10); vert(3, 1, 10); vert(-3, 1, 10); }
color(0.2, 0.6, 0.3);
poly { vert(-3, 1, 2); vert(3, 1, 2); vert(3, 1, 10); vert(-3, 1, 10); }
SCENE
# a wall 0.15 in front of the camera: disparity 48 / 0.15 = 320 px
cat >"$t/s/Near.scene" <<'SCENE'
color(1, 1, 1);
poly { vert(-5, -5, 0.15); vert(5, -5, 0.15); vert(5, 5, 0.15); vert(-5, 5, 0.15); }
SCENE
"$B/glsc" -I "$t/s" -o "$t/wall.glsb" Wall && "$B/glsc" -I "$t/s" -o "$t/near.glsb" Near ||
    { fail outputs_disparity_setup "scenes do not compile"; exit 0; }

# rig 1: world axes, B = 0.4 (the right camera's centre at x = 0.4)
cam() { # cam FILE T [R] [extra lines]
    printf 'width 160\nheight 120\nfx 120\nfy 118\ncx 79.5\ncy 59.5\nR %s\nT %s\nnear 0.1\nfar 100\n%s' \
        "${3:-1 0 0 0 1 0 0 0 1}" "$2" "$4" >"$1"
}
mkdir -p "$t/r1" "$t/r2" "$t/bad"
cam "$t/r1/left.cam" "0 0 0"
cam "$t/r1/right.cam" "-0.4 0 0"
# rig 2: rotated, left centre (0.2, -0.3, -0.5), B = 0.35; T = -R C,
# written with every digit by numpy
$PY - "$t/r2" <<'PY'
import sys, numpy as np, cv2
R = cv2.Rodrigues(np.array([0.03, -0.08, 0.02]))[0]
Cl = np.array([0.2, -0.3, -0.5])
Cr = Cl + R.T @ np.array([0.35, 0, 0])
for name, C in (('left', Cl), ('right', Cr)):
    T = -R @ C
    with open('%s/%s.cam' % (sys.argv[1], name), 'w') as f:
        f.write('width 160\nheight 120\nfx 120\nfy 118\ncx 79.5\ncy 59.5\n')
        f.write('R ' + ' '.join(repr(float(x)) for x in R.ravel()) + '\n')
        f.write('T ' + ' '.join(repr(float(x)) for x in T) + '\nnear 0.1\nfar 100\n')
PY

# ---- values: closed form, reprojection, KITTI, depth16 ----------------------
if "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/o1" \
    --outputs image,depth,disparity,disparity16,depth16 2>"$t/err"; then
    ok disparity_renders
    $PY $CHECK closed "$t/o1" "$t/r1/left.cam" "$t/r1/right.cam"
    $PY $CHECK reproject "$t/o1" "$t/r1/left.cam" "$t/r1/right.cam" rig1
    $PY $CHECK kitti "$t/o1" left right
    $PY $CHECK depth16 "$t/o1" 256 left right
else
    fail disparity_renders "$(cat "$t/err")"
fi
# the anti-aliased image does not blend the disparity: the same bytes
"$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/o1aa" --aa 4 \
    --outputs image,disparity,disparity16 2>"$t/err"
cmp -s "$t/o1/left/disparity_000000.pfm" "$t/o1aa/left/disparity_000000.pfm" &&
    cmp -s "$t/o1/right/disparity16_000000.png" "$t/o1aa/right/disparity16_000000.png" &&
    ok disparity_centre_sample_under_aa || fail disparity_centre_sample_under_aa "--aa 4 changed the disparity: $(cat "$t/err")"
"$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/o1tum" --outputs depth,depth16 \
    --depth-scale tum 2>"$t/err" || fail depth16_tum_renders "$(cat "$t/err")"
$PY $CHECK depth16 "$t/o1tum" 5000 left right
"$PLAY" "$t/wall.glsb" -c "$t/r2/left.cam" -c "$t/r2/right.cam" -o "$t/o2" --outputs depth,disparity 2>"$t/err" ||
    fail disparity_rotated_rig_renders "$(cat "$t/err")"
$PY $CHECK reproject "$t/o2" "$t/r2/left.cam" "$t/r2/right.cam" rig2

# ---- .npy: the same floats as the PFM files ---------------------------------
if "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/pfm" --outputs image,depth,disparity \
    --image-format pfm 2>"$t/err" &&
    "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/npy" --outputs image,depth,disparity \
        --image-format pfm --float-format npy 2>"$t/err"; then
    ls "$t/npy/left" | tr '\n' ' ' >"$t/ls"
    [ "$(cat "$t/ls")" = "depth_000000.npy disparity_000000.npy image_000000.npy " ] && ok npy_file_names ||
        fail npy_file_names "$(cat "$t/ls")"
    $PY $CHECK npy "$t/pfm" "$t/npy" left depth 1
    $PY $CHECK npy "$t/pfm" "$t/npy" left disparity 1
    $PY $CHECK npy "$t/pfm" "$t/npy" left image 3
else
    fail npy_renders "$(cat "$t/err")"
fi
exact float_format_usage 2 "glsplay: error: --float-format takes one of: pfm, npy (not 'tiff') (try glsplay --help)" -- \
    "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -o "$t/x" --float-format tiff
exact depth_scale_usage 2 \
    "glsplay: error: --depth-scale needs a positive number, kitti (256) or tum (5000), got '0' (try glsplay --help)" -- \
    "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -o "$t/x" --depth-scale 0

# ---- overflow: refused, never clamped ---------------------------------------
exact disparity16_overflow 1 \
    "glsplay: error: disparity16: camera left, frame 0, pixel (0, 0): disparity 320 px is over 255.996 px, the most a KITTI 16-bit PNG holds (d * 256 <= 65535); use --outputs disparity (float) instead" -- \
    "$PLAY" "$t/near.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/ov" --outputs image,disparity16
# checked before any file of the frame is written: not even the image,
# and the directories the run made are taken back (nothing left behind)
[ ! -e "$t/ov" ] &&
    ok disparity16_overflow_writes_nothing || fail disparity16_overflow_writes_nothing "$(ls -RA "$t/ov")"
exact disparity_float_no_overflow 0 "" -- \
    "$PLAY" "$t/near.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/ov2" --outputs disparity
exact depth16_overflow 1 \
    "glsplay: error: depth16: camera left, frame 0, pixel (0, 0): depth 0.15 is over 0.065535, the largest a 16-bit PNG holds at --depth-scale 1000000 (65535 / 1000000); lower --depth-scale or use --outputs depth (float) instead" -- \
    "$PLAY" "$t/near.glsb" -c "$t/r1/left.cam" -o "$t/ov3" --outputs depth,depth16 --depth-scale 1000000
[ ! -e "$t/ov3" ] && ok depth16_overflow_writes_nothing ||
    fail depth16_overflow_writes_nothing "$(ls -RA "$t/ov3")"
exact depth16_rounds_to_zero 1 \
    "glsplay: error: depth16: camera left, frame 0, pixel (0, 0): depth 0.15 rounds to 0 at --depth-scale 1, which means no surface; raise --depth-scale or use --outputs depth (float) instead" -- \
    "$PLAY" "$t/near.glsb" -c "$t/r1/left.cam" -o "$t/ov4" --outputs depth16 --depth-scale 1

# ---- rigs that are not rectified: refused before anything is rendered -------
cp "$t/r1/left.cam" "$t/bad/left.cam"
# the count of cameras is on the command line: a usage error (exit 2,
# spec/exit_status.md); what the camera files say, an input error (exit 1)
refused() { # refused NAME MESSAGE CAMERA...
    what=$1 msg=$2
    shift 2
    set -- "$t/wall.glsb" $(for c in "$@"; do printf -- '-c %s ' "$t/$c"; done)
    case $msg in exactly*) st=2 hint=" (try glsplay --help)" ;; *) st=1 hint= ;; esac
    exact "disparity_refuses_$what" $st "glsplay: error: --outputs disparity needs a rectified pair: $msg$hint" -- \
        "$PLAY" "$@" -o "$t/no_$what" --outputs image,disparity
    [ ! -e "$t/no_$what" ] && ok "disparity_refuses_${what}_writes_nothing" ||
        fail "disparity_refuses_${what}_writes_nothing" "$(ls -R "$t/no_$what")"
}
refused one "exactly two cameras, the left one first; 1 given" r1/left.cam
cp "$t/r1/right.cam" "$t/bad/third.cam"
refused three "exactly two cameras, the left one first; 3 given" r1/left.cam r1/right.cam bad/third.cam
refused swapped "camera left is not to the right of camera right (its centre is at x = -0.4 in right's frame); give the left camera first" \
    r1/right.cam r1/left.cam
cam "$t/bad/turned.cam" "-0.4 0 0" "0.99875 0 0.049979 0 1 0 -0.049979 0 0.99875"
refused rotation "cameras left and turned have different rotations" bad/left.cam bad/turned.cam
cam "$t/bad/up.cam" "-0.4 0.1 0"
refused baseline_y "the baseline is not along x: camera up's centre is at (0.4, -0.1, 0) in camera left's frame" \
    bad/left.cam bad/up.cam
sed 's/^fx 120$/fx 121/' "$t/r1/right.cam" >"$t/bad/fx.cam"
refused intrinsics "cameras left and fx have different fx (120 and 121)" bad/left.cam bad/fx.cam
sed 's/^width 160$/width 162/' "$t/r1/right.cam" >"$t/bad/wide.cam"
refused size "cameras left and wide have different sizes (160x120 and 162x120)" bad/left.cam bad/wide.cam
exact disparity16_refuses_one 2 \
    "glsplay: error: --outputs disparity16 needs a rectified pair: exactly two cameras, the left one first; 1 given (try glsplay --help)" -- \
    "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -o "$t/no16" --outputs disparity16

# ---- a trajectory: the rig-relative cameras are checked ---------------------
mkdir -p "$t/rig" "$t/rigbad"
cam "$t/rig/left.cam" "0 0 0" "" "pose rig
"
cam "$t/rig/right.cam" "-0.4 0 0" "" "pose rig
"
cam "$t/rigbad/left.cam" "0 0 0" "" "pose rig
"
cam "$t/rigbad/right.cam" "-0.4 0 0.2" "" "pose rig
"
# the rig 1 unit forward per frame (T = -R C with R = I)
{ echo "# test trajectory"; for f in 0 1; do echo "$f $f 1 0 0 0 1 0 0 0 1 0 0 -$f"; done; } >"$t/traj.txt"
exact disparity_trajectory 0 "" -- "$PLAY" "$t/wall.glsb" -c "$t/rig/left.cam" -c "$t/rig/right.cam" \
    --trajectory "$t/traj.txt" -o "$t/seq" --outputs depth,disparity
$PY - "$t/seq" <<'PY'
import sys, numpy as np, cv2
ok = True
for f in (0, 1):
    z = cv2.imread('%s/left/depth_%06d.pfm' % (sys.argv[1], f), cv2.IMREAD_UNCHANGED)
    d = cv2.imread('%s/left/disparity_%06d.pfm' % (sys.argv[1], f), cv2.IMREAD_UNCHANGED)
    fin = np.isfinite(z)
    ok &= fin.any() and np.abs(d[fin] - 120 * 0.4 / z[fin].astype(np.float64)).max() < 1e-4 * d[fin].max()
print('ok disparity_trajectory_values' if ok else 'FAIL disparity_trajectory_values: d != fx B / Zc')
PY
exact disparity_trajectory_refuses 1 \
    "glsplay: error: --outputs disparity needs a rectified pair: the baseline is not along x: camera right's centre is at (0.4, 0, -0.2) in camera left's frame" -- \
    "$PLAY" "$t/wall.glsb" -c "$t/rigbad/left.cam" -c "$t/rigbad/right.cam" --trajectory "$t/traj.txt" \
    -o "$t/seqbad" --outputs disparity

# ---- --resume knows the new outputs and settings ----------------------------
resume() { "$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" -o "$t/res" --resume "$@" 2>&1 >/dev/null |
    grep -o '[0-9]* of 1 frame complete'; }
resume --outputs depth,disparity,depth16 >/dev/null
[ "$(resume --outputs depth,disparity,depth16)" = "1 of 1 frame complete" ] && ok resume_same_disparity_outputs ||
    fail resume_same_disparity_outputs "$(resume --outputs depth,disparity,depth16)"
[ "$(resume --outputs depth,disparity,depth16 --depth-scale tum)" = "0 of 1 frame complete" ] &&
    ok resume_other_depth_scale || fail resume_other_depth_scale "a depth16 at scale 256 was taken for scale 5000"
resume --outputs depth,disparity,depth16 >/dev/null
[ "$(resume --outputs depth,disparity,depth16 --float-format npy)" = "0 of 1 frame complete" ] &&
    ok resume_other_float_format || fail resume_other_float_format "PFM files were taken for .npy"
[ "$(resume --outputs depth,disparity,disparity16,depth16 --float-format npy)" = "0 of 1 frame complete" ] &&
    ok resume_other_outputs_disparity16 || fail resume_other_outputs_disparity16 "a frame without disparity16 was taken as complete"

# ---- --explain: what they cost -----------------------------------------------
"$PLAY" "$t/wall.glsb" -c "$t/r1/left.cam" -c "$t/r1/right.cam" --explain --outputs image,disparity,disparity16,depth16 \
    --aa 4 --depth-scale tum >"$t/plan" 2>&1
grep -qx "  writes: disparity (PFM, fx B / Zc) disparity16 (KITTI 16-bit PNG, d \* 256) depth16 (16-bit PNG, Zc \* 5000) from the unjittered centre pass's depth: no extra pass" "$t/plan" &&
    ok explain_disparity_cost || fail explain_disparity_cost "$(grep writes "$t/plan")"
