#!/bin/sh
# End-to-end tests of glsroad: the CLI, description errors, outputs that
# glsc compiles, poses checked with OpenCV, --camera-at composition.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
R=$B/glsroad
[ -x "$R" ] || { fail road_cli "no $R"; exit 0; }

# expect NAME STATUS EXACT-STDERR-LINE -- command...  (a command that hangs
# fails with status 124)
expect() {
    name=$1 want=$2 msg=$3
    shift 4
    timeout 120 "$@" >"$t/stdout" 2>"$t/stderr"
    rc=$?
    if [ $rc -ne "$want" ]; then fail "$name" "exit $rc, wanted $want: $(cat "$t/stderr")"
    elif [ -n "$msg" ] && [ "$(head -1 "$t/stderr")" != "$msg" ]; then fail "$name" "stderr '$(head -1 "$t/stderr")', wanted '$msg'"
    else ok "$name"; fi
}

expect road_usage_no_args 2 "glsroad: error: no road description given" -- "$R"
expect road_usage_no_output 2 "glsroad: error: no output directory: give -o DIR" -- "$R" examples/road/demo.road
expect road_usage_unknown_option 2 "glsroad: error: unknown option '--frobnicate'" -- "$R" --frobnicate
expect road_help 0 "" -- "$R" --help
# an empty path names nothing: the command line alone is wrong, exit 2
# (spec/exit_status.md), where it was 1 after trying to open it
expect road_usage_empty_output 2 "glsroad: error: -o needs a non-empty directory" -- "$R" examples/road/demo.road -o ""
expect road_usage_empty_description 2 "glsroad: error: an empty road description name" -- "$R" "" -o "$t/empty"
expect road_usage_camera_at_empty 2 "glsroad: error: --camera-at: an empty camera file name" -- \
    "$R" --camera-at 0 examples/road/trajectory.txt ""
expect road_missing_file 1 "$t/none.road: error: cannot open: No such file or directory" -- "$R" "$t/none.road" -o "$t/o"
# -o creates missing parent directories, like glsc -o and glsplay -o
expect road_output_parents_created 0 "" -- "$R" examples/road/demo.road -o "$t/new/sub/road"
[ -s "$t/new/sub/road/road.scene" ] || fail road_output_parents_created "no $t/new/sub/road/road.scene"

# description errors: FILE:LINE:COL: error: message (then the source line
# and a caret, checked once below), exit 1
err_case() {
    name=$1 text=$2 msg=$3
    printf '%b' "$text" >"$t/$name.road"
    expect "road_error_$name" 1 "$t/$name.road:$msg" -- "$R" "$t/$name.road" -o "$t/o_$name"
    [ -e "$t/o_$name" ] && fail "road_error_${name}_writes_nothing" "output directory created"
}
P='point 0 0 0\npoint 0 0 50\npoint -10 0 100\npoint -10 0 150\n'
S='speed_at distance 0 10\n'
err_case unknown_key "${P}${S}lane_widht 3\n" "6:1: error: unknown key 'lane_widht'; did you mean 'lane_width'?"
err_case bad_number "${P}${S}tolerance 1mm\n" "6:11: error: tolerance: '1mm' is not a finite number"
err_case few_points "point 0 0 0\npoint 0 0 1\n${S}" "1:1: error: a curve of degree 3 needs at least 4 control points; there are 2"
err_case knots_count "${P}knots 0 0 0 0 1 1 1\n${S}" "5:1: error: 7 knots given; 4 points of degree 3 need 8"
err_case knots_unclamped "${P}knots 0 0 0 0.5 1 1 1 1\n${S}" "5:1: error: the knot vector must be clamped: its first and last degree + 1 knots equal"
err_case weight_zero "point 0 0 0 0\n" "1:13: error: weight must be positive, got 0"
err_case no_speed "${P}" "4:1: error: no speed profile: give at least one 'speed_at distance 0 SPEED' (m/s)"
err_case speed_mixed "${P}${S}speed_at time 5 10\n" "6:1: error: a speed profile is given either by distance or by time, not both"
err_case speed_order "${P}${S}speed_at distance 50 10\nspeed_at distance 20 12\n" "7:1: error: profile points must have increasing distances (20 after 50)"
err_case boundary "${P}${S}marking 3 solid\n" "6:1: error: boundary 3 does not exist: 2 lanes have boundaries 0..2 (0 is the leftmost)"
err_case style "${P}${S}marking 1 dotted\n" "6:11: error: 'marking': unexpected 'dotted' (options: solid, dashed, double, none)"
err_case too_far "${P}${S}frames 1000\n" "6:1: error: the vehicle passes the end of the road (150.399 m) at frame 376 (t = 15.04 s); give fewer frames, a lower speed or a longer road"
err_case vehicle_unknown "${P}${S}vehicle_speed bus distance 0 10\n" "6:15: error: unknown vehicle 'bus' (define it with a 'vehicle' line first)"

