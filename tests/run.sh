#!/bin/sh
# Run every test program and script; count "ok"/"FAIL" lines; print the
# closing line the CI reads: "N passed, N failed".
# Unit tests: build/tests/* (compiled from tests/unit/*.c).
# End-to-end tests: tests/e2e/*.sh, run from the repository root with
# GLS_BIN=build; they print the same "ok NAME" / "FAIL NAME" lines.
cd "$(dirname "$0")/.." || exit 2
B=${GLS_BIN:-build}
export GLS_BIN=$B
log=$(mktemp)
status=0
for t in "$B"/tests/*; do
    [ -x "$t" ] || continue
    echo "== $t"
    "$t" >"$log" 2>&1
    rc=$?
    cat "$log"
    if [ $rc -ne 0 ] && ! grep -q '^FAIL ' "$log"; then
        echo "FAIL $(basename "$t"): exited with status $rc"
    fi
done >"$B/test.log"
for t in tests/e2e/*.sh; do
    [ -f "$t" ] || continue
    echo "== $t"
    sh "$t" 2>&1
done >>"$B/test.log"
cat "$B/test.log"
passed=$(grep -c '^ok ' "$B/test.log")
failed=$(grep -c '^FAIL ' "$B/test.log")
rm -f "$log"
echo
grep '^FAIL ' "$B/test.log"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
