#!/bin/sh
# Motion blur, rolling shutter and depth of field through a distorted lens
# (spec/camera.md "Through a lens"), and points with a rolling shutter
# (spec/outputs.md): tests/py/check_exposure_combos.py renders them and
# compares with images and points computed through cv2 and numpy.
# Prints "ok NAME" / "FAIL NAME: why".
BIN=${GLS_BIN:-build}
PY=/usr/bin/python3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if $PY -c 'import cv2, numpy' 2>/dev/null; then
    $PY tests/py/check_exposure_combos.py "$BIN" "$t" || echo "FAIL exposure_combos_check: check_exposure_combos.py exited with status $?"
else
    echo "FAIL exposure_combos_check: no cv2 and numpy under $PY"
fi
