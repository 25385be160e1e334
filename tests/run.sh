#!/bin/sh
# Run every test program and script; count "ok"/"FAIL" lines; print the
# closing line the CI reads: "N passed, N failed".
# Unit tests: build/tests/* (compiled from tests/unit/*.c).
# End-to-end tests: tests/e2e/*.sh, run from the repository root with
# GLS_BIN=build; they print the same "ok NAME" / "FAIL NAME" lines.
cd "$(dirname "$0")/.." || exit 2
log=$(mktemp)
status=0
for t in build/tests/*; do
    [ -x "$t" ] || continue
    echo "== $t"
    "$t" >"$log" 2>&1
    rc=$?
    cat "$log"
    if [ $rc -ne 0 ] && ! grep -q '^FAIL ' "$log"; then
        echo "FAIL $(basename "$t"): exited with status $rc"
    fi
done >build/test.log
for t in tests/e2e/*.sh; do
    [ -f "$t" ] || continue
    echo "== $t"
    GLS_BIN=build sh "$t" 2>&1
done >>build/test.log
cat build/test.log
passed=$(grep -c '^ok ' build/test.log)
failed=$(grep -c '^FAIL ' build/test.log)
rm -f "$log"
echo
grep '^FAIL ' build/test.log
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
