#!/bin/sh
# make bench-distortion: what lens distortion costs and keeps (spec/camera.md
# "The distorted image").  Not a pass/fail run (the tests are
# tests/e2e/distortion.sh); writes $B/bench/distortion.txt (make bench-distortion: into docs/benchmarks.md).
#  1. time per frame of the road demo (examples/road, the left rig camera,
#     640x480, --outputs image,depth,points), DB_FRAMES frames (default 8),
#     best of DB_REPEAT runs (default 2): the pinhole camera, the same with
#     all-zero coefficients, and with k1 = -0.3 k2 = 0.08 p1 = 0.001
#     p2 = -0.0015, without anti-aliasing and with --samples 64; with
#     DB_BASELINE set to a glsplay built before the lens existed, the
#     pinhole with it too (the "no extra time when off" check);
#  2. edge accuracy of the distorted image against the pinhole's, per row,
#     at 0.5, 10, 30, 45 degrees (bench/distortion_edges.py);
#  3. the 15-view calibration of tests/py/check_distortion.py (make test
#     runs it with 4 views).
B=${1:-build}
. bench/lib.sh
FRAMES=${DB_FRAMES:-8}
REPEAT=${DB_REPEAT:-2}
PY=/usr/bin/python3
mkdir -p "$B/bench" && OUT=$B/bench/distortion.txt
work_dir
fixed_malloc
"$B/glsroad" examples/road/demo.road -o "$t/road" >/dev/null &&
    "$B/glsc" -I "$B/scenelib.glsb" -I "$t/road" -o "$t/road.glsb" "$t/road/road.scene" 2>/dev/null || exit 1
mkdir -p "$t/pin" "$t/zero" "$t/lens"
cp examples/road/rig/left.cam "$t/pin/left.cam"
{ cat examples/road/rig/left.cam; echo "distortion 0 0 0 0"; } >"$t/zero/left.cam"
{ cat examples/road/rig/left.cam; echo "distortion -0.3 0.08 0.001 -0.0015"; } >"$t/lens/left.cam"
set -- $(for m in "$t"/road/motion/*.txt; do [ -f "$m" ] && echo "--motion $(basename "$m" .txt)=$m"; done)
MOTION="$*"

# ms GLSPLAY CAMDIR ARGS...: milliseconds per frame, best of REPEAT runs
ms() {
    play=$1 cam=$2
    shift 2
    best=""
    i=0
    while [ $i -lt "$REPEAT" ]; do
        rm -rf "$t/out"
        t0=$(now)
        # shellcheck disable=SC2086
        # no anti-aliasing: --aa 1 (the default since issue 28 is exact coverage)
        "$play" "$t/road.glsb" --camera "$cam/left.cam" --trajectory "$t/road/trajectory.txt" $MOTION \
            --frames "0:$FRAMES" --outputs image,depth,points --background 0.55,0.7,0.9 -o "$t/out" ${*:---aa 1} \
            2>"$t/err" || { cat "$t/err" >&2; exit 1; }
        t1=$(now)
        v=$(awk -v n="$FRAMES" -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", 1000 * (b - a) / n }')
        [ -z "$best" ] || [ "$v" -lt "$best" ] && best=$v
        i=$((i + 1))
    done
    echo "$best"
}

{
echo "machine: $(cpu), $(nproc) cores; load average before the run: $(loadavg 3)"
echo "date: $(date -u +%Y-%m-%d)"
echo
echo "## 1. Time per frame, road demo, left rig camera 640x480, $FRAMES frames, image + depth + points"
echo "(whole runs, start-up included, divided by the frames; best of $REPEAT; the machine is shared)"
echo
echo "| camera | no anti-aliasing | --samples 64 |"
echo "|---|---|---|"
[ -n "$DB_BASELINE" ] &&
    echo "| pinhole, glsplay before lens distortion ($DB_BASELINE) | $(ms "$DB_BASELINE" "$t/pin") ms | $(ms "$DB_BASELINE" "$t/pin" --samples 64) ms |"
echo "| pinhole | $(ms "$B/glsplay" "$t/pin") ms | $(ms "$B/glsplay" "$t/pin" --samples 64) ms |"
echo "| distortion 0 0 0 0 (off: the pinhole path) | $(ms "$B/glsplay" "$t/zero") ms | $(ms "$B/glsplay" "$t/zero" --samples 64) ms |"
echo "| distortion -0.3 0.08 0.001 -0.0015 | $(ms "$B/glsplay" "$t/lens") ms | $(ms "$B/glsplay" "$t/lens" --samples 64) ms |"
echo
"$B/glsplay" "$t/road.glsb" --camera "$t/lens/left.cam" --trajectory "$t/road/trajectory.txt" --frames 0:1 \
    --samples 64 --explain 2>/dev/null | grep '  lens:'
echo
echo "## 2. Edge accuracy (bench/distortion_edges.py)"
echo
sed -n '/^A white half-plane/,/^"""/p' bench/distortion_edges.py | sed '$d'
echo
mkdir "$t/edges"
$PY bench/distortion_edges.py "$B" "$t/edges"
echo
echo "## 3. Calibration from 15 rendered views per lens (tests/py/check_distortion.py board, --aa 8 --pattern grid)"
echo
mkdir "$t/board"
$PY tests/py/check_distortion.py board "$B" "$t/board" 15
} >"$t/distortion.txt" || exit 1
mkdir -p docs
cp "$t/distortion.txt" "$OUT"
cat "$OUT"
