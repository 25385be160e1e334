#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# End-to-end tests of the paper-figure examples (examples/*/, rendered by
# examples/render.sh, `make demo`).  Prints "ok NAME" / "FAIL NAME: why"
# and the measured figures ("# ..." lines).  Needs glsc, glsplay and
# scenelib.glsb in $GLS_BIN (default build), /usr/bin/python3 with cv2.
#   - the camera files are what tools/excams.py writes now;
#   - every example compiles against the scene library with no diagnostic,
#     and every camera renders a non-blank image with finite depth (the
#     examples that are only for looks at --aa 1, image and depth only);
#   - calibration: OpenCV's chessboard detector finds all 9 x 6 corners in
#     all 15 views (rendered as `make demo` does, --aa 8), and the refined
#     corners lie within 0.1 px (RMS and max) of the stated corners
#     projected through the camera files; cv2.calibrateCamera recovers
#     fx, fy, cx, cy within 1 px;
#   - stereo: the binocular pair writes disparity and disparity16 (every
#     pixel reprojected into the other camera lands u -+ d away, on the
#     same row; the KITTI PNG is round(256 d)), the trinocular rig none;
#   - dense stereo: StereoSGBM on the rectified pair (--aa 4, as make demo)
#     agrees with the ground-truth disparity f B / Z within 1 px on at least
#     95% of the pixels valid in both (measured 0.989), within 3 px on 97%.
# EXAMPLES_KEEP=DIR keeps the renders.
. tests/e2e/lib.sh
keep_in "$EXAMPLES_KEEP"
need examples_build_products glsc glsplay scenelib.glsb
EXAMPLES="calibration stereo dense_stereo grouping lane signs lighting"

# ---- camera files are generated and up to date --------------------------------
if $PY tools/excams.py "$t/cams" >"$t/cams.list" 2>"$t/err"; then
    bad=""
    while read -r f; do
        cmp -s "$f" "examples/${f#"$t/cams/"}" || bad="$bad ${f#"$t/cams/"}"
    done <"$t/cams.list"
    for e in $EXAMPLES; do
        for f in examples/$e/*.cam; do
            grep -qx "$t/cams/${f#examples/}" "$t/cams.list" || bad="$bad $f(stale)"
        done
    done
    if [ -z "$bad" ] && [ -s "$t/cams.list" ]; then ok examples_cameras_up_to_date
    else fail examples_cameras_up_to_date "differ from tools/excams.py:$bad (run python3 tools/excams.py)"; fi
else
    fail examples_cameras_up_to_date "tools/excams.py failed: $(head -3 "$t/err")"
fi

# ---- every example compiles without a diagnostic -------------------------------
for e in $EXAMPLES; do
    scene=$(ls examples/$e/*.scene 2>/dev/null)
    if [ "$(echo "$scene" | wc -w)" -ne 1 ]; then
        fail "examples_compile_$e" "want exactly one top-level .scene in examples/$e, found: $scene"
        continue
    fi
    if "$B/glsc" -I "$B/scenelib.glsb" -o "$t/$e.glsb" "$scene" >"$t/diag" 2>&1 && [ ! -s "$t/diag" ]; then
        ok "examples_compile_$e"
    else
        fail "examples_compile_$e" "$(head -5 "$t/diag" | tr '\n' ' ')"
    fi
    if [ -s "examples/$e/README.md" ]; then ok "examples_readme_$e"; else fail "examples_readme_$e" "no examples/$e/README.md"; fi
done

# ---- render as make demo does (looks-only examples at --aa 1) -------------------
if ! EXAMPLES_LOOK_AA=1 EXAMPLES_OUTPUTS=image,depth EXAMPLES_DEPTH_VIEW=0 \
    sh examples/render.sh "$B" "$t/out" >"$t/render.log" 2>&1; then
    fail examples_render "examples/render.sh failed: $(tail -5 "$t/render.log" | tr '\n' ' ')"
fi
need_cv2 examples_python
for e in $EXAMPLES; do
    $PY tests/py/examples_check.py depth "$e" "$t/out/$e"
done
$PY tests/py/examples_check.py calib examples/calibration "$t/out/calibration" 0.1 | grep -v '^# view'
# stereo: the binocular rig, a rectified pair, writes its disparity
$PY tests/py/check_disparity.py reproject "$t/out/stereo" examples/stereo/bino_left.cam examples/stereo/bino_right.cam \
    stereo_example | grep -v '^#'
$PY tests/py/check_disparity.py kitti "$t/out/stereo" bino_left bino_right
[ ! -e "$t/out/stereo/tri_left/disparity_000000.pfm" ] && [ -f "$t/out/stereo/tri_left/image_000000.png" ] &&
    ok examples_stereo_trinocular_no_disparity || fail examples_stereo_trinocular_no_disparity "$(ls "$t/out/stereo/tri_left")"
$PY tests/py/examples_check.py sgbm examples/dense_stereo "$t/out/dense_stereo" 0.95 0.97
