#!/bin/sh
# make bench-effects: what the effects of issue 16 cost, and that they cost
# nothing when no scene or camera asks for one.  Writes $B/bench/effects.txt
# (make bench-effects puts it in docs/benchmarks.md).
# Not a pass/fail test.
#
# For each scene (road: the road demo, textured, left rig camera; terrain:
# bench/play_scene.h's 100,352-triangle height field; both 640x480, image
# output only, along their trajectories from frame 1, so that a motion
# blur's exposure has a pose before the first frame), time per frame of:
#   (a) the build before issue 16 (BE_BASE, default main's 0debd87), built
#       from `git archive` into a temporary directory (removed at the end),
#       or the build directory BE_BASE_BUILD when given;
#   (b) this build with no effect asked for: the same camera, the same
#       options;
#   (c) this build with each case of bench/effects.cases (one line each:
#       name, scene, camera keys, glsplay options; the file says more).
# (a) and (b) run interleaved, a b a b ..., and each case interleaved with
# (b), so that a drift of the machine's load touches both sides alike.  A
# case of a lit scene (road:FILE) is timed against the road unlit, its
# floor: the cost is the difference.
# Time per frame = wall time of a whole glsplay run (start-up, upload, PNG
# writing included) / frames, and its CPU time (user + system, all threads;
# /usr/bin/time) / frames, which other work on a shared machine disturbs
# less; median, min and max of BE_RUNS runs.
#   BE_RUNS (default 7) runs per measurement; BE_FRAMES (default 12) frames
#   per run; BE_CASES (default bench/effects.cases).
# Both builds render the same scene text: the road as the base's glsroad
# writes it (later builds add landmarks, which draw nothing), compiled by
# each build's own glsc; the terrain as each build's play_bench writes it.
#
# bench/effects.sh --check BUILD: no timing and no base build; renders one
# frame of each case at 64x48 (tests/e2e/bench_effects_cases.sh), so that a
# case naming a missing file, a scene that does not compile or keys that
# glsplay refuses fails make test.
CHECK=""
if [ "$1" = --check ]; then CHECK=1; shift; fi
B=${1:-build}
. bench/lib.sh
RUNS=${BE_RUNS:-7}
FRAMES=${BE_FRAMES:-12}
CASES=${BE_CASES:-bench/effects.cases}
BASE=${BE_BASE:-0debd87}
mkdir -p "$B/bench" && OUT=$B/bench/effects.txt
# from frame 1: a motion blur's exposure needs the pose before its frame
FIRST=1 SIZE=""
[ -n "$CHECK" ] && FRAMES=1 SIZE="--size 64x48"
t=$(mktemp -d) && trap '[ -n "$BE_KEEP" ] || rm -rf "$t"' EXIT || exit 1
fixed_malloc
die() { echo "bench-effects: $*" >&2; exit 1; }
load0=$(loadavg 1)
NEW=$(cd "$B" && pwd) || die "no build directory $B"

# (a): the build before issue 16 (--check: this build stands in for it)
if [ -n "$CHECK" ]; then
    OLD=$NEW OLD_SRC=$(pwd)
elif [ -n "$BE_BASE_BUILD" ]; then
    OLD=$(cd "$BE_BASE_BUILD" && pwd) || die "no directory $BE_BASE_BUILD"
    OLD_SRC=$(dirname "$OLD")
else
    echo "building $BASE in $t/base (a few minutes)" >&2
    mkdir "$t/base" && git archive "$BASE" | tar -x -C "$t/base" || die "cannot extract $BASE"
    make -C "$t/base" -s -j2 all build/bench/play_bench >"$t/base.log" 2>&1 || { tail -20 "$t/base.log" >&2; die "cannot build $BASE"; }
    OLD=$t/base/build OLD_SRC=$t/base
fi

