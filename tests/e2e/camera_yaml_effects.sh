#!/bin/sh
# Effect keys in OpenCV YAML cameras (spec/camera.md "OpenCV camera
# files"): tests/py/check_camera_yaml_effects.py renders a .cam with every
# sensor and exposure key and its twin written by cv2.FileStorage (the same
# bytes), reads glsplay --write-calib's calib_F.yml back with cv2 and gives
# it back to glsplay.  The YAML errors are tests/errors/camera/opencv_*.yml
# (camera_errors.sh).  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
py_check camera_yaml_effects check_camera_yaml_effects.py "$BIN" "$BIN/scenelib.glsb" "$t"
