#!/bin/sh
# The GL backends (spec/backends.md) in the normal build, where both are
# built: on llvmpipe, EGL and OSMesa give byte-identical images, depth maps
# and point clouds; the projection and depth exactness tests pass through
# each; --explain names the backend; the errors are one line each; auto
# falls back to OSMesa when EGL gives no context; glsplay imports no GL
# function from any library (runtime/gl/glcalls.h).
# EGL is made to render with llvmpipe here whatever the machine has
# (--backend egl-surfaceless with LIBGL_ALWAYS_SOFTWARE=1), so that the
# comparison holds on a machine with a GPU too; the exactness tests run
# through --backend egl, a GPU where there is one.
# Prints "ok NAME" / "FAIL NAME: why"; a backend that is not built is
# reported and skipped (tests/e2e/build_backends.sh tests such builds).
. tests/e2e/lib.sh
PLAY=$B/glsplay
need backends_build_products glsc glsplay glsroad scenelib.glsb tests/test_player
# a backend this glsplay lacks says so and exits 2 (build_backends.sh)
for be in egl osmesa; do
    msg=$("$PLAY" --backend $be --help 2>&1 >/dev/null)
    case $msg in
    "") ;;
    *"was built without"*) echo "note: backends: this glsplay has no $be backend; the comparisons are skipped"; exit 0 ;;
    *) fail backends_option "glsplay --backend $be: $msg"; exit 0 ;;
    esac
done

# ---- the scenes: the demo, test_player's, every example, a road frame ---------------
$B/tests/test_player --write "$t" >/dev/null || { fail backends_scenes "test_player --write failed"; exit 0; }
$B/glsc -I examples/demo -I "$B/textures" -o "$t/demo.glsb" examples/demo/Demo.scene 2>"$t/err" ||
    fail backends_demo_compiles "$(cat "$t/err")"
