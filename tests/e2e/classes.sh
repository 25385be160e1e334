#!/bin/sh
# class("name") (spec/language.md 7, spec/outputs.md "Classes"): an
# object's declared class names its instances in instances_F.json, the
# class image's ids, coco's categories and the KITTI boxes' type; an
# object without one gets its nearest caller's, else its package; a
# specialised object its template's; a library keeps them; glsdis prints
# them.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
mkdir -p "$t/cls"
# Car: declared, its geometry a called box (the box's instance is the car's)
printf 'class("Car");\ncall("objects.BoxRed");\n' >"$t/cls/Car.scene"
# Tree: no class, draws its own quad: its package, cls
printf 'poly { col(0.1, 0.6, 0.2); vert(-0.5, 0, 0); vert(0.5, 0, 0); vert(0.5, 1, 0); vert(-0.5, 1, 0); }\n' \
    >"$t/cls/Tree.scene"
# Sign: a template; its specialisation cls.Sign(h=0.8) keeps the class
printf 'param h = 1;\nclass("Sign");\nscale(0.3, h, 0.3);\ncall("objects.BoxYellow");\n' >"$t/cls/Sign.scene"
# Rider: Cyclist, its frame a called box; its Person gives its own class
printf 'class("Pedestrian");\npoly { col(0.9, 0.7, 0.6); vert(-0.2, 0, 0); vert(0.2, 0, 0); vert(0, 1, 0); }\n' \
    >"$t/cls/Person.scene"
printf 'class("Cyclist");\npush; scale(0.8, 0.5, 0.2); call("objects.BoxBlue"); pop;\ntrans(0, -1.1, 0);\ncall("cls.Person");\n' \
    >"$t/cls/Rider.scene"
cat >"$t/Top.scene" <<'SCENE'
push; trans(-1.5, 0, 6); call("cls.Car"); pop;
push; trans(0, 0, 6); call("cls.Tree"); pop;
push; trans(1.5, 0, 6); call("cls.Sign", h = 0.8); pop;
push; trans(0, -1.5, 8); call("cls.Car"); pop;
push; trans(-2, -1, 9); call("cls.Rider"); pop;
SCENE
printf 'pose world\nwidth 160\nheight 120\nfx 150\nfy 150\ncx 79.5\ncy 59.5\nR 1 0 0  0 1 0  0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n' \
    >"$t/cam.cam"
"$B/glsc" -I "$t" -I "$B/scenelib.glsb" -o "$t/b.glsb" "$t/Top.scene" 2>"$t/err" ||
    { fail classes_compile "$(cat "$t/err")"; exit 0; }

"$B/glsdis" "$t/b.glsb" >"$t/dis"
if grep -qx 'classes: 4 objects, 4 classes' "$t/dis" && grep -A1 -x 'object cls.Car' "$t/dis" | grep -qx '  class "Car"' &&
    grep -A1 -x 'object cls.Sign(h=0.8)' "$t/dis" | grep -qx '  class "Sign"' && ! grep -q '^marks:' "$t/dis"; then
    ok classes_glsdis
else
    fail classes_glsdis "$(grep -n 'class' "$t/dis")"
fi

"$B/glsplay" "$t/b.glsb" --camera "$t/cam.cam" --outputs image,instance,class,coco,boxes -o "$t/o" 2>"$t/err" ||
    { fail classes_render "$(cat "$t/err")"; exit 0; }
$PY - "$t/o/cam" <<'PYCHECK'
import json, sys
import cv2
import numpy as np
d = sys.argv[1]
want = {  # call path prefix -> class
    "Top > cls.Car#1 >": "Car", "Top > cls.Car#2 >": "Car", "Top > cls.Tree#1": "cls",
    "Top > cls.Sign(h=0.8)#1 >": "Sign", "Top > cls.Rider#1 > objects.BoxBlue#1": "Cyclist",
    "Top > cls.Rider#1 > cls.Person#1": "Pedestrian"}
fails = 0
def result(name, good, why):
    global fails
    print("ok " + name if good else "FAIL %s: %s" % (name, why))
    fails += not good
js = json.load(open(d + "/instances_000000.json"))
inst = js["instances"]
got = {}
for i in inst:
    hits = [p for p in want if i["path"].startswith(p)]
    got[hits[0] if len(hits) == 1 else i["path"]] = i["class"]
