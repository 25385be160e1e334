#!/bin/sh
# glsplay --outputs boxes (spec/outputs.md "Boxes"): two boxes at known
# placements, one partly hiding the other, which crosses the image's edge;
# tests/py/check_boxes.py compares boxes_F.txt (KITTI labels, field by
# field) and boxes_F.json with numpy's corners, projections and pixel
# coverage.  Here: --aa changes nothing, --explain.  Prints "ok NAME" /
# "FAIL NAME: why".
. tests/e2e/lib.sh
$PY tests/py/check_boxes.py write "$t" || { fail boxes_scene "cannot write the scene"; exit 0; }
"$B/glsc" -I "$B/scenelib.glsb" -o "$t/b.glsb" "$t/Boxes.scene" 2>"$t/err" || { fail boxes_compile "$(cat "$t/err")"; exit 0; }
PLAY="$B/glsplay $t/b.glsb --camera $t/cam.cam"
$PLAY --outputs image,boxes -o "$t/o" 2>"$t/err" || fail boxes_render "$(cat "$t/err")"
$PY tests/py/check_boxes.py check "$t/o"
# ground truth is never blended: the same files with --aa
$PLAY --outputs image,boxes --aa 3 -o "$t/aa" 2>"$t/err" || fail boxes_render_aa "$(cat "$t/err")"
if cmp -s "$t/o/cam/boxes_000000.txt" "$t/aa/cam/boxes_000000.txt" &&
    cmp -s "$t/o/cam/boxes_000000.json" "$t/aa/cam/boxes_000000.json"; then
    ok boxes_same_with_aa
else
    fail boxes_same_with_aa "boxes files differ with --aa 3"
fi
# deterministic: the same bytes again
$PLAY --outputs boxes -o "$t/again" 2>/dev/null
cmp -s "$t/o/cam/boxes_000000.json" "$t/again/cam/boxes_000000.json" && ok boxes_deterministic ||
    fail boxes_deterministic "two runs differ"
$PLAY --outputs boxes --explain >"$t/plan" 2>&1
grep -q "^  boxes: the ground-truth pass's instance ids and one pass per visible instance drawn alone" \
    "$t/plan" && ok boxes_explain || fail boxes_explain "$(tail -2 "$t/plan")"
# a camera 3 m along z looking straight down at the floor (the top object's own
# geometry, which gets no box): an empty label file and "boxes": [] (the
# floor is there: its depth)
sed 's/^R 1 0 0  0 1 0  0 0 1/R 1 0 0  0 0 -1  0 1 0/; s/^T 0 0 0/T 0 3 0/' "$t/cam.cam" >"$t/down.cam"
"$B/glsplay" "$t/b.glsb" --camera "$t/down.cam" --outputs depth,boxes -o "$t/e" 2>"$t/err"
if [ -f "$t/e/down/boxes_000000.txt" ] && [ ! -s "$t/e/down/boxes_000000.txt" ] &&
    $PY -c "import cv2,json,numpy,sys; z = cv2.imread('$t/e/down/depth_000000.pfm', cv2.IMREAD_UNCHANGED)
sys.exit(int(json.load(open('$t/e/down/boxes_000000.json'))['boxes'] != [] or numpy.isfinite(z).sum() < 1000))"; then
    ok boxes_none_empty
else
    fail boxes_none_empty "$(cat "$t/err") $(cat "$t/e/down/boxes_000000.json")"
fi
# a camera's name is its file name, quotes and backslashes included: the
# JSON stays JSON (names are quoted, not pasted)
cp "$t/cam.cam" "$t/we\"ird\\cam.cam"
"$B/glsplay" "$t/b.glsb" --camera "$t/we\"ird\\cam.cam" --outputs boxes -o "$t/q" 2>"$t/err" ||
    fail boxes_json_quoted_camera "$(cat "$t/err")"
if $PY -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["camera"] == sys.argv[2] and d["boxes"] else 1)' \
    "$t/q/we\"ird\\cam/boxes_000000.json" "we\"ird\\cam"; then
    ok boxes_json_quoted_camera
else
    fail boxes_json_quoted_camera "boxes_000000.json does not parse or names another camera"
fi
