#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# Lens distortion (spec/camera.md "Lens distortion"): the model against
# cv2.projectPoints / cv2.fisheye.projectPoints, rendered checkerboards
# against OpenCV's corner detector and calibration (tests/py/check_distortion.py).
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
if ! $PY -c 'import cv2, numpy' 2>/dev/null; then
    echo "FAIL distortion: no cv2 and numpy under $PY"
    exit 0
fi
mkdir "$t/model"
$PY tests/py/check_distortion.py model "$BIN" "$t/model" || echo "FAIL distortion_model: check_distortion.py exited with status $?"
mkdir "$t/edges"
$PY tests/py/check_distortion.py edges "$BIN" "$t/edges" || echo "FAIL distortion_edges: check_distortion.py exited with status $?"
mkdir "$t/truth"
$PY tests/py/check_distortion.py truth "$BIN" "$t/truth" || echo "FAIL distortion_truth: check_distortion.py exited with status $?"
# four views each (make bench-distortion runs fifteen); not under the
# sanitizers (CI's second pass), where the eight 64-sample renders take
# minutes: the checks above run the same code
[ "$GLS_SANITIZED" = 1 ] && exit 0
mkdir "$t/board"
$PY tests/py/check_distortion.py board "$BIN" "$t/board" 4 || echo "FAIL distortion_board: check_distortion.py exited with status $?"
