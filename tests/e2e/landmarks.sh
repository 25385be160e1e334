#!/bin/sh
# Landmarks (issue 15): mark("name", x, y, z) compiled, dumped, linked
# through a library bundle, drawing nothing; glsplay --outputs landmarks
# checked against cv2.projectPoints and known occluders by
# tests/py/check_landmarks.py (spec/outputs.md "Landmarks").  The compile
# errors are tests/errors/mark_*.scene; the validator's test_mark_names.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh

mkdir -p "$t/src/lm" "$t/plain/lm" "$t/cams"
printf 'param h = 2;\nmark("foot", 0, 0, 0);\nmark("top", 0.25, h, -0.125);\ncolor(1, 0, 0);\npoly { vert(-1, 0, 0); vert(1, 0, 0); vert(0, h, 0); }\n' >"$t/src/lm/Post.scene"
printf 'mark("origin", 0, 0, 10);\npush; trans(0.5, 0, 10); rot(30, 0, 1, 0); call("lm.Post", h = 1.5); pop;\nrepeat(i, 0, 2) { push; trans(i - 1, 0.5, 12); call("lm.Post"); pop; }\n' >"$t/src/Top.scene"
# the same scene without its marks
grep -v '^mark' "$t/src/lm/Post.scene" >"$t/plain/lm/Post.scene"
grep -v '^mark' "$t/src/Top.scene" >"$t/plain/Top.scene"
"$BIN/glsc" -I "$t/src" -o "$t/top.glsb" "$t/src/Top.scene" 2>"$t/err" || { fail landmarks_compile "$(cat "$t/err")"; exit 0; }

# the dump: the counts line, and each mark as written
"$BIN/glsdis" "$t/top.glsb" >"$t/dis" 2>&1
if grep -qx 'features: marks' "$t/dis" && grep -qx 'marks: 5, landmark names: 3' "$t/dis" &&
    grep -qx '  mark "origin" 0 0 10' "$t/dis" && grep -qx '  mark "top" 0.25 1.5 -0.125' "$t/dis" &&
    [ "$(grep -c '^  mark "foot" 0 0 0$' "$t/dis")" -eq 2 ]; then
    ok landmarks_glsdis
else
    fail landmarks_glsdis "$(cat "$t/dis")"
fi

# linked through a library bundle: the same bundle, byte for byte
mkdir "$t/top" && cp "$t/src/Top.scene" "$t/top/"
linked_same landmarks_library_link "$t/src" "$t/top/Top.scene"

# marks draw nothing: the image is that of the scene without them
printf 'width 160\nheight 120\nfx 150\nfy 150\ncx 79.5\ncy 59.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n' >"$t/cams/c.cam"
"$BIN/glsc" -I "$t/plain" -o "$t/plain.glsb" "$t/plain/Top.scene" 2>"$t/err"
"$BIN/glsplay" "$t/top.glsb" --camera "$t/cams/c.cam" --outputs image,depth,landmarks -o "$t/o1" 2>"$t/err"
"$BIN/glsplay" "$t/plain.glsb" --camera "$t/cams/c.cam" --outputs image,depth -o "$t/o2" 2>>"$t/err"
if cmp -s "$t/o1/c/image_000000.png" "$t/o2/c/image_000000.png" && cmp -s "$t/o1/c/depth_000000.pfm" "$t/o2/c/depth_000000.pfm" &&
    [ "$(wc -l <"$t/o1/c/landmarks_000000.csv")" -eq 8 ]; then
    ok landmarks_draw_nothing
else
    fail landmarks_draw_nothing "images or depth differ, or no 8-line CSV: $(cat "$t/err")"
fi
# the frame record names the output, so --resume redoes a frame without it
if grep -q '^outputs image depth landmarks$' "$t/o1/c/.frame_000000.done"; then
    ok landmarks_frame_record
else
    fail landmarks_frame_record "$(cat "$t/o1/c/.frame_000000.done")"
fi
# far from the camera (the tolerance is relative to the depth, 1e-4 Zc,
# runtime/truth/gt_landmarks.c): a wall 100 units away, a mark 0.005 behind it
# visible (within 0.01), one 0.02 behind hidden; an absolute 1e-4 would hide both
mkdir "$t/far"
printf 'mark("just.behind", 0, 0, 100.005);\nmark("well.behind", 0, 0, 100.02);\ncolor(0.5, 0.5, 0.5);\npoly { vert(-50, -50, 100); vert(50, -50, 100); vert(50, 50, 100); vert(-50, 50, 100); }\n' >"$t/far/Wall.scene"
printf 'width 160\nheight 120\nfx 150\nfy 150\ncx 79.5\ncy 59.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 200\n' >"$t/cams/far.cam"
"$BIN/glsc" -o "$t/far.glsb" "$t/far/Wall.scene" 2>"$t/err" &&
    "$BIN/glsplay" "$t/far.glsb" --camera "$t/cams/far.cam" --outputs landmarks -o "$t/o4" 2>>"$t/err"
vis=$(cut -d, -f1,10 "$t/o4/far/landmarks_000000.csv" 2>/dev/null | tr '\n' ' ')
if [ "$vis" = "name,visible just.behind,1 well.behind,0 " ]; then
    ok landmarks_far_tolerance
