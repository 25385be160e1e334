#!/bin/sh
# One job of tests/run.sh's suite: runs one unit test or e2e script
# against the build BUILD, then prints its whole output as one block
# (under a lock, so that jobs running side by side never interleave their
# lines), the block ending with "# took S s NAME".
#     sh tests/run_one.sh BUILD LOCKFILE KIND PATH
# KIND is unit (an executable of BUILD/tests) or e2e (a tests/e2e script,
# run with GLS_BIN=BUILD).  A unit test that exits non-zero without a
# "FAIL " line of its own gets one, so a crash is counted.
B=$1 lock=$2 kind=$3 t=$4
out=$(mktemp) || exit 1
t0=$(date +%s.%N)
if [ "$kind" = unit ]; then
    "$t" >"$out" 2>&1
    rc=$?
    if [ $rc -ne 0 ] && ! grep -q '^FAIL ' "$out"; then
        echo "FAIL $(basename "$t"): exited with status $rc" >>"$out"
    fi
else
    GLS_BIN=$B sh "$t" >"$out" 2>&1
fi
took=$(awk -v n="$t" -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "# took %.1f s %s\n", b - a, n }')
flock "$lock" sh -c 'echo "== $1"; cat "$2"; echo "$3"' sh "$t" "$out" "$took"
rm -f "$out"
