#!/bin/sh
# A rolling shutter through a lens draws and reads, for each band of rows,
# only the fine rows its pixels read (runtime/distort_exposure.c,
# gls_distort_truth_bands; spec/outputs.md "Through a lens"): every output
# must be the same bytes as with each band drawing and reading the whole
# fine image (GLS_LENS_BANDS_WHOLE=1, the switch that exists for this test).
# Brown-Conrady and fisheye, the scene of tests/py/flow_scene.py (a moving
# box: ids, normals, flow, boxes), every output a lens allows.
# Prints "ok NAME" / "FAIL NAME: why".
BIN=${GLS_BIN:-build}
PY=/usr/bin/python3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if ! $PY tests/py/flow_scene.py "$t" 2>"$t/err" ||
    ! "$BIN/glsc" -I "$BIN/scenelib.glsb" -o "$t/f.glsb" "$t/Flow.scene" 2>>"$t/err"; then
    echo "FAIL lens_bands_setup: $(cat "$t/err")"
    exit 0
fi
# the scene's camera at 160x120, each row read 1/120 of a frame after the
# one above
sed -e 's/^width .*/width 160/' -e 's/^height .*/height 120/' -e 's/^fx .*/fx 150/' -e 's/^fy .*/fy 150/' \
    -e 's/^cx .*/cx 79.5/' -e 's/^cy .*/cy 59.5/' "$t/cam.cam" >"$t/base.cam"
{ cat "$t/base.cam"; printf 'line_delay 0.008333\ndistortion -0.25 0.02 0.001 -0.001\n'; } >"$t/brown.cam"
{ cat "$t/base.cam"; printf 'line_delay 0.008333\nfisheye 0.05 -0.01 0.002 -0.0004\n'; } >"$t/fish.cam"
# run DIR [ENV...]: both lenses, frame 0 (its flow reads frame 1's rows), every
# output
run() {
    d=$1
    shift
    env "$@" "$BIN/glsplay" "$t/f.glsb" --camera "$t/brown.cam" --camera "$t/fish.cam" \
        --trajectory "$t/trajectory.txt" --motion "mover=$t/mover.txt" --frames 0:1 \
        --outputs image,depth,points,instance,normals,flow,boxes -o "$t/$d" 2>"$t/$d.err"
}
run rows GLS_LENS_BANDS_WHOLE=0 || { echo "FAIL lens_bands_same_bytes: glsplay failed: $(cat "$t/rows.err")"; exit 0; }
run whole GLS_LENS_BANDS_WHOLE=1 || { echo "FAIL lens_bands_same_bytes: glsplay failed: $(cat "$t/whole.err")"; exit 0; }
(cd "$t/rows" && find . -type f | sort) >"$t/rows.list"
(cd "$t/whole" && find . -type f | sort) >"$t/whole.list"
# 2 cameras x (image depth points instance instances.json normals
# boxes.txt boxes.json flow.flo flow.png flowmask .done)
want=$((2 * 12))
n=$(wc -l <"$t/rows.list")
differ=""
while read -r f; do
    cmp -s "$t/rows/$f" "$t/whole/$f" || differ="$differ $f"
done <"$t/rows.list"
if ! cmp -s "$t/rows.list" "$t/whole.list"; then
    echo "FAIL lens_bands_same_bytes: not the same files: $(diff "$t/rows.list" "$t/whole.list" | tr '\n' ' ')"
elif [ "$n" -ne "$want" ]; then
    echo "FAIL lens_bands_same_bytes: $n files, want $want: $(tr '\n' ' ' <"$t/rows.list")"
elif [ -n "$differ" ]; then
    echo "FAIL lens_bands_same_bytes: differ:$differ"
else
    echo "ok lens_bands_same_bytes"
fi
