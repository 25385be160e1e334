# What the end-to-end scripts share, once.  tests/run.sh runs each script
# from the repository root; a script sources this first:
#     . tests/e2e/lib.sh
# and then has:
#   B, BIN   the build directory ($GLS_BIN, default build); a script that
#            needs it absolute sets BIN=$(cd "$B" && pwd) itself
#   REF      the build whose tools compute a test's references (a 65,536-
#            sample image an exact one is held to): $GLS_REF_BIN, default
#            B.  The sanitizer pass (tests/run.sh) sets it to the normal
#            build: its subject is the sanitized tool, and a reference
#            drawn by it again costs minutes and checks nothing new
#   PY       the Python with cv2 and numpy (python3 on PATH has neither)
#   t        an empty temporary directory, removed on exit (a script that
#            must undo more on exit sets its own trap, removing "$t" too)
#   ok NAME, fail NAME WHY   the "ok NAME" / "FAIL NAME: why" lines
#            tests/run.sh counts
# and the helpers below.  Not a test itself: tests/run.sh skips it.
B=${GLS_BIN:-build}
BIN=$B
REF=${GLS_REF_BIN:-$B}
PY=${GLS_PY:-/usr/bin/python3}  # GLS_PY: another Python with cv2 and numpy (a GPU machine's)
# (the trap removes the directory made here even where a script uses t
# for something else later, as install.sh's loops do)
e2e_tmp=$(mktemp -d) && trap 'rm -rf "$e2e_tmp"' EXIT || exit 1
t=$e2e_tmp
ok() { echo "ok $1"; }
fail() { echo "FAIL $1: $2"; }

# keep_in DIR: with DIR given, work in DIR (emptied, kept on exit) rather
# than in the temporary directory (the EXAMPLES_KEEP-style variables)
keep_in() {
    [ -n "$1" ] || return 0
    rm -rf "$e2e_tmp"
    trap - EXIT
    t=$1 && rm -rf "$t" && mkdir -p "$t" || exit 1
}

# need NAME FILE...: the script ends with "FAIL NAME: no $B/FILE (run
# make)" unless every FILE is in $B
need() {
    need_name=$1
    shift
    for need_f; do
        [ -e "$B/$need_f" ] || { fail "$need_name" "no $B/$need_f (run make)"; exit 0; }
    done
}

# need_players NAME: the script ends with one FAIL line unless glsc and
# glsplay are built
need_players() {
    [ -x "$B/glsc" ] && [ -x "$B/glsplay" ] || { fail "$1" "no $B/glsc or $B/glsplay"; exit 0; }
}

# need_cv2 NAME: the script ends with one FAIL line unless $PY has numpy
# and cv2
need_cv2() {
    [ -x $PY ] && $PY -c 'import numpy, cv2' 2>/dev/null || { fail "$1" "no numpy/cv2 under $PY"; exit 0; }
}

# py_check NAME SCRIPT ARGS...: tests/py/SCRIPT ARGS under $PY (it prints
# its own ok/FAIL lines); "FAIL NAME: ..." when it exits with a failure
# status, or when $PY has no cv2 and numpy
py_check() {
    py_name=$1 py_script=$2
    shift 2
    if $PY -c 'import cv2, numpy' 2>/dev/null; then
        $PY "tests/py/$py_script" "$@" || fail "$py_name" "$py_script exited with status $?"
    else
        fail "$py_name" "no cv2 and numpy under $PY"
    fi
}

# linked_same NAME SRC TOP: TOP compiled against the library bundle of
# the directory SRC and against SRC itself: the same bundle, byte for byte
linked_same() {
    "$BIN/glsc" --lib "$2" -o "$t/lib.glsb" 2>"$t/err" &&
        "$BIN/glsc" -I "$t/lib.glsb" -o "$t/linked.glsb" "$3" 2>>"$t/err"
    "$BIN/glsc" -I "$2" -o "$t/direct.glsb" "$3" 2>>"$t/err"
    if cmp -s "$t/linked.glsb" "$t/direct.glsb"; then
        ok "$1"
    else
        fail "$1" "linked and direct bundles differ: $(cat "$t/err")"
    fi
}

# rig_cam FILE: a 64x48 pinhole camera (fx = fy = 50) at the rig's origin,
# looking along the rig's +z (pose rig: a trajectory moves it)
rig_cam() {
    printf 'width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\npose rig\n' >"$1"
}

# exact NAME STATUS LINE -- command...: exit status, and stderr exactly
# LINE; a script that sets EXACT_LINES=1 also wants its line count (one
# line ending in a newline, or none when LINE is empty)
EXACT_LINES=0
exact() {
    name=$1 want=$2 line=$3
    shift 4
    "$@" >"$t/stdout" 2>"$t/stderr"
    rc=$?
    if [ $rc -ne "$want" ]; then fail "$name" "exit $rc, wanted $want: $(cat "$t/stderr")"
    elif [ "$(cat "$t/stderr")" != "$line" ] || { [ "$EXACT_LINES" = 1 ] &&
        [ "$(wc -l <"$t/stderr")" -ne $([ -n "$line" ] && echo 1 || echo 0) ]; }; then
        fail "$name" "stderr is '$(cat "$t/stderr")', wanted '$line'"
    else ok "$name"; fi
}