# The inputs: the base's road, compiled by each build; each build's terrain.
(cd "$OLD_SRC" && "$OLD/glsroad" examples/road/demo.road -o "$t/road" >/dev/null) || die "glsroad failed"
for side in old new; do
    [ -n "$CHECK" ] && [ $side = old ] && continue
    eval "b=\$$(echo "$side" | tr a-z A-Z)"
    mkdir -p "$t/$side"
    "$b/glsc" -I "$b/scenelib.glsb" -I "$t/road" -o "$t/$side/road.glsb" "$t/road/road.scene" ||
        die "$side glsc failed on the road"
    "$b/bench/play_bench" --write "$t/$side" >/dev/null || die "$side play_bench --write failed"
done
[ -x "$OLD/bench/play_bench" ] || die "no $OLD/bench/play_bench"
ROAD_CAM="$OLD_SRC/examples/road/rig/left.cam"

# The cases, checked before anything is timed: one line each of four fields
# separated by '|', the name one word, the scene road, terrain or road:FILE
# (an existing scene file), the keys '-' or an existing file.  Written to
# $t/cases as NAME|SCENE|KEYS|OPTIONS, blanks trimmed, '-' options emptied.
[ -r "$CASES" ] || die "cannot read $CASES"
awk -F'|' -v f="$CASES" '
    function trim(x) { gsub(/^[ \t]+|[ \t]+$/, "", x); return x }
    /^[ \t]*(#|$)/ { next }
    {
        if (NF != 4) { printf "%s:%d: %d fields, want 4: name | scene | camera keys | options\n", f, NR, NF > "/dev/stderr"; bad = 1; next }
        n = trim($1); sc = trim($2); k = trim($3); o = trim($4)
        if (n !~ /^[A-Za-z0-9_]+$/) { printf "%s:%d: the name must be one word, got '\''%s'\''\n", f, NR, n > "/dev/stderr"; bad = 1 }
        if (sc != "road" && sc != "terrain" && sc !~ /^road:./) { printf "%s:%d: unknown scene '\''%s'\'' (road, terrain or road:FILE)\n", f, NR, sc > "/dev/stderr"; bad = 1 }
        if (o == "-") o = ""
        print n "|" sc "|" k "|" o
    }
    END { exit bad }' "$CASES" >"$t/cases" || die "malformed $CASES"

# bundle SIDE SCENE: the bundle of a scene; road:FILE is FILE, which calls
# the road (unit "road"), compiled by this build once, into a bundle named
# after FILE's whole path
bundle() {
    case $2 in
    road | terrain) echo "$t/$1/$2.glsb" ;;
    road:*)
        b_out="$t/$1/scene_$(echo "${2#road:}" | tr -c 'A-Za-z0-9_\n' '_').glsb"
        [ -s "$b_out" ] || "$NEW/glsc" -I "$NEW/scenelib.glsb" -I "$t/road" -o "$b_out" "${2#road:}" >&2 ||
            die "case $name: glsc failed on ${2#road:}"
        echo "$b_out" ;;
    esac
}
# args SIDE SCENE: the glsplay arguments of a scene's plain run, less the
# camera
args() {
    case $2 in
    road*) echo "$(bundle "$1" "$2") --trajectory $t/road/trajectory.txt --background 0.55,0.7,0.9" ;;
    terrain) echo "$t/$1/terrain.glsb --trajectory $t/$1/trajectory.txt" ;;
    esac
}
# camera SIDE SCENE KEYS NAME: the camera file of a run, named NAME.cam: the
# scene's, with the keys file's keys in place of the scene camera's same
# keys (a fisheye's fx, fy) and added otherwise, unless KEYS is -
camera() {
    mkdir -p "$t/cam/$4"
    if [ "${2%%:*}" = road ]; then cat "$ROAD_CAM"; else cat "$t/$1/rig.cam"; fi >"$t/cam/$4/base.cam"
    if [ "$3" = - ]; then
        cp "$t/cam/$4/base.cam" "$t/cam/$4/cam.cam"
    else
        sh bench/effects/with_keys.sh "$t/cam/$4/base.cam" "$3" >"$t/cam/$4/cam.cam" || die "no camera keys file $3"
    fi
    echo "$t/cam/$4/cam.cam"
}
# every case's files exist, and its scene compiles
while IFS='|' read -r name cscene keys opts; do
    [ "$keys" = - ] || [ -r "$keys" ] || die "case $name: no camera keys file $keys"
    case $cscene in road:*) [ -r "${cscene#road:}" ] || die "case $name: no scene file ${cscene#road:}" ;; esac
    bundle new "$cscene" >/dev/null || exit 1
