#!/bin/sh
# The road example writes flow and boxes (examples/road/render.sh: a clip
# of consecutive frames with the vehicles moving, OUTDIR/clip):
# tests/py/check_road_flow.py reprojects every static pixel's depth along
# the trajectory (outside the moving vehicles' boxes) and checks that the
# vehicles' pixels move otherwise, the KITTI PNG and the label lines.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
if ROAD_FRAMES=200 ROAD_CLIP=200:202 sh examples/road/render.sh "$B" "$t/out" >"$t/log" 2>&1; then
    echo "ok road_example_flow_render"
    /usr/bin/python3 tests/py/check_road_flow.py "$t/out" examples/road/rig 200 202
else
    echo "FAIL road_example_flow_render: $(tail -3 "$t/log" | tr '\n' ' ')"
fi