# every key's errors come from one table (roads/road_keys.c) and read alike
# (spec/road.md, "The description"): the count of values with the key's
# values, a key given twice or with one it excludes, a value out of its
# range at the value's column, a word that is none of the options
err_case arity_point "${P}${S}point 1 2\n" "6:1: error: 'point' takes 3 to 4 values (x y z [w]), got 2"
err_case arity_colour "${P}${S}road_color 1 1\n" "6:1: error: 'road_color' takes 3 values (r g b in 0..1), got 2"
err_case arity_speed "${P}speed_at 0 10\n" "5:1: error: 'speed_at' takes 3 values (distance X V | time T V), got 2"
err_case arity_trees "${P}${S}trees 10\n" "6:1: error: 'trees' takes at least 2 values (EVERY OFFSET [left|right|both] [start S] [object NAME]), got 1"
err_case arity_knots "${P}${S}knots 0\n" "6:1: error: 'knots' takes at least 2 values (the knot vector: points + p + 1 numbers), got 1"
err_case arity_one "${P}${S}lanes 2 3\n" "6:1: error: 'lanes' takes 1 value (1..16), got 2"
err_case twice "${P}${S}degree 3\ndegree 2\n" "7:1: error: 'degree' given twice (first on line 6)"
err_case twice_frames "${P}${S}frames 10\nframes 20\n" "7:1: error: 'frames' given twice (first on line 6)"
err_case twice_vehicle "${P}${S}vehicle a\nvehicle_speed a distance 0 1\nvehicle a\n" "8:1: error: 'vehicle a' given twice (first on line 6)"
# a setting given again replaces the earlier line's value (spec/road.md:
# "the last counts"), as it always has
printf '%b' "${P}${S}lanes 3\nmarking 1 solid\nmarking 1 double\nlanes 2\n" >"$t/again.road"
if "$R" "$t/again.road" -o "$t/o_again" >"$t/stdout" 2>"$t/stderr" && grep -q '^# boundary 1 double$' "$t/o_again/lanes.txt" &&
    grep -q '^# boundary 2 solid$' "$t/o_again/lanes.txt" && ! grep -q '^# boundary 3' "$t/o_again/lanes.txt"; then
    ok road_setting_again_last_counts
else
    fail road_setting_again_last_counts "$(cat "$t/stderr")"
fi
err_case excludes_width "${P}${S}lane_width 3\nlane_width_at 0 3\n" "7:1: error: give either 'lane_width' or 'lane_width_at', not both ('lane_width' is on line 6)"
err_case excludes_frames "${P}${S}duration 2\nframes 10\n" "7:1: error: give either 'frames' or 'duration', not both ('duration' is on line 6)"
err_case range_bank "${P}${S}bank_max 0.7\n" "6:10: error: bank_max must be 0..0.5 (a cross slope, rise over run), got 0.7"
err_case range_tolerance "${P}${S}tolerance 1e-7\n" "6:11: error: tolerance must be at least 1e-06 (a micrometre: finer is beyond what the tessellation can meet), got 1e-7"
err_case range_colour "${P}${S}road_color 0.5 1.5 0\n" "6:16: error: colour component must be 0..1, got 1.5"
err_case range_angle "${P}${S}rig_pitch -200\n" "6:11: error: rig_pitch must be -180..180 (degrees), got -200"
err_case range_speed "${P}speed_at distance 0 0\n" "5:21: error: speed must be positive (by distance: the vehicle could never pass a point of speed 0), got 0"
err_case word_speed "${P}speed_at speed 0 10\n" "5:10: error: 'speed_at': unexpected 'speed' (options: distance, time)"
err_case option_trees "${P}${S}trees 10 2 middle\n" "6:12: error: 'trees': unexpected 'middle' (options: left, right, both, start S, object NAME)"
# errors across lines point at the key of the line that can fix them;
# something missing, at the first word of the last line
err_case missing_at_last_key "${P}  fps 25\n" "5:3: error: no speed profile: give at least one 'speed_at distance 0 SPEED' (m/s)"
err_case across_at_key "  point 0 0 0\n  point 0 0 1\n${S}" "1:3: error: a curve of degree 3 needs at least 4 control points; there are 2"
# the curve's own errors are located errors too, with the line and a caret
printf '%b' "point 0 0 0\npoint 0 0 0\npoint 0 0 0\npoint 0 0 0\n${S}" >"$t/tangent.road"
"$R" "$t/tangent.road" -o "$t/o_tangent" 2>"$t/stderr"
if [ "$(head -1 "$t/stderr")" = "$t/tangent.road:1:1: error: the curve has a zero or undefined tangent near u = 0 (coincident control points?)" ] &&
    [ "$(sed -n 2p "$t/stderr")" = "point 0 0 0" ] && [ "$(sed -n 3p "$t/stderr")" = "^" ]; then
    ok road_error_tangent_excerpt
