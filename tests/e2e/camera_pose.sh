#!/bin/sh
# Camera poses as glsplay uses them: R printed with few decimals (accepted
# and re-orthonormalised with a note, or refused).
# Prints "ok NAME" / "FAIL NAME: why".
BIN=${GLS_BIN:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
ok() { echo "ok $1"; }
fail() { echo "FAIL $1: $2"; }
"$BIN/glsc" -I tests/compiler/lang -o "$t/leaf.glsb" pkg.Leaf || { fail camera_pose_setup "glsc"; exit 0; }

# cam FILE R...: a small camera file with the given R
cam() {
    f=$1
    shift
    printf 'width 32\nheight 24\nfx 30\nfy 30\ncx 15.5\ncy 11.5\nR %s\nT 0 0 5\nnear 0.1\nfar 100\n' "$*" >"$f"
}

# R printed with 5 decimals (a rotation of 0.5 rad about (1, 1, 1)): a note, then the render
cam "$t/r5.cam" 0.91839 -0.23599 0.3176 0.3176 0.91839 -0.23599 -0.23599 0.3176 0.91839
"$BIN/glsplay" "$t/leaf.glsb" --camera "$t/r5.cam" -o "$t/o" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && [ -f "$t/o/r5/image_000000.png" ] && [ "$(wc -l <"$t/err")" = 1 ] &&
    grep -q "^$t/r5.cam:7:3: note: R is orthonormal only within .* (used as given within 1e-6): replaced by the nearest rotation, which moves no entry by more than " "$t/err"; then
    ok camera_r_five_decimals_note
else
    fail camera_r_five_decimals_note "exit $rc: $(cat "$t/err")"
fi
# the same R with 3 decimals is refused
cam "$t/r3.cam" 0.918 -0.236 0.318 0.318 0.918 -0.236 -0.236 0.318 0.918
"$BIN/glsplay" "$t/leaf.glsb" --camera "$t/r3.cam" -o "$t/o3" 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && grep -q "^$t/r3.cam:7:3: error: R is not orthonormal: (R R^T)\[0\]\[0\] = 0.999544, must be 1 within 1e-4$" "$t/err"; then
    ok camera_r_three_decimals_refused
else
    fail camera_r_three_decimals_refused "exit $rc: $(cat "$t/err")"
fi
