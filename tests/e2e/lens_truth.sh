#!/bin/sh
# Ground truth through a lens (spec/outputs.md "Through a lens"): instance
# ids, normals and landmarks of a distorted camera (tests/py/check_lens_truth.py,
# against cv2), and the outputs refused with a lens, asserted verbatim.
# Prints "ok NAME" / "FAIL NAME: why".
BIN=${GLS_BIN:-build}
PY=/usr/bin/python3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if $PY -c 'import cv2, numpy' 2>/dev/null; then
    $PY tests/py/check_lens_truth.py "$BIN" "$t/py" || echo "FAIL lens_truth: check_lens_truth.py exited with status $?"
else
    echo "FAIL lens_truth: no cv2 and numpy under $PY"
fi
printf 'poly { vert(-1, -1, 5); vert(1, -1, 5); vert(0, 1, 5); }\n' >"$t/Tri.scene"
"$BIN/glsc" -I "$t" -o "$t/tri.glsb" Tri 2>"$t/err" || echo "FAIL lens_refuse_setup: $(cat "$t/err")"
printf 'width 64\nheight 48\nfx 60\nfy 60\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\ndistortion -0.2 0.01 0 0\n' >"$t/lens.cam"
printf 'width 64\nheight 48\nfx 60\nfy 60\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT -0.1 0 0\nnear 0.1\nfar 100\ndistortion -0.2 0.01 0 0\n' >"$t/lens_r.cam"
printf '# frame R T\n0 1 0 0 0 1 0 0 0 1 0 0 0\n1 1 0 0 0 1 0 0 0 1 0 0 0.1\n' >"$t/traj.txt"
refused() { # NAME WORD WHY ARGS...
    name=$1 word=$2 why=$3
    shift 3
    "$BIN/glsplay" "$t/tri.glsb" "$@" -o "$t/out_$name" >/dev/null 2>"$t/err"
    rc=$?
    want="glsplay: error: $t/lens.cam: --outputs $word needs a camera without lens distortion: $why"
    if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "$want" ] && [ ! -e "$t/out_$name" ]; then
        echo "ok $name"
    else
        echo "FAIL $name: exit $rc: $(cat "$t/err")"
    fi
}
refused lens_refuses_disparity disparity "a rectified pair has no lens distortion" \
    --camera "$t/lens.cam" --camera "$t/lens_r.cam" --outputs disparity
cp "$t/lens.cam" "$t/rig/lens.cam" 2>/dev/null || { mkdir "$t/rig" && cp "$t/lens.cam" "$t/rig/lens.cam"; }
echo 'pose rig' >>"$t/rig/lens.cam"
"$BIN/glsplay" "$t/tri.glsb" --camera "$t/rig/lens.cam" --trajectory "$t/traj.txt" --outputs flow -o "$t/out_flow" \
    >/dev/null 2>"$t/err"
rc=$?
want="glsplay: error: $t/rig/lens.cam: --outputs flow needs a camera without lens distortion: flow is not made through a lens yet"
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "$want" ] && [ ! -e "$t/out_flow" ]; then
    echo "ok lens_refuses_flow"
else
    echo "FAIL lens_refuses_flow: exit $rc: $(cat "$t/err")"
fi
refused lens_refuses_boxes boxes "boxes are not made through a lens yet" --camera "$t/lens.cam" --outputs boxes