else
    fail road_error_tangent_excerpt "$(cat "$t/stderr")"
fi
err_case fold "degree 2\npoint 0 0 0\npoint 0 0 10\npoint -8 0 10 0.7071067811865476\npoint -8 0 0\nknots 0 0 0 0.5 1 1 1\nverge 0\n${S}" " error: the road folds over itself near distance 8.981 m: the curve radius there (3.921 m) is smaller than the lateral offset of an edge (4.000 m); widen the curve or narrow the road"


# computed counts are checked before anything is generated (spec/road.md,
# "Limits"), at the key to change: none of these may run long or exhaust
# memory (before the checks, fps 1e200 ran until memory ran out)
err_case frames_product "${P}${S}fps 1e6\nduration 100\n" "7:1: error: duration 100 s at 1e+06 fps is 1e+08 frames, more than the 1000000 allowed"
err_case frames_to_end "${P}${S}fps 1e200\n" "6:1: error: the vehicle reaches the end of the road (150.399 m) after 15.0399 s: 1.50399e+201 frames at 1e+200 fps, more than the 1000000 allowed; lower the fps or give 'frames' or 'duration'"
err_case frames_limit "${P}${S}frames 1000001\n" "6:8: error: frames must be a whole number 1..1000000, got '1000001'"
err_case seconds "${P}speed_at time 0 0\nfps 0.001\nframes 100\n" "7:1: error: 100 frames at 0.001 fps last 99000 s, more than the 10000 s allowed (the body's motion is integrated in steps of 1 ms)"
V=''
for v in a b c d e f g h i j k; do V="${V}vehicle $v\nvehicle_speed $v distance 0 1\n"; done
err_case vehicle_poses "${P}${S}fps 1e5\nframes 1000000\n$V" "7:1: error: 1e+06 frames x 11 vehicles are 1.1e+07 vehicle poses, more than the 10000000 allowed"
err_case max_segment "${P}${S}max_segment 1e-5\n" "6:1: error: 150.399 m of road within tolerance 0.001 m and max_segment 1e-05 m need about 9.78e+07 vertices for its surface and lines, more than the 4194304 allowed; raise max_segment"
err_case dashes "${P}${S}dash 1e-5 1e-5\n" "6:1: error: 7.51996e+06 dashes (1e-05 m dash, 1e-05 m gap along 150.399 m of road) and the rest of the road need about 3.01e+07 vertices, more than the 4194304 allowed; lengthen the dashes and gaps"
err_case trees "${P}${S}trees 1e-5 1\n" "6:1: error: the 'trees' lines place 3.00798e+07 trees along 150.399 m of road, more than the 1048576 allowed; space them further apart"
# a helix of radius ~40 m, 100 turns: 1e-6 m of chordal tolerance is
# millions of vertices (estimated from the curvature, refused at once)
H=$(awk 'BEGIN { for (i = 0; i <= 800; i++) { a = i * 3.14159265 / 4; printf "point %.3f %.3f %.3f\\n", 40 * cos(a), i * 0.5, 40 * sin(a) } }')
err_case tolerance "${H}${S}frames 2\ntolerance 1e-6\n" "804:1: error: 22668.535 m of road within tolerance 1e-06 m and max_segment 10 m need about 8.67e+06 vertices for its surface and lines, more than the 4194304 allowed; raise the tolerance"
# over the vertex limit while tessellating (the estimate, from the centre
# line, cannot see edges a billion metres out): an error, not a crash (the
# scene's text was freed twice: glsroad aborted)
err_case vertices_while_tessellating "${P}${S}verge 1\nlane_width 1e9\n" "1:1: error: the road's surface and lines within tolerance 0.001 m (max_segment 10 m) need more than 4194304 vertices; raise the tolerance or max_segment"
S257=$(awk 'BEGIN { for (i = 0; i <= 256; i++) printf "speed_at time %d 10\\n", i }')
err_case profile_points "${P}${S257}" "261:1: error: a profile has at most 256 points"
V257=$(awk 'BEGIN { for (i = 0; i <= 256; i++) printf "vehicle v%d\\n", i }')
err_case vehicles "${P}${S}${V257}" "262:1: error: at most 256 'vehicle' lines"
# a key with indentation: the caret is under the key
printf '%b' "${P}${S}   fps 1e9\n" >"$t/key_col.road"
timeout 120 "$R" "$t/key_col.road" -o "$t/o_key_col" 2>"$t/stderr"
if [ "$(head -1 "$t/stderr")" = "$t/key_col.road:6:4: error: the vehicle reaches the end of the road (150.399 m) after 15.0399 s: 1.50399e+10 frames at 1e+09 fps, more than the 1000000 allowed; lower the fps or give 'frames' or 'duration'" ] &&
    [ "$(sed -n 2p "$t/stderr")" = "   fps 1e9" ] && [ "$(sed -n 3p "$t/stderr")" = "   ^" ]; then
    ok road_error_limit_at_key
