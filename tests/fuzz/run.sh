#!/bin/sh
# usage: sh tests/fuzz/run.sh SECONDS [TARGET...]
# Fuzz each target (default: all) for SECONDS with libFuzzer under ASan and
# UBSan (build them first: make fuzz-build).  Every target first replays
# its whole corpus (tests/fuzz/corpus/T) and every input that ever crashed
# it (tests/fuzz/regressions/T).  New inputs that add coverage are merged
# into the corpus unless CI=true; a crash is copied to regressions/T and
# fails the run.  SECONDS=0 only replays.  Prints "ok fuzz_T" / "FAIL
# fuzz_T" and one statistics line per target.
#
# GLS_FUZZ_JOBS=N (default 1) fuzzes N targets at a time, one process
# each (the CI uses 2, its core count); each target's lines are printed
# together, in the order of the targets, whatever the order they finish.
secs=${1:-60}
shift
targets=${*:-"compile bundle texture camera road writers"}
F=build-fuzz/fuzz
jobs=${GLS_FUZZ_JOBS:-1}
# ASan fills every allocation with 0xFF (default: 0xBE, first 4 KiB only),
# so a read of memory never written gives the same wrong value on every
# run, and an index taken from it goes out of bounds at once (README,
# finding 10: stb_image's undefined JPEG tables)
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}malloc_fill_byte=255:max_malloc_fill_size=268435456"

# fuzz_one T: replay and fuzz one target; prints its lines, returns 1 on failure
fuzz_one() {
    t=$1
    status=0
    bin=$F/fuzz_$t
    if [ ! -x "$bin" ]; then
        echo "FAIL fuzz_$t: $bin not built (make fuzz-build)"
        return 1
    fi
    corpus=tests/fuzz/corpus/$t
    regr=tests/fuzz/regressions/$t
    mkdir -p "$corpus" "$regr"
    work=$(mktemp -d)
    log=$work/log
    if [ "$secs" = 0 ]; then
        "$bin" -runs=0 -rss_limit_mb=4096 "$corpus" "$regr" >"$log" 2>&1
    else
        "$bin" -max_total_time="$secs" -rss_limit_mb=4096 -timeout=10 -print_final_stats=1 \
            -artifact_prefix="$work/" "$work" "$corpus" "$regr" >"$log" 2>&1
    fi
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | sed 's/cov: //')
    echo "fuzz $t: ${secs}s, ${execs:-replay} executions, coverage ${cov:-?} edges, corpus $(ls "$corpus" | wc -l) inputs, regressions $(ls "$regr" | wc -l)"
    if [ $rc -ne 0 ]; then
        for a in "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-*; do
            [ -f "$a" ] && cp "$a" "$regr/" && echo "  saved $regr/$(basename "$a")"
        done
        grep -m3 -E 'ERROR|SUMMARY|runtime error' "$log" | sed 's/^/  /'
        echo "FAIL fuzz_$t: libFuzzer exited with status $rc"
        status=1
    else
        echo "ok fuzz_$t"
        if [ "$secs" != 0 ] && [ "$CI" != true ] && [ -n "$(ls "$work" | grep -v '^log$')" ]; then
            "$bin" -merge=1 "$corpus" "$work" >/dev/null 2>&1
        fi
    fi
    rm -rf "$work"
    return $status
}

out=$(mktemp -d)
status=0
set -- $targets
while [ $# -gt 0 ]; do
    batch=
    n=0
    while [ $# -gt 0 ] && [ $n -lt "$jobs" ]; do
        (fuzz_one "$1" >"$out/$1.log" 2>&1; echo $? >"$out/$1.rc") &
        batch="$batch $1"
        n=$((n + 1))
        shift
    done
    wait
    for t in $batch; do
        cat "$out/$t.log"
        [ "$(cat "$out/$t.rc")" = 0 ] || status=1
    done
done
rm -rf "$out"
exit $status
