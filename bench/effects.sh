#!/bin/sh
# make bench-effects: what the effects of issue 16 cost, and that they cost
# nothing when no scene or camera asks for one.  Writes docs/effects.txt.
# Not a pass/fail test.
#
# For each scene (road: the road demo, textured, left rig camera; terrain:
# bench/play_scene.h's 100,352-triangle height field; both 640x480, image
# output only, along their trajectories), time per frame of:
#   (a) the build before issue 16 (BE_BASE, default main's 0debd87), built
#       from `git archive` into a temporary directory (removed at the end),
#       or the build directory BE_BASE_BUILD when given;
#   (b) this build with no effect asked for: the same camera, the same
#       options;
#   (c) this build with each case of bench/effects.cases (one line each:
#       name, scene, camera keys, glsplay options).
# (a) and (b) run interleaved, a b a b ..., and each case interleaved with
# (b), so that a drift of the machine's load touches both sides alike.
# Time per frame = wall time of a whole glsplay run (start-up, upload, PNG
# writing included) / frames, and its CPU time (user + system, all threads;
# /usr/bin/time) / frames, which other work on a shared machine disturbs
# less; median, min and max of BE_RUNS runs.
#   BE_RUNS (default 7) runs per measurement; BE_FRAMES (default 12) frames
#   per run; BE_CASES (default bench/effects.cases).
# Both builds render the same scene text: the road as the base's glsroad
# writes it (later builds add landmarks, which draw nothing), compiled by
# each build's own glsc; the terrain as each build's play_bench writes it.
B=${1:-build}
RUNS=${BE_RUNS:-7}
FRAMES=${BE_FRAMES:-12}
CASES=${BE_CASES:-bench/effects.cases}
BASE=${BE_BASE:-0debd87}
OUT=docs/effects.txt
t=$(mktemp -d) && trap '[ -n "$BE_KEEP" ] || rm -rf "$t"' EXIT || exit 1
export GLIBC_TUNABLES=glibc.malloc.trim_threshold=4000000000:glibc.malloc.mmap_threshold=33554432
die() { echo "bench-effects: $*" >&2; exit 1; }
load0=$(cut -d' ' -f1 /proc/loadavg)
NEW=$(cd "$B" && pwd) || die "no build directory $B"

# (a): the build before issue 16
if [ -n "$BE_BASE_BUILD" ]; then
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
    eval "b=\$$(echo "$side" | tr a-z A-Z)"
    mkdir -p "$t/$side"
    "$b/glsc" -I "$b/scenelib.glsb" -I "$t/road" -o "$t/$side/road.glsb" "$t/road/road.scene" ||
        die "$side glsc failed on the road"
    "$b/bench/play_bench" --write "$t/$side" >/dev/null || die "$side play_bench --write failed"
done
[ -x "$OLD/bench/play_bench" ] || die "no $OLD/bench/play_bench"
ROAD_CAM="$OLD_SRC/examples/road/rig/left.cam"