else
    fail road_error_limit_at_key "$(cat "$t/stderr")"
fi

# errors found while generating point at their key too
printf '%b' "${P}${S}  frames 1000\n" >"$t/too_far_key.road"
timeout 120 "$R" "$t/too_far_key.road" -o "$t/o_too_far_key" 2>"$t/stderr"
if [ "$(head -1 "$t/stderr")" = "$t/too_far_key.road:6:3: error: the vehicle passes the end of the road (150.399 m) at frame 376 (t = 15.04 s); give fewer frames, a lower speed or a longer road" ] &&
    [ "$(sed -n 2p "$t/stderr")" = "  frames 1000" ] && [ "$(sed -n 3p "$t/stderr")" = "  ^" ]; then
    ok road_error_too_far_at_key
else
    fail road_error_too_far_at_key "$(cat "$t/stderr")"
fi

# the excerpt under the message: the offending line, a caret under the column
printf '%b' "${P}${S}tolerance 1mm\n" >"$t/excerpt.road"
"$R" "$t/excerpt.road" -o "$t/o_excerpt" 2>"$t/stderr"
if [ "$(sed -n 2p "$t/stderr")" = "tolerance 1mm" ] && [ "$(sed -n 3p "$t/stderr")" = "          ^" ] && [ "$(wc -l <"$t/stderr")" = 3 ]; then
    ok road_error_source_excerpt
else
    fail road_error_source_excerpt "$(cat "$t/stderr")"
fi

# the demo road: all outputs, compiled by glsc
if "$R" examples/road/demo.road -o "$t/demo" >/dev/null 2>"$t/err"; then
    missing=""
    for f in road.scene roadobj/Tree.scene roadobj/Car.scene trajectory.txt poses_kitti.txt poses_tum.txt lanes.txt vehicles.txt; do
        [ -s "$t/demo/$f" ] || missing="$missing $f"
    done
    [ -z "$missing" ] && ok road_outputs || fail road_outputs "missing:$missing"
    ls "$t/demo" | grep -q '\.tmp' && fail road_no_temporaries "temporary files left" || ok road_no_temporaries
else
    fail road_outputs "$(cat "$t/err")"
fi
# (the demo names scenelib's trees, vehicles and textures)
if [ -x "$B/glsc" ] && [ -f "$B/scenelib.glsb" ]; then
    if "$B/glsc" -I "$t/demo" -I "$B/scenelib.glsb" -o "$t/demo.glsb" "$t/demo/road.scene" 2>"$t/err"; then
        ok road_scene_compiles
    else
        fail road_scene_compiles "$(head -3 "$t/err")"
    fi
fi
# deterministic
"$R" examples/road/demo.road -o "$t/demo2" >/dev/null 2>&1
if diff -r "$t/demo" "$t/demo2" >/dev/null; then ok road_deterministic; else fail road_deterministic "outputs differ"; fi
# one frame per line, 500 frames (20 s at 25 fps)
n=$(grep -vc '^#' "$t/demo/trajectory.txt")
[ "$n" = 500 ] && [ "$(wc -l <"$t/demo/poses_kitti.txt")" = 500 ] && ok road_frame_count || fail road_frame_count "$n frames"

