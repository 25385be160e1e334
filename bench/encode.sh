#!/bin/sh
# make bench-encode: what writing the output files costs glsplay (issue 14).
# Not a pass/fail test; timings only.  Writes $B/bench/encode.txt
# (make bench-encode puts it in docs/benchmarks.md).
#
# 1. glsplay frames per second on two sequences (the road demo as glsroad
#    writes it, textured, left rig camera; the 100,352-triangle terrain of
#    make bench-play), at 640x480 and 1920x1080 (the cameras' intrinsics
#    scaled), single pass:
#      image    --outputs image (8-bit PNG), writer thread on (the default)
#      image0   the same with --writer-threads 0 (encode and write in turn)
#      depth    --outputs depth (a PFM, no image file), writer thread on
#      stb      --outputs image with the glsplay given in BE_BASELINE (a
#               build from before issue 14: stb_image_write's encoder, no
#               writer thread), when set
#    frames per second = frames / wall time of the whole run (start-up and
#    upload included), the best of BE_REPEAT runs (default 2).
# 2. One frame of each sequence and size encoded by every encoder and
#    setting (bench/png_bench.c): milliseconds and bytes, 8-bit and 16-bit.
#   BE_FRAMES (default 36) frames at 640x480, BE_FRAMES_HD (default 12) at
#   1920x1080.
B=${1:-build}
. bench/lib.sh
FRAMES=${BE_FRAMES:-36}
FRAMES_HD=${BE_FRAMES_HD:-12}
REPEAT=${BE_REPEAT:-2}
mkdir -p "$B/bench" && OUT=$B/bench/encode.txt
work_dir
fixed_malloc

. bench/sequences.sh # the road and the terrain
# camera CAM SCALE W H: CAM with fx fy cx cy scaled and the size set
camera() {
    awk -v s="$2" -v w="$3" -v h="$4" '
        $1 == "width" { print "width", w; next }
        $1 == "height" { print "height", h; next }
        $1 == "fx" || $1 == "fy" { print $1, $2 * s; next }
        $1 == "cx" { print "cx", (w - 1) / 2; next }
        $1 == "cy" { print "cy", (h - 1) / 2; next }
        { print }' "$1"
}
mkdir -p "$t/sd" "$t/hd"
camera examples/road/rig/left.cam 1 640 480 >"$t/sd/left.cam"
camera examples/road/rig/left.cam 3 1920 1080 >"$t/hd/left.cam"
camera "$t/rig.cam" 1 640 480 >"$t/sd/rig.cam"
camera "$t/rig.cam" 3 1920 1080 >"$t/hd/rig.cam"

# fps GLSPLAY FRAMES ARGS...: frames per second of one run
fps() {
    play=$1 n=$2
    shift 2
    run_fps "$n" "$play" "$@"
}
best() {
    b=0 i=0
    while [ $i -lt "$REPEAT" ]; do
        f=$(fps "$@") || exit 1
        b=$(larger "$f" "$b")
        i=$((i + 1))
    done
    echo "$b"
}
# row NAME FRAMES ARGS...: one table row
row() {
    name=$1 n=$2
    shift 2
    a=$(best "$B/glsplay" "$n" "$@" --outputs image --aa 1) || exit 1
    b=$(best "$B/glsplay" "$n" "$@" --outputs image --aa 1 --writer-threads 0) || exit 1
    c=$(best "$B/glsplay" "$n" "$@" --outputs depth) || exit 1
    d="-"
    [ -n "$BE_BASELINE" ] && { d=$(best "$BE_BASELINE" "$n" "$@" --outputs image) || exit 1; }
    echo "| $name | $a | $b | $c | $d |"
}

load0=$(loadavg 1)
{
echo "machine: $(machine)"
"$B/glsplay" "$t/terrain.glsb" --camera "$t/sd/rig.cam" --explain 2>/dev/null | grep -E '^GL_RENDERER:'
echo "date: $(date -u +%Y-%m-%d)"
echo
echo "glsplay frames per second, single pass, best of $REPEAT runs (whole run: start-up and upload included)."
echo "image: --outputs image (8-bit PNG, libspng level 1), writer thread; image, no thread: --writer-threads 0;"
echo "depth only: --outputs depth (PFM, no image file); stb: ${BE_BASELINE:-not measured (BE_BASELINE unset)}"
echo
echo "| sequence | image | image, no thread | depth only | stb, no thread (before) |"
echo "|---|---|---|---|---|"
ROAD="$t/road.glsb --trajectory $t/road/trajectory.txt --background 0.55,0.7,0.9"
TERRAIN="$t/terrain.glsb --trajectory $t/trajectory.txt"
row "road 640x480, $FRAMES frames" "$FRAMES" $ROAD --camera "$t/sd/left.cam"
row "road 1920x1080, $FRAMES_HD frames" "$FRAMES_HD" $ROAD --camera "$t/hd/left.cam"
row "terrain 640x480, $FRAMES frames" "$FRAMES" $TERRAIN --camera "$t/sd/rig.cam"
row "terrain 1920x1080, $FRAMES_HD frames" "$FRAMES_HD" $TERRAIN --camera "$t/hd/rig.cam"
echo
echo "one frame (frame 4) encoded, milliseconds (best of 5) and bytes; stb = stb_image_write (before),"
echo "spng-L-F = libspng at zlib level L, filter F (all: adaptive per row); the player uses spng-1-sub:"
echo
set --
for s in sd hd; do
    for sc in road terrain; do
        if [ $sc = road ]; then args="$ROAD --camera $t/$s/left.cam"; else args="$TERRAIN --camera $t/$s/rig.cam"; fi
        # shellcheck disable=SC2086
        "$B/glsplay" $args --frames 4:5 --outputs image --aa 1 -o "$t/f8_${sc}_$s" 2>/dev/null &&
            "$B/glsplay" $args --frames 4:5 --outputs image --aa 4 --image-format png16 -o "$t/f16_${sc}_$s" \
                2>/dev/null || exit 1
        set -- "$@" "$t"/f8_${sc}_$s/*/image_000004.png "$t"/f16_${sc}_$s/*/image_000004.png
    done
done
"$B/bench/png_bench" "$@" | sed "s|$t/f[0-9]*_||; s|/[a-z]*/image_000004.png||" |
    awk '{ printf "%-12s %-9s %-6s %-13s %8s ms %9s bytes\n", $1, $2, $3, $4, $5, $6 }'
echo
echo "load average (1 min, other work on the machine included): $load0 before, $(loadavg 1) after"
} >"$OUT"
cat "$OUT"
