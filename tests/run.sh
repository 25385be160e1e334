#!/bin/sh
# Run the test suite; count "ok NAME" / "FAIL NAME" lines; print the closing
# line the CI reads: "N passed, N failed".
#
# Always: the unit tests ($B/tests/*, from tests/unit/*.c) and the
# end-to-end scripts (tests/e2e/*.sh but lib.sh, the helpers they source;
# run from the repository root with GLS_BIN=$B), against the normal build
# in $B (GLS_BIN, default build).
#
# With CI=true (or GLS_FULL=1), also:
#   - the same suite against a clang ASan+UBSan build (build-asan), lines
#     prefixed "asan:", but for the scripts marked "# sanitizers: not
#     rerun" (they check the sources, the docs or the build itself);
#   - every fuzz target replays its corpus and regressions, then fuzzes for
#     GLS_FUZZ_SECONDS (default 15) under ASan+UBSan (tests/fuzz/run.sh),
#     GLS_FUZZ_JOBS (default 2) targets at a time;
#   - glsplay renders the demo once under valgrind: no errors, no leaks
#     outside Mesa (tests/valgrind.supp).
cd "$(dirname "$0")/.." || exit 2
B=${GLS_BIN:-build}
log=$B/test.log
: >"$log"

# took NAME T0: the line "# took S s NAME", the seconds since T0 (the
# slowest are listed at the end, for whoever shortens the suite)
took() { awk -v n="$1" -v a="$2" -v b="$(date +%s.%N)" 'BEGIN { printf "# took %.1f s %s\n", b - a, n }'; }

# suite BUILD: the unit tests and e2e scripts against BUILD, GLS_TEST_JOBS
# at a time (default: the number of CPUs; 1 runs them one after another).
# The tests share nothing but the build they read (each writes only under
# its own temporary directory), so side by side they give the same lines;
# each test's output is printed whole when it ends (tests/run_one.sh), so
# the blocks come in the order the tests finish.  The e2e scripts go
# first, those marked "# suite: long" (over a minute) before the others:
# a long job started last would run alone at the end.
suite() {
    lock=$(mktemp)
    : >"$lock.list"
    # the scripts marked "# suite: long" first, then the rest
    for t in $(grep -l '^# suite: long' tests/e2e/*.sh) $(grep -L '^# suite: long' tests/e2e/*.sh); do
        [ -f "$t" ] && [ "$t" != tests/e2e/lib.sh ] || continue
        # a script about the sources, the docs or the build itself runs
        # no sanitized code: the normal suite's run is the whole of it
        if [ "$GLS_SANITIZED" = 1 ] && grep -q '^# sanitizers: not rerun' "$t"; then
            echo "# not rerun under the sanitizers: $t"
            continue
        fi
        echo "e2e $t" >>"$lock.list"
    done
    for t in "$1"/tests/*; do
        [ -f "$t" ] && [ -x "$t" ] && echo "unit $t" # not the objects' directories
    done >>"$lock.list"
    xargs -P "$jobs" -L 1 sh tests/run_one.sh "$1" "$lock" <"$lock.list"
    rm -f "$lock" "$lock.list"
}

jobs=${GLS_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
echo "# $jobs tests at a time (GLS_TEST_JOBS)" | tee -a "$log"
suite "$B" | tee -a "$log"

if [ "$CI" = true ] || [ "$GLS_FULL" = 1 ]; then
    echo "== sanitizer build (clang, ASan + UBSan) in build-asan" | tee -a "$log"
    t0=$(date +%s.%N)
    export ASAN_OPTIONS=abort_on_error=0:detect_leaks=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    export LSAN_OPTIONS=suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0
    units=$(for f in tests/unit/*.c; do printf 'build-asan/tests/%s ' "$(basename "$f" .c)"; done)
    # distort_project: the lens model as a filter, run by distortion.sh;
    # glsplay_bands_whole: glsplay with whole bands, run by rolling_bands.sh.
    # Not the shared library (all but libglscene.so): a second compile of
    # every object with -fPIC, about 40% of this build, which no test loads
    # under the sanitizers (python cannot load an ASan-built library; the
    # library's exports are the normal build's check, library_symbols.sh)
    asan_all="build-asan/glsc build-asan/glsdis build-asan/glsplay build-asan/glsroad build-asan/textures.stamp"
    asan_all="$asan_all build-asan/scenelib.glsb build-asan/libglscene.a"
    if make --no-print-directory -s -j2 B=build-asan SANITIZE=1 CC=clang $asan_all $units build-asan/distort_project \
        build-asan/glsplay_bands_whole \
        >build-asan.log 2>&1; then
        export GLS_SANITIZED=1
        # references (65,536-sample images) from the normal build (lib.sh REF)
        export GLS_REF_BIN=$B
        suite build-asan | sed 's/^ok /ok asan:/; s/^FAIL /FAIL asan:/; s/^\(# took [0-9.]* s \)/\1asan:/' | tee -a "$log"
    else
        tail -20 build-asan.log
        echo "FAIL asan_build: see build-asan.log" | tee -a "$log"
    fi

    took "the sanitizer build and its suite (all)" "$t0" | tee -a "$log"
    echo "== fuzzing (libFuzzer, ASan + UBSan)" | tee -a "$log"
    t0=$(date +%s.%N)
    if make --no-print-directory -s -j2 fuzz-build >build-fuzz.log 2>&1; then
        export GLS_FUZZ_JOBS=${GLS_FUZZ_JOBS:-2} # two targets at a time: the CI machine has 2 cores
        sh tests/fuzz/run.sh 0 2>&1 | sed 's/^ok fuzz_/ok fuzz_replay_/; s/^FAIL fuzz_/FAIL fuzz_replay_/' | tee -a "$log"
        sh tests/fuzz/run.sh "${GLS_FUZZ_SECONDS:-15}" 2>&1 | tee -a "$log"
    else
        tail -20 build-fuzz.log
        echo "FAIL fuzz_build: see build-fuzz.log" | tee -a "$log"
    fi

    took "fuzzing (all)" "$t0" | tee -a "$log"
    echo "== valgrind: glsplay renders the demo" | tee -a "$log"
    t0=$(date +%s.%N)
    sh tests/valgrind.sh "$B" 2>&1 | tee -a "$log"
    took "valgrind (all)" "$t0" | tee -a "$log"
fi

passed=$(grep -c '^ok ' "$log")
failed=$(grep -c '^FAIL ' "$log")
echo
echo "the slowest (seconds):"
grep '^# took ' "$log" | sort -k3 -n -r | head -12 | cut -d' ' -f3,5-
grep '^FAIL ' "$log"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
