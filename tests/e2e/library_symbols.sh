#!/bin/sh
# sanitizers: not rerun (it checks the build: the sanitizer pass builds no shared library, tests/run.sh)
# libglscene (docs/api.md): the shared library has the soname
# libglscene.so.0 and exports the public API only (glscene_*, every
# function of include/glscene.h); no object of the library refers to the
# standard streams, exit or abort: errors come back as values, nothing is
# printed.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
so=$B/libglscene.so
[ -e "$so" ] && [ -e "$B/libglscene.a" ] || { echo "FAIL library_built: no $so or $B/libglscene.a (run make)"; exit 0; }
soname=$(objdump -p "$so" | awk '$1 == "SONAME" { print $2 }')
[ "$soname" = libglscene.so.0 ] && echo "ok library_soname" || echo "FAIL library_soname: '$soname'"
# the functions the header declares, and the functions the library exports
sed -n 's/^[a-z].*[ *]\(glscene_[a-z_]*\)(.*/\1/p' include/glscene.h | sort >"$t/declared"
nm -D --defined-only "$so" | awk '$2 == "T" { print $3 }' | sed 's/@.*//' | sort >"$t/exported"
if [ -s "$t/declared" ] && cmp -s "$t/declared" "$t/exported"; then
    echo "ok library_exports_the_api_only"
else
    echo "FAIL library_exports_the_api_only: $(diff "$t/declared" "$t/exported" | grep '^[<>]' | tr '\n' ' ')"
fi
# the sanitizers' runtime brings its own references; the check is the normal build's
if [ "$GLS_SANITIZED" != 1 ]; then
    bad=$(nm -A "$B/libglscene.a" 2>/dev/null | grep -E ' U (stderr|stdout|exit|_exit|abort|printf|puts|putchar|perror)$')
    [ -z "$bad" ] && echo "ok library_never_prints_or_exits" ||
        echo "FAIL library_never_prints_or_exits: $(echo "$bad" | tr '\n' ' ')"
fi
