#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# Ground truth through a lens (spec/outputs.md "Through a lens"): instance
# ids, normals and landmarks of a distorted camera (tests/py/check_lens_truth.py,
# against cv2), flow and boxes (tests/py/check_lens_flow_boxes.py; with a
# rolling shutter, tests/py/check_lens_rolling.py), and the outputs refused
# with a lens, asserted verbatim.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
py_check lens_truth check_lens_truth.py "$BIN" "$t/py"
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
mkdir "$t/rig" && cp "$t/lens.cam" "$t/rig/lens.cam"
echo 'pose rig' >>"$t/rig/lens.cam"
# flow and boxes from a rolling shutter through a lens
# (tests/py/check_lens_rolling.py, against cv2 and a fixed point in numpy)
$PY tests/py/check_lens_rolling.py "$BIN" "$t/rl" ||
    echo "FAIL lens_rolling_flow_boxes: check_lens_rolling.py exited with status $?"
# flow and boxes through a lens (tests/py/check_lens_flow_boxes.py, against cv2)
$PY tests/py/check_lens_flow_boxes.py "$BIN" "$BIN/scenelib.glsb" "$t/fb" ||
    echo "FAIL lens_flow_boxes: check_lens_flow_boxes.py exited with status $?"
# ground truth is never blended: flow and boxes through the lens are the
# same files with --aa (tests/py/flow_scene.py's scene)
mkdir "$t/aa" && $PY tests/py/flow_scene.py "$t/aa" &&
    "$BIN/glsc" -I "$BIN/scenelib.glsb" -o "$t/aa/f.glsb" "$t/aa/Flow.scene" 2>"$t/err" &&
    { cat "$t/aa/cam.cam"; echo 'fisheye 0.05 -0.01 0.002 -0.0004'; } >"$t/aa/fish.cam" || echo "FAIL lens_aa_setup: $(cat "$t/err")"
for a in 1 3; do
    "$BIN/glsplay" "$t/aa/f.glsb" --camera "$t/aa/fish.cam" --trajectory "$t/aa/trajectory.txt" \
        --motion "mover=$t/aa/mover.txt" --outputs image,flow,boxes --aa $a -o "$t/aa/o$a" 2>/dev/null
done
same=1
for f in flow_000000.flo flow_000000.png flowmask_000000.png boxes_000000.json boxes_000001.txt; do
    [ -f "$t/aa/o1/fish/$f" ] && cmp -s "$t/aa/o1/fish/$f" "$t/aa/o3/fish/$f" || same=0
done
[ $same = 1 ] && echo "ok lens_flow_boxes_same_with_aa" || echo "FAIL lens_flow_boxes_same_with_aa: files differ or missing"
# --explain says how flow and boxes are made through the lens
"$BIN/glsplay" "$t/tri.glsb" --camera "$t/rig/lens.cam" --trajectory "$t/traj.txt" --outputs flow,boxes --explain \
    >"$t/plan" 2>&1
if grep -qx "  lens: flow: the depth of frame t+1 drawn by the fine camera and read at each pixel centre's ray; points projected by the Brown-Conrady model" "$t/plan" &&
    grep -qx "  lens: boxes: each instance drawn alone by the fine camera and read at each pixel centre's ray; truncated from 65 points an edge through the Brown-Conrady model" "$t/plan"; then
    echo "ok lens_flow_boxes_explain"
else
    echo "FAIL lens_flow_boxes_explain: $(grep 'lens' "$t/plan")"
fi