done <"$t/cases"
# the CPU time of a run too (user + system, GL's threads included), which
# other work on the machine disturbs less than the wall time
TIME=/usr/bin/time
[ -x "$TIME" ] || TIME=""
# once BIN SIDE SCENE CAMERA OPTIONS...: ms per frame of one glsplay run,
# wall and CPU ("-" without /usr/bin/time); $what names the run in errors
once() {
    # o_*: sh has no local variables, and the callers' names must survive
    o_bin=$1 o_side=$2 o_scene=$3 o_cam=$4
    shift 4
    rm -rf "$t/out"
    if [ -n "$TIME" ]; then
        # shellcheck disable=SC2046,SC2068,SC2086
        "$TIME" -f "%e %U %S" -o "$t/time" "$o_bin/glsplay" $(args "$o_side" "$o_scene") --camera "$o_cam" \
            --frames "$FIRST:$((FIRST + FRAMES))" --outputs image -o "$t/out" $SIZE --aa 1 $@ 2>"$t/err" || { cat "$t/err" >&2; die "$what: glsplay failed"; }
    else
        t0=$(date +%s.%N)
        # shellcheck disable=SC2046,SC2068,SC2086
        "$o_bin/glsplay" $(args "$o_side" "$o_scene") --camera "$o_cam" --frames "$FIRST:$((FIRST + FRAMES))" --outputs image -o "$t/out" $SIZE --aa 1 $@ \
            2>"$t/err" || { cat "$t/err" >&2; die "$what: glsplay failed"; }
        echo "$t0 $(date +%s.%N)" | awk '{ printf "%.3f - -\n", $2 - $1 }' >"$t/time"
    fi
    awk -v n="$FRAMES" '{ if ($2 == "-") printf "%.1f -\n", 1000 * $1 / n;
        else printf "%.1f %.1f\n", 1000 * $1 / n, 1000 * ($2 + $3) / n }' "$t/time"
}
# stats FILE COLUMN: median min max of a column of FILE
stats() {
    awk -v c="$2" '{ print $c }' "$1" | sort -n | awk '{ v[NR] = $1 } END {
        if (v[1] == "-") { print "- - -"; exit }
        m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%.1f %.1f %.1f\n", m, v[1], v[NR] }'
}
fmt() { set -- $1; printf '%s (%s..%s)' "$1" "$2" "$3"; }
# cost BEFORE AFTER: the change of the medians, in ms and %
cost() { echo "$1 $2" | awk '{ if ($1 == "-") print "-"; else printf "%+.1f ms (%+.1f %%)", $4 - $1, 100 * ($4 - $1) / $1 }'; }
spread() { echo "$1" | awk '{ if ($1 == "-") print "-"; else printf "%.0f %%", 100 * ($3 - $2) / $1 }'; }

# --check: one small frame of each case, through the same functions
if [ -n "$CHECK" ]; then
    n=0
    while IFS='|' read -r name cscene keys opts; do
        ccam=$(camera new "$cscene" "$keys" "case_$name")
        what="case $name"
        # shellcheck disable=SC2086
        once "$NEW" new "$cscene" "$ccam" $opts >/dev/null || exit 1
        [ -s "$t/out/cam/image_00000$FIRST.png" ] || die "case $name: no image"
        # the plan's top object: that the case drew its own scene
        # shellcheck disable=SC2046
        top=$("$NEW/glsplay" $(args new "$cscene") --camera "$ccam" --outputs image --explain 2>/dev/null |
            sed -n "s/^plan for .*: top object '\([^']*\)'.*/\1/p")
        echo "ok case $name ($cscene): top object $top"
        n=$((n + 1))
    done <"$t/cases"
    echo "$n cases of $CASES render"
    exit 0
fi

