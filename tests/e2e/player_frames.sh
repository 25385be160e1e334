#!/bin/sh
# glsplay over trajectories, the user's trial of issue 26: the trajectory
# read once (a pipe works as a file), checked whole whatever --frames
# asks for, frames asked for with no row named, no empty directory left
# by a run that fails or renders nothing, and every output at once.
# Prints ok/FAIL lines.
. tests/e2e/lib.sh
need_players player_frames

# A red square 10 units ahead of the world origin.
mkdir -p "$t/s"
cat >"$t/s/Sq.scene" <<'SCENE'
color(1, 0, 0);
poly { vert(-1, -1, 10); vert(1, -1, 10); vert(1, 1, 10); vert(-1, 1, 10); }
SCENE
"$BIN/glsc" -I "$t/s" -o "$t/sq.glsb" Sq || { fail player_frames_setup "scene does not compile"; exit 0; }
rig_cam "$t/cam.cam"
# the rig moves 0.1 unit forward a frame
row() { echo "$1 $1 1 0 0 0 1 0 0 0 1 0 0 -0.$1"; }
{ echo "# five frames"; for f in 0 1 2 3 4; do row $f; done; } >"$t/traj.txt"
PLAY="$BIN/glsplay $t/sq.glsb --camera $t/cam.cam --size 16x12"

sed 's/^pose rig$/pose rig\nshutter 0.5/' "$t/cam.cam" >"$t/blur.cam"

# a trajectory from a pipe is refused before anything is made, saying
# what it is (every input is a regular file: spec/camera.md); it used to
# be read twice, giving "no frames in the trajectory" and an empty
# directory
cat "$t/traj.txt" | $PLAY --outputs image --trajectory /dev/stdin -o "$t/pipe" 2>"$t/err_pipe"
rc_pipe=$?
if [ $rc_pipe -eq 1 ] && grep -q "/dev/stdin: error: cannot read: it is a FIFO (named pipe), not a regular file" "$t/err_pipe" &&
    [ "$(wc -l <"$t/err_pipe")" -eq 1 ] && [ ! -e "$t/pipe" ]; then
    ok trajectory_from_pipe
else
    fail trajectory_from_pipe "rc $rc_pipe: $(cat "$t/err_pipe"); $(ls -R "$t/pipe" 2>/dev/null | tr '\n' ' ')"
fi

# every output at once (19 files a camera frame, with edges' old name
# mask beside it): a rectified pair over a trajectory, each frame's files
# complete and recorded (frame 4, the last, writes no flow: 16 files)
mkdir -p "$t/pair"
cp "$t/cam.cam" "$t/pair/left.cam"
sed 's/^T 0 0 0$/T -0.5 0 0/' "$t/cam.cam" >"$t/pair/right.cam"
ALL=image,depth,points,edges,mask,disparity,disparity16,depth16,landmarks,instance,class,coco,normals,flow,boxes
"$BIN/glsplay" "$t/sq.glsb" --camera "$t/pair/left.cam" --camera "$t/pair/right.cam" --size 16x12 --aa 2 \
    --depth-scale 100 --outputs $ALL --trajectory "$t/traj.txt" -o "$t/all" 2>"$t/err"
rc=$?
n0=$(ls "$t/all/left" | grep -c '_000000\.')
n4=$(ls "$t/all/right" | grep -c '_000004\.')
if [ $rc -eq 0 ] && [ "$n0" -eq 19 ] && [ "$n4" -eq 16 ] && [ "$(ls "$t/all/left" | wc -l)" -eq 92 ] &&
    [ "$(ls "$t/all/right" | wc -l)" -eq 92 ] && [ -f "$t/all/left/.frame_000000.done" ] &&
    [ -f "$t/all/right/.frame_000004.done" ]; then
    ok every_output_at_once
else
    fail every_output_at_once "rc $rc, $n0 files of left's frame 0, $n4 of right's frame 4: $(cat "$t/err")"
fi

# --explain prints the plan the player runs (frame_plan.h): a camera
# with a shutter over a trajectory accumulates its sub-frame renders even
# at --aa 1, so no line may say "no accumulator" for it; the still
# camera beside it (right) draws 1 pass without one
$PLAY --camera "$t/blur.cam" --camera "$t/pair/right.cam" --aa 1 --trajectory "$t/traj.txt" --frames 1:4 \
    --explain >"$t/plan" 2>"$t/err"
rc=$?
blur=$(sed -n '/^camera blur:/,/^camera right:/p' "$t/plan")
still=$(sed -n '/^camera right:/,$p' "$t/plan")
if [ $rc -eq 0 ] && ! grep -q "^passes: " "$t/plan" &&
    echo "$blur" | grep -q "the image from an accumulator of 16 samples per pixel" &&
    echo "$blur" | grep -q "accumulator: 16 samples per pixel (anti-aliasing samples x sub-frame renders)" &&
    echo "$blur" | grep -q "frame plan: passes centre exposure" &&
    ! echo "$blur" | grep -q "no accumulator" && echo "$still" | grep -q "passes: 1 per camera and frame .*; no accumulator" &&
    echo "$blur" | grep -q "reads back (unjittered centre pass): colour (RGBA8) depth" &&
    echo "$still" | grep -q "reads back: colour (RGBA8) depth"; then
    ok explain_shutter_at_aa1_accumulates
else
    fail explain_shutter_at_aa1_accumulates "rc $rc: $(grep -n 'passes\|accumulator\|reads back' "$t/plan" | tr '\n' ' ') $(cat "$t/err")"
fi

