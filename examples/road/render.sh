#!/bin/sh
# Render the demo road (examples/road/demo.road) as a short stereo sequence.
# usage: render.sh BIN OUTDIR [STRIP.png]
#
# Three commands: glsroad writes the road scene, the rig's trajectory and
# one motion file per vehicle (motion/NAME.txt); glsc compiles the scene,
# in which each vehicle is a named instance; glsplay follows the rig along
# the trajectory (--trajectory, with the rig cameras examples/road/rig/*.cam
# giving poses relative to the rig) and moves each vehicle along its motion
# file (--motion NAME=FILE).  The selected frames are the trajectory's
# lines for them (a trajectory may hold a selection of frames).  A fourth
# command renders a clip of consecutive frames (ROAD_CLIP, default
# 200:203) with optical flow and object boxes into OUTDIR/clip.
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
awk -v frames=" $FRAMES " '/^#/ || index(frames, " " $1 " ")' "$OUT/road/trajectory.txt" >"$tmp/trajectory.txt"
CAMS="--camera $HERE/rig/left.cam --camera $HERE/rig/right.cam"
"$B/glsc" -I "$OUT/road" -I "$B/scenelib.glsb" -o "$OUT/road.glsb" "$OUT/road/road.scene"
set --
for m in "$OUT"/road/motion/*.txt; do
    [ -f "$m" ] && set -- "$@" --motion "$(basename "$m" .txt)=$m"
done
"$B/glsplay" "$OUT/road.glsb" $CAMS --trajectory "$tmp/trajectory.txt" "$@" --outputs image,depth,points,landmarks \
    --background 0.55,0.7,0.9 -o "$OUT"
# optical flow and boxes on a short clip of consecutive frames (flow goes
# from each frame to the trajectory's next line, so the whole trajectory):
# OUTDIR/clip/left and right, with the vehicles moving
CLIP=${ROAD_CLIP:-200:203}
"$B/glsplay" "$OUT/road.glsb" $CAMS --trajectory "$OUT/road/trajectory.txt" "$@" --frames "$CLIP" \
    --outputs image,depth,flow,boxes,instance,normals,landmarks --background 0.55,0.7,0.9 -o "$OUT/clip"
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
echo "demo-road: frames in $OUT/left and $OUT/right (images, depth, points, landmarks); road outputs in $OUT/road"
echo "demo-road: frames $CLIP with flow, boxes, instance ids, normals and landmarks in $OUT/clip/left and $OUT/clip/right"