echo "measuring: $RUNS runs of $FRAMES frames per figure" >&2
: >"$t/rows"
for scene in road terrain; do
    oldcam=$(camera old "$scene" - "old_$scene")
    newcam=$(camera new "$scene" - "new_$scene")
    : >"$t/a" && : >"$t/b"
    what="plain $scene run"
    i=0
    while [ $i -lt "$RUNS" ]; do
        once "$OLD" old "$scene" "$oldcam" >>"$t/a" || exit 1
        once "$NEW" new "$scene" "$newcam" >>"$t/b" || exit 1
        i=$((i + 1))
    done
    wa=$(stats "$t/a" 1) wb=$(stats "$t/b" 1) ca=$(stats "$t/a" 2) cb=$(stats "$t/b" 2)
    printf '| %s | none (before issue 16, %s) | %s | %s | base; spread of its runs: wall %s, CPU %s |\n' \
        "$scene" "$BASE" "$(fmt "$wa")" "$(fmt "$ca")" "$(spread "$wa")" "$(spread "$ca")" >>"$t/rows"
    printf '| %s | none (this build) | %s | %s | wall %s, CPU %s against the base |\n' "$scene" "$(fmt "$wb")" \
        "$(fmt "$cb")" "$(cost "$wa" "$wb")" "$(cost "$ca" "$cb")" >>"$t/rows"
    while IFS='|' read -r name cscene keys opts; do
        [ "${cscene%%:*}" = "$scene" ] || continue
        ccam=$(camera new "$cscene" "$keys" "case_$name")
        : >"$t/c" && : >"$t/p"
        i=0
        while [ $i -lt "$RUNS" ]; do
            # the plain run (for road:FILE, the road unlit: the floor) with
            # the same options, then the case
            what="case $name, plain run"
            # shellcheck disable=SC2086
            once "$NEW" new "$scene" "$newcam" $opts >>"$t/p" || exit 1
            what="case $name"
            # shellcheck disable=SC2086
            once "$NEW" new "$cscene" "$ccam" $opts >>"$t/c" || exit 1
            i=$((i + 1))
        done
        wc=$(stats "$t/c" 1) wp=$(stats "$t/p" 1) cc=$(stats "$t/c" 2) cp=$(stats "$t/p" 2)
        label=$scene
        [ "$cscene" = "$scene" ] || label="$scene + $(basename "${cscene#*:}")"
        printf '| %s | %s%s | %s | %s | wall %s, CPU %s against the same run without it (%s, %s) |\n' "$label" \
            "$name" "${opts:+ ($opts)}" "$(fmt "$wc")" "$(fmt "$cc")" "$(cost "$wp" "$wc")" "$(cost "$cp" "$cc")" \
            "$(fmt "$wp")" "$(fmt "$cp")" >>"$t/rows"
    done <"$t/cases"
done

commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- runtime base format compiler roads 2>/dev/null || commit="$commit + uncommitted changes"
{
echo "make bench-effects ($(date -u +%Y-%m-%d)): time per frame, ms, median (min..max) of $RUNS whole glsplay"
echo "runs of $FRAMES frames each (frames $FIRST..$((FIRST + FRAMES - 1))), 640x480, image output only (start-up, upload and PNG writing included)"
echo "machine: $(machine)"
"$NEW/glsplay" "$t/new/terrain.glsb" --camera "$t/new/rig.cam" --trajectory "$t/new/trajectory.txt" --explain 2>/dev/null |
    grep -E '^(backend|GL_RENDERER):'
echo "this build: $commit; base: $BASE (the build before issue 16, from git archive)"
echo "scenes: road = the road demo (the base's glsroad output, textured), left rig camera;"
echo "        terrain = bench/play_scene.h's height field, 100,352 triangles, its camera path"
echo "cases: $CASES (the keys files they name replace or add keys of the scene's camera; road + FILE:"
echo "       the road drawn by FILE, which adds lights or shadows, timed against the road unlit)"
echo
echo "| scene | effects | wall ms/frame, median (min..max) | CPU ms/frame | cost (change of the medians) |"
echo "|---|---|---|---|---|"
cat "$t/rows"
echo
echo "load average (1 min, other work on the machine included): $load0 before, $(loadavg 1) after"
} >"$OUT"
cat "$OUT"