# The output directory is replaced as a whole (spec/road.md, "Outputs"):
# a failure part way leaves the previous set intact.  The failure: a file
# size limit (ulimit -f, SIGXFSZ ignored so write() fails with EFBIG) that
# road.scene and lanes.txt of this road fit in and its trajectory.txt not.
printf '%b' "${P}${S}fps 100\n" >"$t/long.road"
"$R" examples/road/demo.road -o "$t/set" >/dev/null 2>&1 && cp -a "$t/set" "$t/set_before"
expect road_output_write_fails 1 "glsroad: error: cannot write $t/set/trajectory.txt: File too large" -- \
    sh -c 'trap "" XFSZ; ulimit -f 200; exec "$0" "$@"' "$R" "$t/long.road" -o "$t/set"
if diff -r "$t/set_before" "$t/set" >"$t/diff" 2>&1; then ok road_output_kept_on_failure
else fail road_output_kept_on_failure "the previous set changed: $(head -3 "$t/diff")"; fi
ls -d "$t"/set.* >/dev/null 2>&1 && fail road_output_no_temporary_dir "left: $(ls -d "$t"/set.*)" ||
    ok road_output_no_temporary_dir
# without the limit the same road replaces the set: exactly its own outputs
"$R" "$t/long.road" -o "$t/long_fresh" >/dev/null 2>&1
if "$R" "$t/long.road" -o "$t/set/" >/dev/null 2>"$t/err" && diff -r "$t/long_fresh" "$t/set" >"$t/diff" 2>&1 &&
    ! ls -d "$t"/set.* >/dev/null 2>&1; then
    ok road_output_replaced_whole
else
    fail road_output_replaced_whole "$(cat "$t/err") $(head -3 "$t/diff")"
fi
# a directory glsroad did not write is never replaced, nor written into
mkdir "$t/user" && echo keep >"$t/user/notes.txt"
expect road_output_foreign_dir 1 "glsroad: error: $t/user is not a glsroad output directory: it holds 'notes.txt', which glsroad does not write; give a new or an empty directory" -- \
    "$R" examples/road/demo.road -o "$t/user"
[ "$(ls "$t/user")" = notes.txt ] && ok road_output_foreign_dir_untouched || fail road_output_foreign_dir_untouched "$(ls "$t/user")"
echo x >"$t/afile"
expect road_output_not_dir 1 "glsroad: error: $t/afile exists and is not a directory" -- \
    "$R" examples/road/demo.road -o "$t/afile"
mkdir "$t/empty"
expect road_output_empty_dir 0 "" -- "$R" examples/road/demo.road -o "$t/empty"
# the directory that cannot be created is the one named (it named
# DIR/roadobj when DIR itself could not be made); missing parents are
# created (above), a parent that is a file cannot be
expect road_output_parent_not_dir 1 "glsroad: error: cannot use $t/afile/out: Not a directory" -- \
    "$R" examples/road/demo.road -o "$t/afile/out"

# --camera-at: the camera file with R, T composed; the rest kept
if "$R" --camera-at 120 "$t/demo/trajectory.txt" examples/road/rig/left.cam >"$t/l120.cam" 2>"$t/err"; then
    grep -q '^fx 600$' "$t/l120.cam" && grep -q '^far 800$' "$t/l120.cam" && [ "$(grep -c '^R ' "$t/l120.cam")" = 1 ] &&
        ok road_camera_at || fail road_camera_at "$(cat "$t/l120.cam")"
else
    fail road_camera_at "$(cat "$t/err")"
fi
expect road_camera_at_missing_frame 1 "$t/demo/trajectory.txt: error: no frame 99999 in the trajectory" -- \
    "$R" --camera-at 99999 "$t/demo/trajectory.txt" examples/road/rig/left.cam
sed 's/^R .*/R 1 0 0 0 1 0 0 0 2/' examples/road/rig/left.cam >"$t/bad.cam"
line=$(grep -n '^R ' "$t/bad.cam" | cut -d: -f1)
expect road_camera_at_bad_R 1 "$t/bad.cam:$line:3: error: R is not orthonormal: (R R^T)[2][2] = 4, must be 1 within 1e-4" -- \
    "$R" --camera-at 0 "$t/demo/trajectory.txt" "$t/bad.cam"
