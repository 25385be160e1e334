#!/bin/sh
# make bench-gpu: frames per second of whole glsplay runs on the road demo,
# a forest of 10,000 trees (43.5 million triangles, instanced) and 100,000
# triangles scattered in random order, at 640x480 and 1920x1080, through
# one GL backend (issue 30's GPU figures).  Not a pass/fail test.
# Files are written on glsplay's one writer thread while the next frame
# renders (--writer-threads 1, its default).
#
# usage: bench/gpu.sh prepare BIN DIR
#            write the inputs into DIR with BIN's glsroad and glsc (the
#            scenes and camera paths of bench/gpu_inputs.py, the demo road
#            and its stereo rig's left camera, scaled to 1920x1080)
#        bench/gpu.sh run BIN DIR [BACKEND [FRAMES]]
#            time BIN's glsplay on DIR's inputs with --backend BACKEND
#            (default egl) and print the table: for each scene, size and
#            output (image: PNG; depth: float32 .npy, the cheapest file
#            to write), T1, the whole process for one frame (start-up, load,
#            upload, draw, write: the time to the first image), and the
#            frames per second of the frames after it, (FRAMES - 1) / (TN -
#            T1), TN the whole process for FRAMES (default 200) frames along
#            the camera path.  Each figure is the best of REPS runs (default
#            2).  Frames write on.
#
# The road's camera path is glsroad's, with its vehicles moving (--motion);
# the forest's and the random scene's turn through a full circle, so each
# run sees the scene from every direction, not one chosen view.
set -e
cmd=$1 BIN=$2 DIR=$3
[ -n "$cmd" ] && [ -n "$BIN" ] && [ -n "$DIR" ] || { echo "usage: bench/gpu.sh prepare|run BIN DIR [BACKEND [FRAMES]]" >&2; exit 2; }
HERE=$(cd "$(dirname "$0")" && pwd)
case $cmd in
prepare)
    mkdir -p "$DIR"
    /usr/bin/python3 "$HERE/gpu_inputs.py" "$DIR"
    "$BIN/glsc" -I "$BIN/scenelib.glsb" -o "$DIR/random.glsb" "$DIR/random.scene"
    "$BIN/glsc" -I "$BIN/scenelib.glsb" -o "$DIR/forest.glsb" "$DIR/forest.scene"
    rm -f "$DIR/random.scene" "$DIR/forest.scene"
    "$BIN/glsroad" "$HERE/../examples/road/demo.road" -o "$DIR/road"
    "$BIN/glsc" -I "$DIR/road" -I "$BIN/scenelib.glsb" -o "$DIR/road.glsb" "$DIR/road/road.scene"
    cp "$HERE/../examples/road/rig/left.cam" "$DIR/road_640.cam"
    # the same camera at 1920x1080: the focal length scaled with the width
    awk '$1 == "width" { $2 = 1920 } $1 == "height" { $2 = 1080 } $1 == "fx" || $1 == "fy" { $2 = 1800 }
         $1 == "cx" { $2 = 959.5 } $1 == "cy" { $2 = 539.5 } { print }' "$DIR/road_640.cam" >"$DIR/road_1920.cam"
    ;;
run)
    BACKEND=${4:-egl} FRAMES=${5:-200} REPS=${REPS:-2}
    t=$(mktemp -d)
    trap 'rm -rf "$t"' EXIT
    now() { date +%s.%N; }
    motion=
    for m in "$DIR"/road/motion/*.txt; do
        [ -f "$m" ] && motion="$motion --motion $(basename "$m" .txt)=$m"
    done
    # best NFRAMES ARGS...: the least whole-process seconds of REPS runs
    best() {
        n=$1
        shift
        b=
        r=0
        while [ $r -lt "$REPS" ]; do
            rm -rf "$t/out"
            t0=$(now)
            # --aa 1 first (an --aa N given replaces it): the GPU's passes,
            # not exact coverage (the default since issue 28, on the CPU)
            "$BIN/glsplay" --aa 1 "$@" --backend "$BACKEND" --frames "0:$n" -o "$t/out" 2>"$t/err" ||
                { cat "$t/err" >&2; exit 1; }
            t1=$(now)
            b=$(awk -v a="$t0" -v c="$t1" -v b="$b" 'BEGIN { s = c - a; print (b == "" || s < b) ? s : b }')
            r=$((r + 1))
        done
        echo "$b"
    }
    "$BIN/glsplay" "$DIR/random.glsb" --camera "$DIR/cam_640.cam" --trajectory "$DIR/orbit_random.txt" \
        --backend "$BACKEND" --explain | grep -m2 -i 'backend:\|GL_RENDERER'
    echo "machine: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores"
    command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | sed 's/^/gpu: /'
    if [ -x "$BIN/bench/play_floor" ]; then
        echo "in process, no files (make bench-play's and bench-instances' programs; frames/s, colour + depth read back):"
        for p in "play_floor" "play_floor --random" "play_bench --backend $BACKEND" "instances_bench random" \
            "instances_bench forest edge 50" "instances_bench forest all 20"; do
            echo "  $p: $("$BIN"/bench/$p 2>&1 | tail -1)"
        done
    fi
    echo "whole glsplay runs:"
    echo "frames: $FRAMES along each camera path; best of $REPS; glsplay --backend $BACKEND"
    echo "scene | size | output | first image (s, whole process) | frames/s after it"
    for scene in road forest random; do
        for size in 640 1920; do
            case $scene in
            road) set -- "$DIR/road.glsb" --camera "$DIR/road_$size.cam" --trajectory "$DIR/road/trajectory.txt" $motion --background 0.55,0.7,0.9 ;;
            *) set -- "$DIR/$scene.glsb" --camera "$DIR/cam_$size.cam" --trajectory "$DIR/orbit_$scene.txt" ;;
            esac
            for out in image depth; do
                one=$(best 1 "$@" --outputs $out --float-format npy)
                all=$(best "$FRAMES" "$@" --outputs $out --float-format npy)
                awk -v s="$scene" -v z="$size" -v o="$out" -v a="$one" -v b="$all" -v n="$FRAMES" \
                    'BEGIN { printf "%s | %s | %s | %.3f | %.1f\n", s, (z == 640 ? "640x480" : "1920x1080"), o, a, (n - 1) / (b - a) }'
            done
        done
    done
    ;;
*)
    echo "usage: bench/gpu.sh prepare|run BIN DIR [BACKEND [FRAMES]]" >&2
    exit 2
    ;;
esac
