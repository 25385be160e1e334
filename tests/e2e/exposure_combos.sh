#!/bin/sh
# Motion blur, rolling shutter and depth of field through a distorted lens
# (spec/camera.md "Through a lens"), and points with a rolling shutter
# (spec/outputs.md): tests/py/check_exposure_combos.py renders them and
# compares with images and points computed through cv2 and numpy.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
py_check exposure_combos_check check_exposure_combos.py "$BIN" "$t"
