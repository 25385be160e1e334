#!/bin/sh
# make bench-scaling: how glsplay's frames per second grow with processes
# (--shard I/N, the processes started together and waited for) and with
# llvmpipe's rasteriser threads (LP_NUM_THREADS: 1, 2, and unset, Mesa's
# default of one per core), for two sequences at 640x480, image output
# only, as bench-backends renders them:
#   road     examples/road/demo.road as glsroad writes it, left rig camera
#   terrain  bench/play_scene.h's height field, 100,352 triangles
#            (play_bench --write), its camera path
# Frames per second = frames of the whole sequence / wall time from the
# first process's start to the last one's end (start-up, upload and PNG
# writing included); the best of BS_REPEAT rounds (default 3), the
# settings interleaved within each round, since the machine may be shared.
# Writes $B/bench/scaling.txt (make bench-scaling: into docs/benchmarks.md) with the machine and its load.  Not a pass/fail
# test.
#   BS_FRAMES (default 48) frames of each sequence; BS_PROCS (default
#   "1 2") process counts; BS_THREADS (default "1 2 default")
B=${1:-build}
. bench/lib.sh
FRAMES=${BS_FRAMES:-48}
REPEAT=${BS_REPEAT:-3}
PROCS=${BS_PROCS:-1 2}
THREADS=${BS_THREADS:-1 2 default}
mkdir -p "$B/bench" && OUT=$B/bench/scaling.txt
work_dir
fixed_malloc

. bench/sequences.sh # the road and the terrain, ROAD and TERRAIN

# fps PROCS THREADS ARGS...: frames per second of PROCS shards run at once
fps() {
    np=$1 th=$2
    shift 2
    rm -rf "$t/out"
    t0=$(now)
    i=0
    pids=""
    while [ $i -lt "$np" ]; do
        if [ "$th" = default ]; then
            # shellcheck disable=SC2068
            env -u LP_NUM_THREADS "$B/glsplay" --aa 1 $@ --frames "0:$FRAMES" --shard "$i/$np" --outputs image -o "$t/out" 2>"$t/err$i" &
        else
            # shellcheck disable=SC2068
            LP_NUM_THREADS=$th "$B/glsplay" --aa 1 $@ --frames "0:$FRAMES" --shard "$i/$np" --outputs image -o "$t/out" 2>"$t/err$i" &
        fi
        pids="$pids $!"
        i=$((i + 1))
    done
    failed=0
    for pid in $pids; do wait "$pid" || failed=1; done
    t1=$(now)
    [ $failed -eq 0 ] || { cat "$t"/err* >&2; exit 1; }
    [ "$(find "$t/out" -name "image_*" | wc -l)" -eq "$FRAMES" ] || { echo "bench-scaling: frames missing" >&2; exit 1; }
    rate "$FRAMES" "$t0" "$t1"
}
# table NAME ARGS...: a row per process count, a column per thread setting
table() {
    name=$1
    shift
    for p in $PROCS; do for th in $THREADS; do eval "best_${p}_$th=0"; done; done
    r=0
    while [ $r -lt "$REPEAT" ]; do
        for p in $PROCS; do
            for th in $THREADS; do
                f=$(fps "$p" "$th" "$@") || exit 1
                eval "b=\$best_${p}_$th"
                eval "best_${p}_$th=$(larger "$f" "$b")"
            done
        done
        r=$((r + 1))
    done
    echo "$name, $FRAMES frames: frames per second"
    echo
    printf '| processes |'
    for th in $THREADS; do printf ' LP_NUM_THREADS=%s |' "$th"; done
    printf '\n|---|'
    for th in $THREADS; do printf -- '---|'; done
    printf '\n'
    for p in $PROCS; do
        printf '| %s |' "$p"
        for th in $THREADS; do eval "printf ' %s |' \"\$best_${p}_$th\""; done
        printf '\n'
    done
    echo
}

load0=$(loadavg 3)
{
echo "machine: $(machine)"
"$B/glsplay" $TERRAIN --explain 2>/dev/null | grep -E '^(backend|GL_RENDERER):'
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "LP_NUM_THREADS=default: unset, llvmpipe's own choice (one thread per core: $(nproc) here)"
echo "best of $REPEAT rounds; glsplay --outputs image, 640x480, whole runs (start-up, upload, PNG writing)"
echo
table "road (examples/road/demo.road, left rig camera)" $ROAD
table "terrain (100,352 triangles, bench/play_scene.h)" $TERRAIN
echo "load average (1, 5, 15 min; other work on the machine included): $load0 before, $(loadavg 3) after"
} >"$OUT"
cat "$OUT"