for e in calibration stereo dense_stereo grouping lane signs; do
    s=$(ls examples/$e/*.scene)
    $B/glsc -I "$B/scenelib.glsb" -o "$t/$e.glsb" "$s" 2>"$t/err" || fail "backends_${e}_compiles" "$(cat "$t/err")"
done
$B/glsroad examples/road/demo.road -o "$t/road" >/dev/null 2>"$t/err" &&
    $B/glsc -I "$B/scenelib.glsb" -I "$t/road" -o "$t/road.glsb" "$t/road/road.scene" 2>"$t/err" ||
    fail backends_road_compiles "$(cat "$t/err")"

# render NAME ARGS...: the same render through EGL on llvmpipe and OSMesa,
# into $t/egl/NAME and $t/osmesa/NAME; then every file compared byte for byte
render() {
    name=$1
    shift
    LIBGL_ALWAYS_SOFTWARE=1 "$PLAY" "$@" --backend egl-surfaceless -o "$t/egl/$name" 2>"$t/err.egl" ||
        { fail "backends_${name}_egl_renders" "$(cat "$t/err.egl")"; return; }
    "$PLAY" "$@" --backend osmesa -o "$t/osmesa/$name" 2>"$t/err.osmesa" ||
        { fail "backends_${name}_osmesa_renders" "$(cat "$t/err.osmesa")"; return; }
    n=0 bad=""
    for f in $(cd "$t/egl/$name" && find . -type f ! -name '.*' | sort); do
        n=$((n + 1))
        cmp -s "$t/egl/$name/$f" "$t/osmesa/$name/$f" || bad="$bad $f"
    done
    if [ $n -eq 0 ]; then fail "backends_${name}_identical" "no output files"
    elif [ -n "$bad" ]; then fail "backends_${name}_identical" "EGL and OSMesa differ in$bad"
    else ok "backends_${name}_identical"; fi
}
SKY="--background 0.55,0.7,0.9"
# the renders without --aa N ask --aa 1: the default, exact coverage, draws
# the image on the CPU, the same bytes whatever the backend
render demo_aa4 "$t/demo.glsb" --camera examples/demo/left.cam --camera examples/demo/right.cam --aa 4 $SKY
render demo_plain "$t/demo.glsb" --camera examples/demo/left.cam --outputs image,depth,points --aa 1
render demo_aa4_png16_edges "$t/demo.glsb" --camera examples/demo/right.cam --aa 4 --image-format png16 \
    --outputs image,edges
render proj "$t/proj.glsb" --camera "$t/proj.cam" --aa 1
render orient_stereo "$t/orient.glsb" --camera "$t/orient.cam" --camera "$t/left.cam" --camera "$t/right.cam" --aa 1
for e in calibration stereo dense_stereo grouping lane signs; do
    render "$e" "$t/$e.glsb" --camera "$(ls examples/$e/*.cam | head -1)" --size 320x240 --aa 2 $SKY
done
render road_frames "$t/road.glsb" --camera examples/road/rig/left.cam --camera examples/road/rig/right.cam \
    --trajectory "$t/road/trajectory.txt" --frames 100:102 --aa 1 $SKY
# both on llvmpipe, or the comparison says nothing
for be in egl-surfaceless osmesa; do
    LIBGL_ALWAYS_SOFTWARE=1 "$PLAY" "$t/proj.glsb" --backend $be --explain >"$t/plan" 2>&1
    grep -q '^GL_RENDERER: llvmpipe' "$t/plan" && ok "backends_${be}_is_llvmpipe" ||
        fail "backends_${be}_is_llvmpipe" "$(grep -E '^(backend|GL_RENDERER|glsplay)' "$t/plan")"
done

# ---- the exactness tests through each backend ----------------------------------
for be in egl osmesa; do
    $B/tests/test_player --backend $be 2>&1 | sed "s/^ok /ok backends_$be:/; s/^FAIL /FAIL backends_$be:/"
done
if [ -x $PY ] && $PY -c 'import cv2' 2>/dev/null; then
    # --aa 1: the image drawn by the backend's GL (the default, exact
    # coverage, draws it on the CPU)
    "$PLAY" "$t/proj.glsb" --camera "$t/proj.cam" --backend egl --aa 1 -o "$t/gpu" 2>"$t/err" &&
        "$PLAY" "$t/orient.glsb" --camera "$t/orient.cam" --camera "$t/left.cam" --camera "$t/right.cam" \
            --backend egl --aa 1 -o "$t/gpu" 2>>"$t/err" || fail backends_egl_py_renders "$(cat "$t/err")"
    for m in proj orient stereo; do
        $PY tests/py/check_player.py $m "$t" "$t/gpu" | sed 's/^ok /ok backends_egl:/; s/^FAIL /FAIL backends_egl:/'
    done
else
    fail backends_opencv "no OpenCV under $PY"
fi

# ---- --explain ----------------------------------------------------------------------
# plan LINE-PATTERN NAME ARGS...
plan() {
    pat=$1 name=$2
    shift 2
    "$PLAY" "$t/proj.glsb" --explain "$@" >"$t/plan" 2>"$t/err"
    grep -q -- "$pat" "$t/plan" && ok "$name" || fail "$name" "$(grep -E '^backend|^GL_' "$t/plan") $(cat "$t/err")"
}
plan '^backend: egl (--backend auto: EGL first, OSMesa if EGL fails), platform: \(device\|surfaceless\), device: ' \
    backends_explain_auto
plan '^backend: osmesa (--backend osmesa), platform: none, device: none (software: Mesa'"'"'s OSMesa)$' \
    backends_explain_osmesa --backend osmesa
plan '^backend: egl (--backend egl-surfaceless), platform: surfaceless, device: driver swrast, EGL vendor Mesa Project$' \
    backends_explain_surfaceless --backend egl-surfaceless
plan '^backend: egl (--backend egl-device), platform: device, device: device [0-9]* of [0-9]*: ' \
    backends_explain_device --backend egl-device
plan '^GL_RENDERER: .*; GL_VERSION: 4\.[5-9]' backends_explain_gl_strings --backend osmesa

# ---- errors and the fallback ----------------------------------------------------------
# expect NAME STATUS LINE ENV... -- ARGS...: exit status and the one line of stderr, verbatim
expect() {
    name=$1 want=$2 line=$3
    shift 3
    envs=""
    while [ "$1" != -- ]; do envs="$envs $1"; shift; done
    shift
    # shellcheck disable=SC2086
    env $envs "$PLAY" "$@" >"$t/stdout" 2>"$t/stderr"
    rc=$?
    if [ $rc -ne "$want" ]; then fail "$name" "exit $rc, wanted $want: $(cat "$t/stderr")"
    elif [ "$(cat "$t/stderr")" != "$line" ]; then fail "$name" "stderr: $(cat "$t/stderr")"
    else ok "$name"; fi
}
expect backends_unknown 2 \
    "glsplay: error: --backend takes one of: auto, egl, egl-device, egl-surfaceless, osmesa (not 'vulkan') (try glsplay --help)" \
    -- "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/x" --backend vulkan
expect backends_missing_value 2 \
    "glsplay: error: --backend needs one of: auto, egl, egl-device, egl-surfaceless, osmesa (try glsplay --help)" \
    -- "$t/proj.glsb" --explain --backend
# Mesa's drivers out of reach: its EGL has no driver (EGL_LOG_LEVEL keeps
# Mesa's own warning off stderr)
mkdir "$t/nodrivers"
expect backends_egl_no_driver 1 \
    "glsplay: error: egl: surfaceless platform: eglInitialize failed: EGL_NOT_INITIALIZED" \
    LIBGL_DRIVERS_PATH="$t/nodrivers" EGL_LOG_LEVEL=fatal -- "$t/proj.glsb" --camera "$t/proj.cam" \
    -o "$t/nodrv" --backend egl-surfaceless
[ ! -e "$t/nodrv" ] && ok backends_egl_error_writes_nothing || fail backends_egl_error_writes_nothing "$(find "$t/nodrv")"
# no EGL vendor library at all (libglvnd's EGL finds none): EGL fails at its
# first step, auto renders with OSMesa, the same image
echo '{}' >"$t/none.json"
expect backends_egl_no_vendor 1 \
    "glsplay: error: egl: the EGL library lacks EGL_EXT_platform_base (client extensions: none)" \
    __EGL_VENDOR_LIBRARY_FILENAMES="$t/none.json" -- "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/x" --backend egl
expect backends_auto_falls_back 0 "" __EGL_VENDOR_LIBRARY_FILENAMES="$t/none.json" -- "$t/proj.glsb" \
    --camera "$t/proj.cam" -o "$t/fallback" --explain --aa 1
grep -q "^backend: osmesa (--backend auto; EGL gave no context: egl: the EGL library lacks EGL_EXT_platform_base (client extensions: none)), platform: none" "$t/stdout" &&
    ok backends_auto_fallback_explained || fail backends_auto_fallback_explained "$(grep '^backend' "$t/stdout")"
cmp -s "$t/fallback/proj/image_000000.png" "$t/egl/proj/proj/image_000000.png" &&
    ok backends_auto_fallback_same_image || fail backends_auto_fallback_same_image "differs from EGL's"

# ---- no GL symbol is linked: every call goes through the backend -------------------
if command -v nm >/dev/null; then
    for p in "$PLAY" $B/tests/test_player $B/tests/test_aa $B/bench/play_bench $B/bench/play_floor; do
        [ -e "$p" ] || continue
        gl=$(nm -D --undefined-only "$p" | awk '$2 ~ /^gl[A-Z]/ { printf " %s", $2 }')
        [ -z "$gl" ] && ok "backends_no_gl_import_$(basename "$p")" ||
            fail "backends_no_gl_import_$(basename "$p")" "imports$gl: add them to runtime/gl/glcalls.h"
    done
else
    fail backends_nm "no nm"
fi
