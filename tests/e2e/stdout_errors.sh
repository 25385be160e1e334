#!/bin/sh
# Every tool checks that its standard output was written: with standard
# output on /dev/full (every write fails with ENOSPC) each exits 1 and
# says exactly "TOOL: error: cannot write standard output: No space left
# on device" (base/stdout_check.c).  The same commands writing to a file
# exit 0, so the failure is the output's.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
BIN=$(cd "$B" && pwd)
tmp=$t
[ -c /dev/full ] || { fail stdout_errors "no /dev/full"; exit 0; }

# full NAME TOOL command...: TOOL's standard output on /dev/full
full() {
    name=$1 tool=$2
    shift 2
    "$@" >"$tmp/out" 2>"$tmp/err"; rc0=$?
    "$@" >/dev/full 2>"$tmp/err"; rc=$?
    want="$tool: error: cannot write standard output: No space left on device"
    if [ $rc0 -ne 0 ] || [ ! -s "$tmp/out" ]; then fail "$name" "to a file: exit $rc0, $(head -1 "$tmp/err")"
    elif [ $rc -ne 1 ]; then fail "$name" "exit $rc, wanted 1"
    elif [ "$(cat "$tmp/err")" != "$want" ]; then fail "$name" "stderr '$(head -1 "$tmp/err")', wanted '$want'"
    else ok "$name"; fi
}

"$BIN/glsc" -I tests/compiler/paper -o "$tmp/c.glsb" road.tex.roads.Curve400m 2>"$tmp/err" ||
    fail stdout_errors "setup: $(head -1 "$tmp/err")"
"$BIN/glsroad" examples/road/demo.road -o "$tmp/road" >/dev/null 2>"$tmp/err" ||
    fail stdout_errors "setup: $(head -1 "$tmp/err")"

full stdout_full_glsdis glsdis "$BIN/glsdis" "$tmp/c.glsb"
full stdout_full_glsplay_explain glsplay "$BIN/glsplay" "$tmp/c.glsb" --camera examples/demo/left.cam --explain
full stdout_full_glsroad glsroad "$BIN/glsroad" examples/road/demo.road -o "$tmp/road2"
full stdout_full_glsroad_camera_at glsroad "$BIN/glsroad" --camera-at 0 "$tmp/road/trajectory.txt" examples/road/rig/left.cam
# help texts longer than standard output's buffer (glsplay's) are written
# past it, and the reason of the failure is kept all the same (it said
# "a write failed")
for tool in glsc glsdis glsplay glsroad; do
    full "stdout_full_${tool}_help" $tool "$BIN/$tool" --help
    full "stdout_full_${tool}_version" $tool "$BIN/$tool" --version
done
