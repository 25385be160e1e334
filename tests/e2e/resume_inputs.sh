#!/bin/sh
# --resume takes a frame only if it was made from the same inputs
# (runtime/play/frame_record.h; spec/road.md "Resuming a sequence"): the
# record names the camera's intrinsics and the digest of the bundle, the
# camera files, the trajectory and the motion files, so a changed scene,
# camera or trajectory re-renders every frame, and what it writes equals a
# fresh render with the new inputs.  Prints ok/FAIL lines.
. tests/e2e/lib.sh
tmp=$t

mkdir -p "$tmp/s"
scene() { # COLOUR: a red or green quadrilateral 10 units ahead
    printf 'color(%s);\npoly { vert(-1, -1, 10); vert(1.2, -0.8, 10); vert(1, 1, 10); vert(-1.1, 0.9, 10); }\n' "$1" \
        >"$tmp/s/Q.scene"
    "$BIN/glsc" -I "$tmp/s" -o "$tmp/q.glsb" Q
}
camera() { # FX
    printf 'width 48\nheight 32\nfx %s\nfy 40\ncx 23.5\ncy 15.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\npose rig\n' \
        "$1" >"$tmp/cam.cam"
}
traj() { # DZ: three frames moving forward DZ each
    printf '0 0 1 0 0 0 1 0 0 0 1 0 0 0\n1 1 1 0 0 0 1 0 0 0 1 0 0 %s\n2 2 1 0 0 0 1 0 0 0 1 0 0 %s\n' "$1" "$(awk -v d="$1" 'BEGIN { print 2 * d }')" \
        >"$tmp/traj.txt"
}
play() { # OUTDIR [more options]
    out=$1
    shift
    "$BIN/glsplay" "$tmp/q.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --outputs image,depth \
        -o "$out" "$@" 2>"$tmp/err"
}
note() { sed -n 's/^glsplay: note: --resume: \([0-9]*\) of .*/\1/p' "$tmp/err"; }
# resume CASE: after changing an input, --resume re-renders all 3 frames
# and its files equal a fresh render's
resume() {
    play "$tmp/run" --resume && [ "$(note)" = 0 ] || { fail "$1" "$(cat "$tmp/err")"; return; }
    rm -rf "$tmp/fresh"
    play "$tmp/fresh" && diff -r "$tmp/fresh" "$tmp/run" >/dev/null && ok "$1" || fail "$1" "not a fresh render's files"
}

scene 1,0,0 && camera 40 && traj -0.5 || { fail resume_inputs_setup "scene"; exit 0; }
play "$tmp/run" || { fail resume_inputs_setup "$(cat "$tmp/err")"; exit 0; }
play "$tmp/run" --resume && [ "$(note)" = 3 ] && ok resume_inputs_same || fail resume_inputs_same "$(cat "$tmp/err")"

rec="$tmp/run/cam/.frame_000001.done"
head -1 "$rec" | grep -qx 'glsplay frame record 2' &&
    grep -qx 'intrinsics fx 40 fy 40 cx 23.5 cy 15.5 skew 0 near 0.1 far 100' "$rec" &&
    tail -1 "$rec" | grep -qx 'inputs [0-9a-f]\{16\}' && ok resume_record_inputs_lines ||
    fail resume_record_inputs_lines "$(cat "$rec")"

camera 41 && resume resume_camera_changed
scene 0,1,0 && resume resume_scene_changed
traj -0.6 && resume resume_trajectory_changed
# the same inputs again: complete
play "$tmp/run" --resume && [ "$(note)" = 3 ] && ok resume_inputs_same_again || fail resume_inputs_same_again "$(cat "$tmp/err")"

