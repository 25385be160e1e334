#!/bin/sh
# glsplay --outputs flow (spec/outputs.md "Optical flow"): the scene of
# tests/py/flow_scene.py (a wall, a floor, a box moved by --motion, a box
# that stays) along a trajectory that moves and yaws the rig;
# tests/py/check_flow.py compares the .flo, the KITTI PNG and the mask
# with geometry computed in numpy.  Here: the last frame, the refusals,
# --aa, --resume and --frames.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
$PY tests/py/flow_scene.py "$t" || { fail flow_scene "cannot write the scene"; exit 0; }
"$B/glsc" -I "$B/scenelib.glsb" -o "$t/f.glsb" "$t/Flow.scene" 2>"$t/err" || { fail flow_compile "$(cat "$t/err")"; exit 0; }
PLAY="$B/glsplay $t/f.glsb --camera $t/cam.cam"
MOT="--motion mover=$t/mover.txt"
note="glsplay: note: frame 2 is the last of $t/trajectory.txt: no flow from it (flow goes from a frame to the next)"
exact flow_last_frame_note 0 "$note" -- $PLAY --trajectory "$t/trajectory.txt" $MOT --outputs depth,flow -o "$t/o"
$PY tests/py/check_flow.py "$t/o"
if [ -f "$t/o/cam/flow_000001.flo" ] && [ ! -e "$t/o/cam/flow_000002.flo" ] && [ ! -e "$t/o/cam/flow_000002.png" ] &&
    [ ! -e "$t/o/cam/flowmask_000002.png" ] && [ -f "$t/o/cam/depth_000002.pfm" ]; then
    ok flow_none_for_last_frame
else
    fail flow_none_for_last_frame "$(ls "$t/o/cam" | tr '\n' ' ')"
fi

# ground truth is never blended: the same files with --aa
$PLAY --trajectory "$t/trajectory.txt" $MOT --outputs image,flow --aa 3 -o "$t/aa" 2>/dev/null
same=1
for f in flow_000000.png flow_000000.flo flowmask_000000.png flow_000001.flo; do
    cmp -s "$t/o/cam/$f" "$t/aa/cam/$f" || same=0
done
[ $same = 1 ] && ok flow_same_with_aa || fail flow_same_with_aa "flow files differ with --aa 3"

# --resume: the last frame is complete without flow files
exact flow_resume_complete 0 "glsplay: note: --resume: 3 of 3 frames complete, skipped; 0 to render" -- \
    $PLAY --trajectory "$t/trajectory.txt" $MOT --outputs depth,flow -o "$t/o" --resume

# --frames ending before the trajectory does: the range's last frame has flow
# to the next row, the same as in the whole run
$PLAY --trajectory "$t/trajectory.txt" $MOT --outputs depth,flow --frames 0:1 -o "$t/r" 2>"$t/err"
if cmp -s "$t/o/cam/flow_000000.flo" "$t/r/cam/flow_000000.flo" && [ ! -s "$t/err" ]; then
    ok flow_frames_range_next_row
else
    fail flow_frames_range_next_row "$(cat "$t/err")"
fi
# ... whose motions must have a row for that next frame
head -2 "$t/mover.txt" >"$t/short.txt"
exact flow_next_frame_motion_checked 1 \
    "glsplay: error: $t/short.txt: no row for frame 2 (the motion of instance mover)" -- \
    $PLAY --trajectory "$t/trajectory.txt" --motion "mover=$t/short.txt" --outputs flow --frames 0:2 -o "$t/s"
[ ! -e "$t/s/cam/flow_000000.flo" ] && ok flow_next_frame_motion_nothing_written ||
    fail flow_next_frame_motion_nothing_written "$(ls "$t/s/cam")"

# flow needs a trajectory
exact flow_needs_trajectory 2 \
    "glsplay: error: --outputs flow needs a --trajectory: the flow goes from each frame to the next (try glsplay --help)" -- \
    $PLAY --outputs image,flow -o "$t/u"
[ ! -e "$t/u" ] && ok flow_needs_trajectory_writes_nothing || fail flow_needs_trajectory_writes_nothing "$(ls -R "$t/u")"

# a flow KITTI's PNG cannot hold (beyond 512 px) is refused before any file
# of that camera frame is written: the rig jumps 40 m sideways in front of
# the wall 20 m away, so every wall pixel moves fx * 40 / 20 = 600 px; the
# first one still in view is (600, 45): the wall's top y = -5 is at
# v = cy - fy * 5 / 20 = 44.5
printf '# glsroad trajectory 1\n0 0 1 0 0 0 1 0 0 0 1 0 0 0\n1 1 1 0 0 0 1 0 0 0 1 -40 0 0\n' >"$t/jump.txt"
sed 's/^width 320/width 1200/' "$t/cam.cam" >"$t/wide.cam"
exact flow_kitti_range_refused 1 \
    "glsplay: error: camera wide, frame 0: the flow at pixel (600, 45) moves -600.00 px along u, beyond the -512..512 px a KITTI flow PNG holds; leave out flow or move less between frames" -- \
    "$B/glsplay" "$t/f.glsb" --camera "$t/wide.cam" --trajectory "$t/jump.txt" --outputs image,flow -o "$t/j"
[ -z "$(ls "$t/j/wide" 2>/dev/null)" ] && ok flow_kitti_range_nothing_written ||
    fail flow_kitti_range_nothing_written "$(ls "$t/j/wide")"

# --explain says what flow costs
$PLAY --trajectory "$t/trajectory.txt" $MOT --outputs flow --explain >"$t/plan" 2>&1
grep -q "^  flow: 1 more centre pass (the depth of frame t+1 with its poses)" "$t/plan" &&
    ok flow_explain || fail flow_explain "$(tail -3 "$t/plan")"
