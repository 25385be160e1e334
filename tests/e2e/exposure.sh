#!/bin/sh
# Motion blur, rolling shutter and depth of field (spec/camera.md "Motion
# blur, rolling shutter, depth of field"): tests/py/check_exposure.py
# renders them and compares with closed forms in numpy.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
py_check exposure_check check_exposure.py "$BIN" "$t"
