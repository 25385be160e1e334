#!/bin/sh
# Render the demo road (examples/road/demo.road) as a short stereo sequence.
# usage: render.sh BIN OUTDIR [STRIP.png]
#
# glsplay follows the rig along trajectory.txt itself (--trajectory, with
# the rig cameras examples/road/rig/*.cam giving poses relative to the
# rig).  The other vehicles move, and a bundle is static, so each selected
# frame gets a small top-level scene placing them (vehicles.txt) around the
# road, compiled against the road precompiled once as a library, and
# glsplay renders just that frame (--frames F:F+1).  A sequence without
# moving vehicles needs no loop: one glsplay call renders every frame.
set -e
B=$1
OUT=$2
STRIP=$3
[ -n "$B" ] && [ -n "$OUT" ] || { echo "usage: render.sh BIN OUTDIR [STRIP.png]" >&2; exit 2; }
HERE=$(dirname "$0")
FRAMES=${ROAD_FRAMES:-"0 50 100 150 200 250 300 350"}
mkdir -p "$OUT"
"$B/glsroad" "$HERE/demo.road" -o "$OUT/road"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# the library bundle: road, its objects, the textures; each frame's scene
# is linked against it
"$B/glsc" -I "$B/scenelib.glsb" --lib "$OUT/road" -o "$tmp/road.glsb"
for f in $FRAMES; do
    # a top scene for this frame: the road and the vehicles where they are
    {
        echo 'call("road");'
        awk -v f="$f" '$1 == "#" && $2 == "vehicle" { obj[$3] = $5 }
            $1 !~ /^#/ && $1 == f {
            printf "push; transform(%s, %s, %s, %s, %s, %s, %s, %s, %s, %s, %s, %s, 0, 0, 0, 1); call(\"%s\"); pop;\n",
                $4, $5, $6, $13, $7, $8, $9, $14, $10, $11, $12, $15, obj[$3] }' "$OUT/road/vehicles.txt"
    } >"$tmp/Frame.scene"
    "$B/glsc" -I "$tmp" -I "$tmp/road.glsb" -I "$B/scenelib.glsb" -o "$tmp/frame.glsb" "$tmp/Frame.scene"
    "$B/glsplay" "$tmp/frame.glsb" --camera "$HERE/rig/left.cam" --camera "$HERE/rig/right.cam" \
        --trajectory "$OUT/road/trajectory.txt" --frames "$f:$((f + 1))" --background 0.55,0.7,0.9 -o "$OUT"
    echo "frame $f"
done
if [ -n "$STRIP" ]; then
    # four frames of the left camera, 300 px wide each (the PNG stays under
    # 300 KB: asphalt and grass textures compress poorly)
    set --
    i=0
    for f in $FRAMES; do
        [ $((i % 2)) -eq 0 ] && set -- "$@" "$OUT/left/image_$(printf '%06d' "$f").png"
        i=$((i + 1))
    done
    mkdir -p "$(dirname "$STRIP")"
    "$B/road_montage" "$STRIP" 4 300 "$@"
    echo "strip: $STRIP"
fi
echo "demo-road: frames in $OUT/left and $OUT/right (images, depth, points); road outputs in $OUT/road"
