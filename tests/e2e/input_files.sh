#!/bin/sh
# Every input file of every tool is a regular file (base/readfile.h, one
# rule): a FIFO with no writer, given as any input, is refused at once
# with "cannot read PATH: it is a FIFO (named pipe), not a regular file"
# in the tool's wording, exit 1, instead of blocking for ever (each case
# runs under timeout 10, so a regression fails rather than hangs); a
# missing --motion file names the tool and the option.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
need_players input_files
KIND="it is a FIFO (named pipe), not a regular file"

# fifo NAME WANTED-STDERR-LINE -- command...: exit 1 within 10 s, and the
# first line of stderr exactly as wanted
fifo() {
    name=$1 want=$2
    shift 3
    timeout 10 "$@" >"$t/out" 2>"$t/err"
    rc=$?
    if [ $rc -eq 124 ]; then fail "$name" "still waiting after 10 s (blocked on the FIFO)"
    elif [ $rc -ne 1 ]; then fail "$name" "exit $rc, wanted 1: $(head -2 "$t/err")"
    elif [ "$(head -1 "$t/err")" != "$want" ]; then fail "$name" "stderr '$(head -1 "$t/err")', wanted '$want'"
    else ok "$name"; fi
}

# a scene with a named instance, its bundle, a camera and a trajectory
mkdir -p "$t/src/k/tex" "$t/bad/k/tex"
printf 'poly { vert(0, 0, 5); vert(1, 0, 5); vert(0, 1, 5); }\n' >"$t/src/k/Tri.scene"
printf 'call("k.Tri", "mover");\n' >"$t/src/k/Top.scene"
"$BIN/glsc" -I "$t/src" -o "$t/top.glsb" k.Top 2>"$t/err" || { fail input_files_setup "$(cat "$t/err")"; exit 0; }
rig_cam "$t/rig.cam"
printf '0 0 1 0 0 0 1 0 0 0 1 0 0 0\n' >"$t/traj.txt"
mkfifo "$t/in.fifo"
F=$t/in.fifo

# glsplay: --camera, --trajectory, --motion, the bundle
fifo input_fifo_camera "$F: error: cannot read: $KIND" -- \
    "$BIN/glsplay" "$t/top.glsb" --camera "$F" -o "$t/o"
fifo input_fifo_trajectory "$F: error: cannot read: $KIND" -- \
    "$BIN/glsplay" "$t/top.glsb" --camera "$t/rig.cam" --trajectory "$F" -o "$t/o"
fifo input_fifo_motion "glsplay: error: --motion mover=$F: cannot read: $KIND" -- \
    "$BIN/glsplay" "$t/top.glsb" --camera "$t/rig.cam" --trajectory "$t/traj.txt" --motion "mover=$F" -o "$t/o"
fifo input_fifo_bundle "glsplay: error: $F: cannot read: $KIND" -- \
    "$BIN/glsplay" "$F" --camera "$t/rig.cam" -o "$t/o"
# glsroad: the road description, --camera-at's trajectory and camera
fifo input_fifo_road "$F: error: cannot read: $KIND" -- "$BIN/glsroad" "$F" -o "$t/road"
fifo input_fifo_camera_at_trajectory "$F: error: cannot read: $KIND" -- \
    "$BIN/glsroad" --camera-at 0 "$F" "$t/rig.cam"
fifo input_fifo_camera_at_camera "$F: error: cannot read: $KIND" -- \
    "$BIN/glsroad" --camera-at 0 "$t/traj.txt" "$F"
# glsc: the top .scene file (it said "no such file"), a called scene and a
# texture found through a root, a bundle root
mkfifo "$t/top.scene"
fifo input_fifo_glsc_top "glsc: error: cannot read $t/top.scene: $KIND" -- \
    "$BIN/glsc" -o "$t/x.glsb" "$t/top.scene"
printf 'call("k.Tri");\n' >"$t/bad/k/Top.scene"
mkfifo "$t/bad/k/Tri.scene"
fifo input_fifo_glsc_called "$t/bad/k/Top.scene:1:7: error: cannot read $t/bad/k/Tri.scene: $KIND" -- \
    "$BIN/glsc" -I "$t/bad" -o "$t/x.glsb" k.Top
printf 'texture("k.tex.T");\n' >"$t/bad/k/Tex.scene"
mkfifo "$t/bad/k/tex/T.png"
fifo input_fifo_glsc_texture "$t/bad/k/Tex.scene:1:10: error: texture 'k.tex.T': cannot read $t/bad/k/tex/T.png: $KIND" -- \
    "$BIN/glsc" -I "$t/bad" -o "$t/x.glsb" k.Tex
fifo input_fifo_glsdis "glsdis: error: $F: cannot read: $KIND" -- "$BIN/glsdis" "$F"
[ ! -e "$t/x.glsb" ] && [ ! -e "$t/o" ] && [ ! -e "$t/road" ] && ok input_fifo_no_output ||
    fail input_fifo_no_output "$(ls "$t")"

# a missing --motion file: the tool and the option are named
fifo input_motion_missing "glsplay: error: --motion mover=$t/none.txt: cannot open: No such file or directory" -- \
    "$BIN/glsplay" "$t/top.glsb" --camera "$t/rig.cam" --trajectory "$t/traj.txt" --motion "mover=$t/none.txt" -o "$t/o"