else
    fail landmarks_far_tolerance "name,visible: '$vis' (want just.behind 1, well.behind 0): $(cat "$t/err")"
fi
# --explain: what it costs
"$BIN/glsplay" "$t/top.glsb" --camera "$t/cams/c.cam" --outputs image,landmarks --aa 4 --explain >"$t/plan" 2>&1
if grep -qx '  writes: landmarks (CSV, 7 per frame): the centre pass'"'"'s depth, one extra unjittered pass (--aa)' "$t/plan"; then
    ok landmarks_explain
else
    fail landmarks_explain "$(grep landmarks "$t/plan")"
fi
# an unknown output word
"$BIN/glsplay" "$t/top.glsb" --camera "$t/cams/c.cam" --outputs image,landmark -o "$t/o3" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(cat "$t/err")" = "glsplay: error: --outputs takes a comma-separated list of: image, depth, points, edges, disparity, disparity16, depth16, landmarks, instance, class, coco, normals, flow, boxes, coverage, edge_segments (not 'landmark'); did you mean 'landmarks'? (try glsplay --help)" ]; then
    ok landmarks_usage
else
    fail landmarks_usage "exit $rc: $(cat "$t/err")"
fi

# the road example (spec/road.md "Landmarks"): glsroad marks each dash's
# corners at its band's corner vertices, trees and its car carry marks,
# and examples/road/render.sh writes landmarks; near dashes' visible
# corners are within 2 px of painted pixels (at least half paint)
if ROAD_FRAMES=0 ROAD_CLIP=200:201 sh examples/road/render.sh "$BIN" "$t/road" >"$t/road.log" 2>&1; then
    sc="$t/road/road/road.scene"
    nd=$(grep -c '^mark("b[0-9]*\.dash[0-9]*\.\(begin\|end\)\.\(left\|right\)", ' "$sc")
    missing=$(sed -n 's/^mark("b[0-9]*\.dash[0-9]*\.[a-z]*\.[a-z]*", \(.*\));$/vert(\1);/p' "$sc" | while read -r v; do
        grep -qF "$v" "$sc" || echo "$v"; done | head -3)
    if [ "$nd" -gt 0 ] && [ $((nd % 4)) -eq 0 ] && [ -z "$missing" ] &&
        grep -qx 'mark("top", 0, 7, 0);' "$t/road/road/roadobj/Tree.scene" &&
        grep -qx 'mark("front.left", 0.9, 0, 2.2);' "$t/road/road/roadobj/Car.scene"; then
        ok landmarks_road_scene
    else
        fail landmarks_road_scene "$nd dash corners; not at a band vertex: $missing"
    fi
    if [ -f "$t/road/left/landmarks_000000.csv" ] && [ -f "$t/road/right/landmarks_000000.csv" ] &&
        $PY - "$t/road/left" <<'PY'
import csv, sys
import cv2
import numpy as np
d = sys.argv[1]
im = cv2.imread(d + "/image_000000.png")
rows = list(csv.DictReader(open(d + "/landmarks_000000.csv", newline="")))
near = [r for r in rows if ".dash" in r["name"] and r["visible"] == "1" and float(r["depth"]) < 40]
bad = []
for r in near:
    i, j = int(np.floor(float(r["u"]) + 0.5)), int(np.floor(float(r["v"]) + 0.5))
    # a painted pixel: at least half paint (asphalt about 80, paint 230;
    # exact coverage, the default, blends a dash a pixel wide at 36 m)
    if im[max(j - 2, 0):j + 3, max(i - 2, 0):i + 3].min(axis=2).max() < 155:
        bad.append(r["name"])
trees = [r for r in rows if "roadobj.Tree#" in r["path"]]
if len(near) < 8 or bad or not trees:
    print("  %d near visible dash corners, %d not on a painted pixel: %s; %d tree marks" % (len(near), len(bad), bad[:3], len(trees)))
    sys.exit(1)
PY
    then
        ok landmarks_road_example
    else
        fail landmarks_road_example "see above"
    fi
    # glsroad's own objects give their class: the road clip's instances of
    # roadobj.Tree are of class Tree (not their package, roadobj)
    if grep -qx 'class("Tree");' "$t/road/road/roadobj/Tree.scene" &&
        grep -qx 'class("Car");' "$t/road/road/roadobj/Car.scene" &&
        $PY - "$t/road/clip/left/instances_000200.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
trees = [i for i in d["instances"] if i["object"].startswith("roadobj.Tree")]
sys.exit(0 if trees and all(i["class"] == "Tree" for i in trees) else 1)
PY
    then
        ok road_objects_classes
    else
        fail road_objects_classes "roadobj scenes without class lines, or a tree of another class in instances_000200.json"
    fi
else
    fail landmarks_road_example "render.sh failed: $(tail -3 "$t/road.log")"
fi

if $PY -c 'import cv2, numpy' 2>/dev/null; then
    mkdir "$t/py"
    $PY tests/py/check_landmarks.py "$BIN" "$t/py" || fail landmarks_check "check_landmarks.py exited with status $?"
else
    fail landmarks_check "no cv2 and numpy under $PY"
fi
