#!/bin/sh
# glsplay's ground-truth outputs (spec/outputs.md "Instances and classes",
# "Normals"): instance, class, coco and normals read back with cv2, json and
# numpy against footprints and normals computed in tests/py/check_gt.py;
# the refusal of more instances than a 16-bit image holds.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
py_check gt_check check_gt.py "$BIN" "$t"

# More instances that draw something than a 16-bit image has ids: refused
# before anything is rendered or created; 65535 are accepted.
mkdir -p "$t/many/pkg"
printf 'poly { vert(0, 0, 0); vert(1, 0, 0); vert(0, 1, 0); }\n' >"$t/many/pkg/Tri.scene"
for n in 65535 65536; do
    printf 'repeat(i, 0, %s) { push; trans(i, 0, 10); call("pkg.Tri"); pop; }\n' $n >"$t/many/Many$n.scene"
    "$BIN/glsc" -I "$t/many" -o "$t/many$n.glsb" Many$n 2>"$t/err" || { fail gt_refuse_setup "$(cat "$t/err")"; exit 0; }
done
printf 'width 8\nheight 6\nfx 8\nfy 8\ncx 3.5\ncy 2.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n' >"$t/c.cam"
"$BIN/glsplay" "$t/many65536.glsb" --camera "$t/c.cam" --outputs image,class -o "$t/refused" >/dev/null 2>"$t/err"
rc=$?
want="glsplay: error: $t/many65536.glsb: 65536 instances draw something, more than the 65535 ids of the 16-bit instance image (--outputs instance, class, coco)"
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "$want" ] && [ ! -e "$t/refused" ]; then
    ok gt_refuse_65536_instances
else
    fail gt_refuse_65536_instances "exit $rc: $(cat "$t/err")"
fi
if "$BIN/glsplay" "$t/many65535.glsb" --camera "$t/c.cam" --outputs instance --explain >/dev/null 2>"$t/err"; then
    ok gt_accept_65535_instances
else
    fail gt_accept_65535_instances "$(cat "$t/err")"
fi
# an unknown word names every output there is
"$BIN/glsplay" "$t/many65535.glsb" --camera "$t/c.cam" --outputs image,instanse -o "$t/u" >/dev/null 2>"$t/err"
rc=$?
want="glsplay: error: --outputs takes a comma-separated list of: image, depth, points, edges, disparity, disparity16, depth16, landmarks, instance, class, coco, normals, flow, boxes, coverage, edge_segments (not 'instanse'); did you mean 'instance'? (try glsplay --help)"
if [ $rc -eq 2 ] && [ "$(cat "$t/err")" = "$want" ]; then
    ok gt_outputs_usage
else
    fail gt_outputs_usage "exit $rc: $(cat "$t/err")"
fi

# normals is a float output: --float-format npy writes normals_F.npy,
# (H, W, 3) float32, equal bit for bit to the PFM (read by cv2 as BGR)
printf 'poly { vert(-1, -1, 5); vert(1, -1, 6); vert(0, 1, 5.5); }\n' >"$t/many/Tilt.scene"
"$BIN/glsc" -I "$t/many" -o "$t/tilt.glsb" Tilt 2>"$t/err" || fail normals_npy_setup "$(cat "$t/err")"
for f in pfm npy; do
    "$BIN/glsplay" "$t/tilt.glsb" --camera "$t/c.cam" --outputs normals --float-format $f -o "$t/n$f" 2>"$t/err" ||
        fail normals_npy "glsplay --float-format $f: $(cat "$t/err")"
done
if $PY - "$t/npfm/c/normals_000000.pfm" "$t/nnpy/c/normals_000000.npy" <<'PYEOF'; then
import sys, cv2, numpy as np
p = cv2.imread(sys.argv[1], cv2.IMREAD_UNCHANGED)[:, :, ::-1]
n = np.load(sys.argv[2], allow_pickle=False)
ok = n.dtype == np.float32 and n.shape == (6, 8, 3) and np.array_equal(p, n) and np.abs(n).max() > 0
sys.exit(0 if ok else 1)
PYEOF
    ok normals_npy_equals_pfm
else
    fail normals_npy_equals_pfm "normals_000000.npy differs from the PFM or is not (6, 8, 3) float32"
fi