# args SIDE SCENE: the glsplay arguments of a scene's plain run, less the camera
args() {
    case $2 in
    road) echo "$t/$1/road.glsb --trajectory $t/road/trajectory.txt --background 0.55,0.7,0.9" ;;
    terrain) echo "$t/$1/terrain.glsb --trajectory $t/$1/trajectory.txt" ;;
    *) die "unknown scene '$2' in $CASES (road or terrain)" ;;
    esac
}
# camera SIDE SCENE KEYS NAME: the camera file of a run (the scene's, with
# the keys file appended unless KEYS is -), named NAME.cam
camera() {
    mkdir -p "$t/cam/$4"
    if [ "$2" = road ]; then cat "$ROAD_CAM"; else cat "$t/$1/rig.cam"; fi >"$t/cam/$4/cam.cam"
    [ "$3" = - ] || cat "$3" >>"$t/cam/$4/cam.cam" || die "no camera keys file $3"
    echo "$t/cam/$4/cam.cam"
}
# the CPU time of a run too (user + system, GL's threads included), which
# other work on the machine disturbs less than the wall time
TIME=/usr/bin/time
[ -x "$TIME" ] || TIME=""
# once BIN SIDE SCENE CAMERA OPTIONS...: ms per frame of one glsplay run,
# wall and CPU ("-" without /usr/bin/time)
once() {
    # o_*: sh has no local variables, and the callers' names must survive
    o_bin=$1 o_side=$2 o_scene=$3 o_cam=$4
    shift 4
    rm -rf "$t/out"
    if [ -n "$TIME" ]; then
        # shellcheck disable=SC2046,SC2068
        "$TIME" -f "%e %U %S" -o "$t/time" "$o_bin/glsplay" $(args "$o_side" "$o_scene") --camera "$o_cam" \
            --frames "0:$FRAMES" --outputs image -o "$t/out" $@ 2>"$t/err" || { cat "$t/err" >&2; die "glsplay failed"; }
    else
        t0=$(date +%s.%N)
        # shellcheck disable=SC2046,SC2068
        "$o_bin/glsplay" $(args "$o_side" "$o_scene") --camera "$o_cam" --frames "0:$FRAMES" --outputs image -o "$t/out" $@ \
            2>"$t/err" || { cat "$t/err" >&2; die "glsplay failed"; }
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

echo "measuring: $RUNS runs of $FRAMES frames per figure" >&2
: >"$t/rows"
for scene in road terrain; do
    oldcam=$(camera old "$scene" - "old_$scene")
    newcam=$(camera new "$scene" - "new_$scene")
    : >"$t/a" && : >"$t/b"
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
    grep -v '^#' "$CASES" | grep '|' | while IFS='|' read -r name cscene keys opts; do
        name=$(echo $name) cscene=$(echo $cscene) keys=$(echo $keys) opts=$(echo $opts)
        [ "$cscene" = "$scene" ] || continue
        [ "$opts" = - ] && opts=""
        ccam=$(camera new "$scene" "$keys" "case_$name")
        : >"$t/c" && : >"$t/p"
        i=0
        while [ $i -lt "$RUNS" ]; do
            # the plain run with the same options, then the case
            # shellcheck disable=SC2086
            once "$NEW" new "$scene" "$newcam" $opts >>"$t/p" || exit 1
            # shellcheck disable=SC2086
            once "$NEW" new "$scene" "$ccam" $opts >>"$t/c" || exit 1
            i=$((i + 1))
        done
        wc=$(stats "$t/c" 1) wp=$(stats "$t/p" 1) cc=$(stats "$t/c" 2) cp=$(stats "$t/p" 2)
        printf '| %s | %s%s | %s | %s | wall %s, CPU %s against the same run without it (%s, %s) |\n' "$scene" \
            "$name" "${opts:+ ($opts)}" "$(fmt "$wc")" "$(fmt "$cc")" "$(cost "$wp" "$wc")" "$(cost "$cp" "$cc")" \
            "$(fmt "$wp")" "$(fmt "$cp")" >>"$t/rows"
    done || exit 1
done

commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- runtime base format compiler roads 2>/dev/null || commit="$commit + uncommitted changes"
{
echo "make bench-effects ($(date -u +%Y-%m-%d)): time per frame, ms, median (min..max) of $RUNS whole glsplay"
echo "runs of $FRAMES frames each, 640x480, image output only (start-up, upload and PNG writing included)"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores, $(uname -sr)"
"$NEW/glsplay" "$t/new/terrain.glsb" --camera "$t/new/rig.cam" --trajectory "$t/new/trajectory.txt" --explain 2>/dev/null |
    grep -E '^GL_RENDERER:'
echo "this build: $commit; base: $BASE (the build before issue 16, from git archive)"
echo "scenes: road = the road demo (the base's glsroad output, textured), left rig camera;"
echo "        terrain = bench/play_scene.h's height field, 100,352 triangles, its camera path"
echo "cases: $CASES (the camera keys files they name are appended to the scene's camera)"
echo
echo "| scene | effects | wall ms/frame, median (min..max) | CPU ms/frame | cost (change of the medians) |"
echo "|---|---|---|---|---|"
cat "$t/rows"
echo
echo "load average (1 min, other work on the machine included): $load0 before, $(cut -d' ' -f1 /proc/loadavg) after"
} >"$OUT"
cat "$OUT"
