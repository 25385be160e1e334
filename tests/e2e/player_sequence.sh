#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# glsplay over sequences: --trajectory, --frames, --resume, --frame,
# --background; memory over 10,000 frames.  Prints ok/FAIL lines.
. tests/e2e/lib.sh
tmp=$t

# A small scene: a red square 10 units ahead of the world origin.
mkdir -p "$tmp/s"
cat >"$tmp/s/Sq.scene" <<'SCENE'
color(1, 0, 0);
poly { vert(-1, -1, 10); vert(1, -1, 10); vert(1, 1, 10); vert(-1, 1, 10); }
SCENE
"$BIN/glsc" -I "$tmp/s" -o "$tmp/sq.glsb" Sq || { fail sequence_setup "scene does not compile"; exit 0; }
# the rig camera: at the rig origin, looking along the rig's +z
rig_cam "$tmp/cam.cam"
# the rig moves 1 unit forward per frame (T = -R C with R = I)
{
    echo "# test trajectory"
    for f in 0 1 2 3 4; do echo "$f $f 1 0 0 0 1 0 0 0 1 0 0 -$f"; done
} >"$tmp/traj.txt"

"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --frames 1:4 -o "$tmp/seq" 2>"$tmp/err"
if [ -f "$tmp/seq/cam/image_000001.png" ] && [ -f "$tmp/seq/cam/image_000003.png" ] && [ ! -e "$tmp/seq/cam/image_000000.png" ] &&
    [ ! -e "$tmp/seq/cam/image_000004.png" ]; then
    ok trajectory_frames_range
else
    fail trajectory_frames_range "$(cat "$tmp/err"; ls "$tmp/seq/cam" 2>/dev/null | tr '\n' ' ')"
fi

# frame 2 of the trajectory == a single render from a camera file holding
# the composed pose (camera 2 units forward), numbered with --frame 2
sed 's/^T 0 0 0$/T 0 0 -2/; s/^pose rig$/pose world/' "$tmp/cam.cam" >"$tmp/cam2.cam"
mkdir -p "$tmp/single"
cp "$tmp/cam2.cam" "$tmp/single/cam.cam"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/single/cam.cam" --frame 2 -o "$tmp/one" 2>>"$tmp/err"
if cmp -s "$tmp/one/cam/image_000002.png" "$tmp/seq/cam/image_000002.png" &&
    cmp -s "$tmp/one/cam/depth_000002.pfm" "$tmp/seq/cam/depth_000002.pfm" &&
    ! cmp -s "$tmp/seq/cam/depth_000001.pfm" "$tmp/seq/cam/depth_000002.pfm"; then
    ok trajectory_pose_matches_single_render
else
    fail trajectory_pose_matches_single_render "frame 2 differs from the composed single render, or frames do not move"
fi

# --resume: complete frames are skipped (untouched), missing ones rendered
rm "$tmp/seq/cam/depth_000002.pfm"
touch -d '2000-01-01' "$tmp/seq/cam/image_000001.png" "$tmp/seq/cam/image_000002.png"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --resume -o "$tmp/seq" 2>>"$tmp/err"
old1=$(find "$tmp/seq/cam/image_000001.png" -newermt '2001-01-01' | wc -l)
new2=$(find "$tmp/seq/cam/image_000002.png" -newermt '2001-01-01' | wc -l)
if [ "$old1" = 0 ] && [ "$new2" = 1 ] && [ -f "$tmp/seq/cam/depth_000002.pfm" ] && [ -f "$tmp/seq/cam/image_000000.png" ] &&
    [ -f "$tmp/seq/cam/points_000004.ply" ]; then
    ok resume_skips_complete_frames
else
    fail resume_skips_complete_frames "frame 1 rewritten=$old1, frame 2 rewritten=$new2"
fi

