#!/bin/sh
# make bench-backends: frames per second of each GL backend this build has
# (spec/backends.md), for two sequences rendered by glsplay at 640x480,
# image output only:
#   road     examples/road/demo.road as glsroad writes it (the road and its
#            objects, textured, no vehicles), left rig camera, frames from 0
#   terrain  bench/play_scene.h's height field, 100,352 triangles with
#            per-vertex colours (play_bench --write), its camera path
# each single pass (--aa 1) and with 256 lattice samples a pixel (--aa 16,
# a 16x16 grid).  Frames per second = frames / wall time of the whole
# glsplay run (start-up, context, upload, PNG writing included); the best
# of BB_REPEAT runs (default 3), the backends interleaved, since the
# machine may be shared.  Also the renderer alone (bench/play_bench: 200
# frames of the terrain, colour and depth read back, no files).  Writes
# $B/bench/backends.txt (make bench-backends puts it in docs/benchmarks.md).  Not a pass/fail test.
#   BB_FRAMES (default 36) single-pass frames; BB_AA_FRAMES (default 3)
#   frames at 256 samples; BB_BACKENDS (default: "egl osmesa", those built)
B=${1:-build}
. bench/lib.sh
FRAMES=${BB_FRAMES:-36}
AA_FRAMES=${BB_AA_FRAMES:-3}
REPEAT=${BB_REPEAT:-3}
mkdir -p "$B/bench" && OUT=$B/bench/backends.txt
work_dir
fixed_malloc

backends=""
for be in ${BB_BACKENDS:-egl osmesa}; do
    if "$B/glsplay" --backend "$be" --help >/dev/null 2>&1; then backends="$backends $be"
    else echo "note: this glsplay has no $be backend"; fi
done
[ -n "$backends" ] || { echo "bench-backends: no backend to measure" >&2; exit 1; }

# the inputs
. bench/sequences.sh # the road and the terrain, ROAD and TERRAIN

# fps BACKEND FRAMES SCENE-ARGS...: frames per second of one glsplay run
fps() {
    be=$1 n=$2
    shift 2
    # --aa 1 first (a row's --aa 16 replaces it): GL's passes, not exact
    # coverage (the default since issue 28, drawn on the CPU)
    run_fps "$n" "$B/glsplay" --aa 1 "$@" --outputs image --backend "$be"
}
# row NAME FRAMES ARGS...: a table row, the best of REPEAT runs of each
# backend, interleaved
row() {
    name=$1 n=$2
    shift 2
    for be in $backends; do eval "best_$be=0"; done
    i=0
    while [ $i -lt "$REPEAT" ]; do
        for be in $backends; do
            f=$(fps "$be" "$n" "$@") || exit 1
            eval "b=\$best_$be"
            eval "best_$be=$(larger "$f" "$b")"
        done
        i=$((i + 1))
    done
    printf '| %s |' "$name"
    for be in $backends; do eval "printf ' %s |' \"\$best_$be\""; done
    printf '\n'
}

load0=$(loadavg 1)
{
echo "machine: $(machine)"
for be in $backends; do
    "$B/glsplay" $TERRAIN --explain --backend "$be" >"$t/plan" 2>/dev/null
    grep -E '^(backend|GL_RENDERER):' "$t/plan"
done
echo "GPU: none on this machine (no device platform GPU; EGL renders with Mesa's llvmpipe through the"
echo "surfaceless platform); no GPU figures are given"
echo "date: $(date -u +%Y-%m-%d)"
echo
echo "glsplay frames per second, 640x480, image output only, best of $REPEAT runs"
echo "(whole glsplay run: start-up, upload and PNG writing included):"
echo
printf '| sequence, samples a pixel |'
for be in $backends; do printf ' %s |' "$be"; done
printf '\n|---|'
for be in $backends; do printf -- '---|'; done
printf '\n'
row "road, $FRAMES frames, 1 (single pass)" "$FRAMES" $ROAD
row "road, $AA_FRAMES frames, 256 (--aa 16)" "$AA_FRAMES" $ROAD --aa 16
row "terrain 100,352 triangles, $FRAMES frames, 1" "$FRAMES" $TERRAIN
row "terrain 100,352 triangles, $AA_FRAMES frames, 256 (--aa 16)" "$AA_FRAMES" $TERRAIN --aa 16
echo
echo "renderer alone (bench/play_bench: terrain, 200 frames, colour + depth read-back, no files), best of $REPEAT:"
for be in $backends; do
    best=0
    i=0
    while [ $i -lt "$REPEAT" ]; do
        f=$("$B/bench/play_bench" --backend "$be" | awk '{print $2}') || exit 1
        best=$(larger "$f" "$best")
        i=$((i + 1))
    done
    echo "  $be: $best frames/s"
done
echo
echo "load average (1 min, other work on the machine included): $load0 before, $(loadavg 1) after"
} >"$OUT"
cat "$OUT"
