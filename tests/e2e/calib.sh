#!/bin/sh
# glsplay --write-calib (spec/outputs.md "Calibration files"): the files
# read back with cv2.FileStorage, numpy, yaml and json against geometry
# computed in tests/py/check_calib.py; cameras written by cv2.FileStorage
# read by glsplay (spec/camera.md "OpenCV camera files"); usage and write
# errors here.
# Prints "ok NAME" / "FAIL NAME: why".
BIN=${GLS_BIN:-build}
PY=/usr/bin/python3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
ok() { echo "ok $1"; }
fail() { echo "FAIL $1: $2"; }
if $PY -c 'import cv2, numpy, yaml' 2>/dev/null; then
    $PY tests/py/check_calib.py export "$BIN" "$t" || echo "FAIL calib_export: check_calib.py exited with status $?"
    mkdir "$t/import"
    $PY tests/py/check_calib.py import "$BIN" "$t/import" || echo "FAIL calib_import: check_calib.py exited with status $?"
else
    fail calib_export "no cv2, numpy and yaml under $PY"
fi

"$BIN/glsc" -I tests/compiler/lang -o "$t/leaf.glsb" pkg.Leaf 2>/dev/null || { fail calib_setup glsc; exit 0; }
cam='width 8\nheight 6\nfx 8\nfy 8\ncx 3.5\ncy 2.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 5\nnear 0.1\nfar 100\n'
mkdir -p "$t/c"
printf "$cam" >"$t/c/a.cam"
# no output directory to write into
"$BIN/glsplay" "$t/leaf.glsb" --camera "$t/c/a.cam" --explain --write-calib >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(head -1 "$t/err")" = "glsplay: error: --write-calib writes into the output directory: give -o OUTDIR (try glsplay --help)" ]; then
    ok calib_needs_outdir
else
    fail calib_needs_outdir "exit $rc: $(cat "$t/err")"
fi
# a camera named calib.txt has a directory where the KITTI file goes: the
# write is refused, nothing is put in its place, no temporary file is left
printf "$cam" >"$t/c/calib.txt"
"$BIN/glsplay" "$t/leaf.glsb" --camera "$t/c/calib.txt" --outputs image --write-calib -o "$t/o" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "glsplay: error: cannot write $t/o/calib.txt: it is a directory" ] &&
    [ -d "$t/o/calib.txt" ] && [ "$(ls -A "$t/o")" = "calib.txt" ]; then
    ok calib_write_refused
else
    fail calib_write_refused "exit $rc: $(cat "$t/err"); $(ls -A "$t/o")"
fi
