#!/bin/sh
# Motion blur, rolling shutter and depth of field (spec/camera.md "Motion
# blur, rolling shutter, depth of field"): tests/py/check_exposure.py
# renders them and compares with closed forms in numpy.
# Prints "ok NAME" / "FAIL NAME: why".
BIN=${GLS_BIN:-build}
PY=/usr/bin/python3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if $PY -c 'import cv2, numpy' 2>/dev/null; then
    $PY tests/py/check_exposure.py "$BIN" "$t" || echo "FAIL exposure_check: check_exposure.py exited with status $?"
else
    echo "FAIL exposure_check: no cv2 and numpy under $PY"
fi