result("classes_instances_json", got == want, "%r" % got)
names = sorted(set(want.values()))
table = {c["id"]: c["name"] for c in js["classes"]}
result("classes_table_sorted", table == {k + 1: n for k, n in enumerate(names)}, "%r" % table)
result("classes_ids", all(table[i["class_id"]] == i["class"] for i in inst), "%r" % inst)
# the class image: each instance's pixels carry its class id
ii = cv2.imread(d + "/instance_000000.png", cv2.IMREAD_UNCHANGED)
ci = cv2.imread(d + "/class_000000.png", cv2.IMREAD_UNCHANGED)
good = all(i["pixels"] > 0 and (ci[ii == i["id"]] == i["class_id"]).all() for i in inst)
result("classes_png", good and (ci[ii == 0] == 0).all(), "class ids do not follow the instances")
coco = json.load(open(d + "/coco_000000.json"))
cats = {c["id"]: c["name"] for c in coco["categories"]}
cid = {a["id"]: a["category_id"] for a in coco["annotations"]}
expect = {k + 1: n for k, n in enumerate(names)}
result("classes_coco", cats == expect and all(cid[i["id"]] == i["class_id"] for i in inst), "%r %r" % (cats, cid))
# KITTI labels: the type is the class; the JSON's boxes in the same order
rows = [l.split()[0] for l in open(d + "/boxes_000000.txt")]
bj = json.load(open(d + "/boxes_000000.json"))["boxes"]
bycls = {i["id"]: i["class"] for i in inst}
result("classes_kitti_type", len(rows) == len(bj) == len(inst) and
       sorted(rows) == sorted(bycls.values()) == sorted(want.values()) and all(b["class"] == r for b, r in zip(bj, rows)),
       "%r / %r" % (rows, [b["class"] for b in bj]))
sys.exit(0)
PYCHECK

# a library keeps the classes: the same classes from the library bundle
BIN=$(cd "$B" && pwd)
(cd "$t" && "$BIN/glsc" --lib . -I "$BIN/scenelib.glsb" -o "$t/lib.glsb") 2>"$t/lerr" ||
    fail classes_library "$(cat "$t/lerr")"
printf 'call("cls.Car");\n' >"$t/Once.scene"
if "$B/glsc" -I "$t/lib.glsb" -I "$B/scenelib.glsb" -o "$t/once.glsb" "$t/Once.scene" 2>"$t/oerr" &&
    "$B/glsdis" "$t/once.glsb" | grep -A1 -x 'object cls.Car' | grep -qx '  class "Car"'; then
    ok classes_library_kept
else
    fail classes_library_kept "$(cat "$t/oerr")"
fi

# the scene library's classes: every part of a Sedan is a Car (its wheels
# and body give none), a Stop sign's post is a Sign, a Van a Van
printf 'push; trans(-2.5, 0, 14); rot(90, 0, 1, 0); call("road.vehicles.Sedan"); pop;\npush; trans(2, 0, 12); call("road.signs.Stop"); pop;\npush; trans(5, 0, 20); call("road.vehicles.Van"); pop;\n' \
    >"$t/Lib.scene"
sed 's/^T 0 0 0/T 0 -1.5 0/' "$t/cam.cam" >"$t/lib.cam"
"$B/glsc" -I "$B/scenelib.glsb" -o "$t/lib2.glsb" "$t/Lib.scene" 2>"$t/err" &&
    "$B/glsplay" "$t/lib2.glsb" --camera "$t/lib.cam" --outputs instance -o "$t/l" 2>>"$t/err" ||
    fail classes_scenelib "$(cat "$t/err")"
$PY - "$t/l/lib/instances_000000.json" <<'PYCHECK'
import json, sys
inst = json.load(open(sys.argv[1]))["instances"]
want = {"road.vehicles.Sedan": "Car", "road.signs.Stop": "Sign", "road.vehicles.Van": "Van"}
got = {}
for i in inst:
    top = i["path"].split(" > ")[1].split("#")[0]
    got.setdefault(top, set()).add(i["class"])
good = {k: {v} for k, v in want.items()} == got and len(inst) > 3
print("ok classes_scenelib" if good else "FAIL classes_scenelib: %r" % got)
PYCHECK
