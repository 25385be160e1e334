#!/bin/sh
# Cost of anisotropic texture filtering (glsplay --anisotropic N) on
# llvmpipe: seconds for one whole glsplay run rendering one 640x480 frame
# of the road demo (examples/road/demo.road, frame 4, right rig camera,
# image only), with filtering off (the default; best of 3) and at each N
# in ANISO_NS (default 16; one run each, as each takes minutes).  Prints a
# markdown table; make bench-aa (bench/aa.sh) appends it to
# docs/benchmarks.md.
B=${1:-build}
NS=${ANISO_NS:-16}
FRAME=${ANISO_FRAME:-4}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$B/glsroad" examples/road/demo.road -o "$tmp/road" >/dev/null &&
    "$B/glsc" -I "$tmp/road" -I "$B/scenelib.glsb" -o "$tmp/road.glsb" "$tmp/road/road.scene" || exit 1
# secs N: wall-clock seconds of one render with --anisotropic N
secs() {
    /usr/bin/time -f %e -o "$tmp/time" "$B/glsplay" "$tmp/road.glsb" --camera examples/road/rig/right.cam \
        --trajectory "$tmp/road/trajectory.txt" --frames "$FRAME:$((FRAME + 1))" --outputs image \
        --anisotropic "$1" --aa 1 -o "$tmp/out" || exit 1
    cat "$tmp/time"
}
off=$( (secs 1; secs 1; secs 1) | sort -n | head -1)
printf '| anisotropic filtering | s/frame | x off |\n|---|---|---|\n'
printf '| off (default) | %.2f | 1 |\n' "$off"
for n in $NS; do
    s=$(secs "$n")
    printf '| --anisotropic %s | %.1f | %.0f |\n' "$n" "$s" "$(echo "$s / $off" | bc -l)"
done