expect road_camera_at_usage 2 "glsroad: error: --camera-at: 'x' is not a frame number" -- \
    "$R" --camera-at x "$t/demo/trajectory.txt" examples/road/rig/left.cam

# OpenCV: the composed camera, the TUM quaternions (via cv2.Rodrigues) and
# the KITTI relative poses agree with trajectory.txt
if [ -x $PY ] && $PY -c 'import cv2' 2>/dev/null; then
    $PY - "$t/demo" "$t/l120.cam" <<'PYEOF'
import sys, math
import numpy as np, cv2
d, cam = sys.argv[1], sys.argv[2]
tr = np.loadtxt(d + "/trajectory.txt")
tum = np.loadtxt(d + "/poses_tum.txt")
ki = np.loadtxt(d + "/poses_kitti.txt")
def ok(n, c, why=""):
    print(("ok " if c else "FAIL ") + n + ("" if c else ": " + why))
worst_q = worst_t = worst_k = 0.0
R0, T0 = tr[0, 2:11].reshape(3, 3), tr[0, 11:14]
for i in range(len(tr)):
    R, T = tr[i, 2:11].reshape(3, 3), tr[i, 11:14]
    Rw = R.T                       # camera -> world
    c = -R.T @ T                   # camera centre
    rvec, _ = cv2.Rodrigues(Rw)
    ang = np.linalg.norm(rvec)
    ax = rvec.ravel() / ang if ang > 0 else np.zeros(3)
    q = np.r_[ax * math.sin(ang / 2), math.cos(ang / 2)]
    # q and -q are the same rotation: compare with the nearer one
    worst_q = max(worst_q, min(np.abs(q - tum[i, 4:8]).max(), np.abs(q + tum[i, 4:8]).max()))
    worst_t = max(worst_t, np.abs(c - tum[i, 1:4]).max())
    K = np.c_[R0 @ Rw, R0 @ c + T0]
    worst_k = max(worst_k, np.abs(K - ki[i].reshape(3, 4)).max())
ok("road_tum_quaternion_opencv", worst_q < 1e-9, "quaternion error %g" % worst_q)
ok("road_tum_position", worst_t < 1e-9, "position error %g" % worst_t)
# TUM quaternions are continuous: the first has w >= 0, each next one the
# sign nearer its predecessor (the demo's rig looks along +z, a half turn
# from the world's axes, so w crosses 0 on the way)
dots = np.sum(tum[1:, 4:8] * tum[:-1, 4:8], axis=1)
ok("road_tum_quaternion_continuous", tum[0, 7] >= 0 and dots.min() >= 0,
   "w0 = %g, %d sign flips, smallest dot %g" % (tum[0, 7], np.count_nonzero(dots < 0), dots.min()))
ok("road_kitti_relative", worst_k < 1e-9, "error %g" % worst_k)
# KITTI poses are relative to the first frame: line 0 is exactly [I|0]
first = open(d + "/poses_kitti.txt").readline()
ok("road_kitti_first_identity", first == "1 0 0 0 0 1 0 0 0 0 1 0\n", "line 0 is %r" % first)
# the composed camera: left camera 0.15 m left of the rig (rig x is right)
vals = {}
for line in open(cam):
    line = line.split("#")[0].split()
    if line and line[0] != "pose": vals[line[0]] = [float(v) for v in line[1:]]
ok("road_camera_at_pose_world", open(cam).read().count("\npose world\n") == 1)
Rc, Tc = np.array(vals["R"]).reshape(3, 3), np.array(vals["T"])
i = int(np.where(tr[:, 0] == 120)[0][0])
R, T = tr[i, 2:11].reshape(3, 3), tr[i, 11:14]
ok("road_camera_at_composition", np.allclose(Rc, R, atol=1e-12) and np.allclose(Tc, T + [0.15, 0, 0], atol=1e-9))
# speeds: 10 m/s at the start, 20 m/s after 100 m, via the rig's positions
# (the profile holds on the centre line; the rig, 1.75 m off it and 1.5 m
# up, moves a little slower on the inside of a curve)
p = tum[:, 1:4]
v = np.linalg.norm(np.diff(p, axis=0), axis=1) * 25
ok("road_speed_profile", abs(v[0] - 10) < 0.1 and abs(v[-1] - 20) < 1, "speeds %g %g" % (v[0], v[-1]))
PYEOF
else
    fail road_opencv "no OpenCV under $PY"
fi