# a re-render that fails part way leaves frame 2 with a new image beside
# the old depth and points; --resume must not take that frame as complete.
# The failure: a file-size limit (4 KiB) kills glsplay (SIGXFSZ) while it
# writes the depth map, after the (small) image.
sed 's/^poly { vert(-1, -1, 10)/poly { vert(-1.5, -1, 10)/' "$tmp/s/Sq.scene" >"$tmp/s/Sq2.scene"
"$BIN/glsc" -I "$tmp/s" -o "$tmp/sq2.glsb" Sq2 || fail resume_setup "second scene does not compile"
# (in a shell of its own, whose stderr takes the shell's report of the signal)
sh -c 'ulimit -f 8; "$@"' sh "$BIN/glsplay" "$tmp/sq2.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" \
    --frames 2:3 -o "$tmp/seq" 2>/dev/null
rm -f "$tmp"/seq/cam/*.tmp*
if ! cmp -s "$tmp/seq/cam/image_000002.png" "$tmp/one/cam/image_000002.png" &&
    cmp -s "$tmp/seq/cam/depth_000002.pfm" "$tmp/one/cam/depth_000002.pfm"; then
    "$BIN/glsplay" "$tmp/sq2.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --frames 2:3 --resume \
        -o "$tmp/seq" 2>>"$tmp/err"
    "$BIN/glsplay" "$tmp/sq2.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --frames 2:3 -o "$tmp/fresh" \
        2>>"$tmp/err"
    if cmp -s "$tmp/seq/cam/depth_000002.pfm" "$tmp/fresh/cam/depth_000002.pfm" &&
        cmp -s "$tmp/seq/cam/points_000002.ply" "$tmp/fresh/cam/points_000002.ply"; then
        ok resume_rejects_partly_rewritten_frame
    else
        fail resume_rejects_partly_rewritten_frame "--resume kept the old depth/points beside the new image"
    fi
else
    fail resume_rejects_partly_rewritten_frame "the interrupted render did not leave a new image and the old depth"
fi

# --resume with another image format (or other outputs) does not take the
# frames rendered before as complete
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --frames 0:2 --outputs image \
    -o "$tmp/fmt" 2>>"$tmp/err"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --frames 0:2 --outputs image \
    --image-format png16 --resume -o "$tmp/fmt" 2>>"$tmp/err"
# the IHDR bit depth, byte 25 of a PNG
depth0=$(od -An -tu1 -j24 -N1 "$tmp/fmt/cam/image_000000.png" | tr -d ' ')
depth1=$(od -An -tu1 -j24 -N1 "$tmp/fmt/cam/image_000001.png" | tr -d ' ')
[ "$depth0" = 16 ] && [ "$depth1" = 16 ] && ok resume_checks_image_format ||
    fail resume_checks_image_format "bit depths after --resume --image-format png16: $depth0 $depth1"

# frame-level progress: only on a terminal, or with --progress; --resume
# says how many frames it skips
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" -o "$tmp/prog" 2>"$tmp/perr"
[ ! -s "$tmp/perr" ] && ok progress_not_on_a_file || fail progress_not_on_a_file "$(cat "$tmp/perr")"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --progress -o "$tmp/prog" \
    2>"$tmp/perr"
# (lines between are at most two a second: five small frames may show none)
if [ "$(head -c 1 "$tmp/perr")" = "$(printf '\r')" ] &&
    tr '\r' '\n' <"$tmp/perr" | tail -1 | grep -q '^glsplay: 5 frames in [0-9. a-z]*, [0-9.]* frames/s *$'; then
    ok progress_frames
else
    fail progress_frames "$(od -c "$tmp/perr" | head -5)"
fi
rm "$tmp/prog/cam/image_000003.png"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --resume -o "$tmp/prog" \
    2>"$tmp/perr"
[ "$(cat "$tmp/perr")" = "glsplay: note: --resume: 4 of 5 frames complete, skipped; 1 to render" ] &&
    [ -f "$tmp/prog/cam/image_000003.png" ] && ok resume_says_what_it_skips ||
    fail resume_says_what_it_skips "$(cat "$tmp/perr")"

# a sequence projected beyond a minute says so first: a million frames
# (over a minute at any speed; the projection is made on the frames done
# in the first half second), stopped once the note is there
awk 'BEGIN { for (i = 0; i < 1000000; i++) printf "%d %d 1 0 0 0 1 0 0 0 1 0 0 %.4f\n", i, i, -i * 0.0001 }' \
    >"$tmp/million.txt"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --size 8x6 --outputs image --trajectory "$tmp/million.txt" \
    -o "$tmp/million" 2>"$tmp/merr" &
pid=$!
i=0
while [ $i -lt 240 ] && ! grep -q "estimated render time" "$tmp/merr"; do sleep 0.25; i=$((i + 1)); done
kill "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
rm -rf "$tmp/million" "$tmp/million.txt"
grep -q '^glsplay: note: estimated render time [0-9a-z ]*: 1000000 camera frames x [0-9.]* [mu]*s (measured on the first [0-9]*)$' \
    "$tmp/merr" && ok estimate_before_long_sequence || fail estimate_before_long_sequence "$(cat "$tmp/merr")"

# --background: uncovered pixels get the colour; depth stays +inf there
mkdir -p "$tmp/world"
sed 's/^pose rig$/pose world/' "$tmp/cam.cam" >"$tmp/world/cam.cam"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/world/cam.cam" --background 0,0.5,1 -o "$tmp/bg" 2>>"$tmp/err"
if /usr/bin/python3 - "$tmp/bg/cam" <<'PY'
import sys, cv2, numpy as np
d = sys.argv[1]
img = cv2.imread(d + "/image_000000.png")          # BGR
z = cv2.imread(d + "/depth_000000.pfm", cv2.IMREAD_UNCHANGED)
corner, centre = img[0, 0], img[24, 32]
ok = tuple(corner) == (255, 128, 0) and tuple(centre) == (0, 0, 255)
ok = ok and np.isinf(z[0, 0]) and abs(z[24, 32] - 10) < 1e-4
sys.exit(0 if ok else 1)
PY
then ok background_colour; else fail background_colour "corner or centre pixel wrong"; fi

# errors: a malformed trajectory line, --frames without --trajectory
{ echo "0 0 1 0 0 0 1 0 0 0 1 0 0 0"; echo "1 0.5 1 0 0 0 1 0 0 0 1 0 0"; } >"$tmp/bad.txt"
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/bad.txt" -o "$tmp/badout" 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q "bad.txt:2: error:" "$tmp/err"; then ok trajectory_error_located; else fail trajectory_error_located "rc=$rc $(cat "$tmp/err")"; fi
# the trajectory is checked whole before anything is created: no empty
# per-camera directory is left behind
if [ ! -e "$tmp/badout" ]; then ok trajectory_error_creates_nothing; else fail trajectory_error_creates_nothing "$(find "$tmp/badout")"; fi
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --frames 1:2 -o "$tmp/x" 2>/dev/null; rc=$?
if [ $rc -eq 2 ]; then ok frames_needs_trajectory; else fail frames_needs_trajectory "rc=$rc"; fi

# memory stays flat: peak RSS over 10,000 frames is within 8 MiB of the
# peak over 100 frames (tiny images, image output only).  Not under ASan,
# whose quarantine keeps freed memory on purpose (GLS_SANITIZED=1).
[ "$GLS_SANITIZED" = 1 ] && exit 0
{ f=0; while [ $f -lt 10000 ]; do echo "$f $f 1 0 0 0 1 0 0 0 1 0 0 -0.0001"; f=$((f + 1)); done; } >"$tmp/long.txt"
rss() {
    /usr/bin/time -f %M "$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --size 8x6 --outputs image \
        --trajectory "$tmp/long.txt" --frames "0:$1" -o "$tmp/long$1" 2>&1 >/dev/null | tail -1
}
r100=$(rss 100)
r10k=$(rss 10000)
n10k=$(ls "$tmp/long10000/cam" | wc -l)
if [ "$n10k" = 10000 ] && [ $((r10k - r100)) -lt 8192 ]; then
    ok memory_flat_over_10k_frames
    echo "  peak RSS: 100 frames ${r100} KiB, 10000 frames ${r10k} KiB"
else
    fail memory_flat_over_10k_frames "100 frames ${r100} KiB, 10000 frames ${r10k} KiB, $n10k images"
fi