# the whole file is checked whatever --frames asks for: rows 0, 7, 2 are
# refused under --frames 0:5 as without it, before anything is created
{ row 0; row 7; row 2; row 3; } >"$t/order.txt"
$PLAY --trajectory "$t/order.txt" --frames 0:5 -o "$t/order" 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "$t/order.txt:3: error: frame 2 does not follow frame 7: frames must increase" ] &&
    [ ! -e "$t/order" ]; then
    ok frames_range_checks_whole_file
else
    fail frames_range_checks_whole_file "rc $rc: $(cat "$t/err"); $(find "$t/order" 2>/dev/null | tr '\n' ' ')"
fi

# frames asked for by --frames with no row: one warning naming them, and
# the frames that have one rendered (exit 0)
{ row 0; row 1; row 2; } >"$t/three.txt"
EXACT_LINES=1
exact frames_without_rows_warned 0 "glsplay: warning: frames 3-4 asked for by --frames have no row in the trajectory $t/three.txt" -- \
    $PLAY --trajectory "$t/three.txt" --frames 0:5 -o "$t/three"
[ -f "$t/three/cam/image_000002.png" ] && [ "$(ls "$t/three/cam" | wc -l)" -eq 9 ] ||
    fail frames_without_rows_rendered "$(ls "$t/three/cam" | tr '\n' ' ')"
# rows with gaps, and a range past them: every run of missing frames named
# up to four, then counted; a single frame said as one
{ row 0; row 2; row 6; row 8; row 10; } >"$t/gaps.txt"
exact frames_without_rows_gaps 0 "glsplay: warning: frames 1, 3-5 and 7 asked for by --frames have no row in the trajectory $t/gaps.txt" -- \
    $PLAY --trajectory "$t/gaps.txt" --frames 0:9 -o "$t/gaps"
exact frames_without_rows_one 0 "glsplay: warning: frame 7 asked for by --frames has no row in the trajectory $t/gaps.txt" -- \
    $PLAY --trajectory "$t/gaps.txt" --frames 6:9 -o "$t/gaps"
exact frames_without_rows_many 0 "glsplay: warning: frames 1, 3-5, 7, 9, ... (16 frames in 5 runs) asked for by --frames have no row in the trajectory $t/gaps.txt" -- \
    $PLAY --trajectory "$t/gaps.txt" --frames 1:21 -o "$t/gaps"
# none of them has a row: an error (exit 1), no warning beside it
exact frames_without_any_row 1 "glsplay: error: $t/three.txt: no frame in the range given by --frames" -- \
    $PLAY --trajectory "$t/three.txt" --frames 3:5 -o "$t/none"
# --frames A: asks for nothing past the file's last row
exact frames_open_end_no_warning 0 "" -- $PLAY --trajectory "$t/three.txt" --frames 1: -o "$t/three"

# a run that fails or renders nothing leaves no directory it made (-o
# d16/new made both), and leaves alone those that were there: depth16 refused by the writer (10
# units at --depth-scale 10000 is over 65535), --shard 5/8 of 5 frames
PAIR="$BIN/glsplay $t/sq.glsb --camera $t/pair/left.cam --camera $t/pair/right.cam"
$PAIR --outputs depth16 --depth-scale 10000 --trajectory "$t/traj.txt" -o "$t/d16/new" 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && grep -q "depth16: camera .* is over" "$t/err" && [ ! -e "$t/d16" ]; then
    ok failed_run_leaves_no_directory
else
    fail failed_run_leaves_no_directory "rc $rc: $(cat "$t/err"); $(find "$t/d16" | tr '\n' ' ')"
fi
mkdir -p "$t/keep/left"
$PAIR --outputs depth16 --depth-scale 10000 --trajectory "$t/traj.txt" -o "$t/keep" 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ -d "$t/keep/left" ] && [ ! -e "$t/keep/right" ] && [ -z "$(ls "$t/keep/left")" ]; then
    ok failed_run_keeps_directories_there_before
else
    fail failed_run_keeps_directories_there_before "rc $rc: $(find "$t/keep" | tr '\n' ' ')"
fi
$PAIR --trajectory "$t/traj.txt" --shard 5/8 -o "$t/shard" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "nothing to render" "$t/err" && [ ! -e "$t/shard" ]; then
    ok empty_shard_leaves_no_directory
else
    fail empty_shard_leaves_no_directory "rc $rc: $(cat "$t/err"); $(find "$t/shard" 2>/dev/null | tr '\n' ' ')"
fi

# the frame record keys on the frame's plan (runtime/play/frame_plan.h):
# the trajectory's last frame writes no flow (there is no next row), so
# its record does not list flow while the others do; --resume then finds
# every frame complete, the last one included
$PLAY --outputs image,flow --trajectory "$t/traj.txt" --frames 2: -o "$t/rec" 2>"$t/err"
rc=$?
first=$(grep '^outputs' "$t/rec/cam/.frame_000002.done" 2>/dev/null)
last=$(grep '^outputs' "$t/rec/cam/.frame_000004.done" 2>/dev/null)
$PLAY --outputs image,flow --trajectory "$t/traj.txt" --frames 2: -o "$t/rec" --resume 2>"$t/err2"
rc2=$?
if [ $rc -eq 0 ] && [ "$first" = "outputs image flow" ] && [ "$last" = "outputs image" ] && [ $rc2 -eq 0 ] &&
    grep -q "3 of 3 frames complete, skipped; 0 to render" "$t/err2"; then
    ok frame_record_keys_on_plan
else
    fail frame_record_keys_on_plan "rc $rc/$rc2; first '$first', last '$last': $(cat "$t/err" "$t/err2")"
fi
