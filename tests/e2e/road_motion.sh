#!/bin/sh
# glsroad's traffic (spec/road.md, "Other vehicles"): one motion file per
# vehicle (motion/NAME.txt, "# glsroad motion 1", a row every frame),
# byte-identical from run to run; road.scene calls each vehicle once as a
# named instance with no transform; a previous output with other vehicles
# is replaced as a whole (its motion files go), and a motion/ directory
# holding something else is refused.  The poses themselves are checked
# against an independent computation in tests/unit/test_road_motion.c.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
[ -x "$B/glsroad" ] || { fail road_motion "no $B/glsroad"; exit 0; }
ROAD='degree 3\npoint 0 0 0\npoint 0 0 60\npoint -10 0 110\npoint -45 0 160\npoint -60 0 220\nfps 10\nduration 8\nspeed_at distance 0 10\n'
printf "${ROAD}vehicle lead lateral -1.75 start 30 object v.Car\nvehicle_speed lead distance 0 12\nvehicle_speed lead distance 50 15\nvehicle van_2 lateral 1.75 start 150 oncoming\nvehicle_speed van_2 time 0 14\n" >"$t/a.road"
printf "${ROAD}vehicle bus lateral -1.75 start 10\nvehicle_speed bus distance 0 8\n" >"$t/b.road"
for d in one two; do
    "$B/glsroad" "$t/a.road" -o "$t/$d" >/dev/null 2>"$t/err_$d" || fail "road_motion_run_$d" "$(cat "$t/err_$d")"
done
if [ -f "$t/one/motion/lead.txt" ] && [ -f "$t/one/motion/van_2.txt" ] && [ "$(ls "$t/one/motion" | wc -l)" -eq 2 ]; then
    ok road_motion_files_written
else
    fail road_motion_files_written "$(ls "$t/one/motion" 2>&1 | tr '\n' ' ')"
fi
if cmp -s "$t/one/motion/lead.txt" "$t/two/motion/lead.txt" && cmp -s "$t/one/motion/van_2.txt" "$t/two/motion/van_2.txt"; then
    ok road_motion_deterministic
else
    fail road_motion_deterministic "two runs differ"
fi
# header, then a row of 14 numbers for every frame 0..79
if [ "$(head -1 "$t/one/motion/lead.txt")" = "# glsroad motion 1" ] &&
    awk '!/^#/ { if (NF != 14 || $1 != n) bad = 1; n++ } END { exit bad || n != 80 }' "$t/one/motion/van_2.txt"; then
    ok road_motion_row_every_frame
else
    fail road_motion_row_every_frame "$(grep -vc '^#' "$t/one/motion/van_2.txt") rows"
fi
# on the road, the motion file's row is vehicles.txt's line for that frame
if awk '!/^#/ && $3 == "lead" { $3 = ""; print }' "$t/one/vehicles.txt" | tr -s ' ' >"$t/veh" &&
    grep -v '^#' "$t/one/motion/lead.txt" | head -"$(wc -l <"$t/veh")" | tr -s ' ' >"$t/mot" && [ -s "$t/veh" ] &&
    cmp -s "$t/veh" "$t/mot"; then
    ok road_motion_matches_vehicles_txt
else
    fail road_motion_matches_vehicles_txt "$(diff "$t/veh" "$t/mot" | head -3 | tr '\n' ' ')"
fi
# the scene: each vehicle once, named, with no transform
if grep -qx 'call("v.Car", "lead");' "$t/one/road.scene" && grep -qx 'call("roadobj.Car", "van_2");' "$t/one/road.scene"; then
    ok road_motion_named_calls
else
    fail road_motion_named_calls "$(grep -n 'call(' "$t/one/road.scene" | tail -3 | tr '\n' ' ')"
fi
mkdir -p "$t/lib/v"
printf 'poly { vert(0, 0, 0); vert(1, 0, 0); vert(1, 1, 0); }\n' >"$t/lib/v/Car.scene"
if "$B/glsc" -I "$t/one" -I "$t/lib" -o "$t/road.glsb" "$t/one/road.scene" 2>"$t/cerr" &&
    "$B/glsdis" "$t/road.glsb" | grep -q '^  calln roadobj.Car "van_2"$'; then
    ok road_motion_scene_compiles
else
    fail road_motion_scene_compiles "$(head -3 "$t/cerr")"
fi
# another description into the same directory: the old motion files go
if "$B/glsroad" "$t/b.road" -o "$t/one" >/dev/null 2>"$t/err" && [ "$(ls "$t/one/motion")" = "bus.txt" ]; then
    ok road_motion_replaces_previous
else
    fail road_motion_replaces_previous "$(cat "$t/err") $(ls "$t/one/motion" | tr '\n' ' ')"
fi
# something glsroad does not write in motion/ is not removed: refused
: >"$t/two/motion/notes.md"
"$B/glsroad" "$t/b.road" -o "$t/two" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "glsroad: error: $t/two is not a glsroad output directory: it holds 'motion/notes.md', which glsroad does not write; give a new or an empty directory" ] &&
    [ -f "$t/two/motion/lead.txt" ]; then
    ok road_motion_stranger_refused
else
    fail road_motion_stranger_refused "exit $rc: $(cat "$t/err")"
fi
