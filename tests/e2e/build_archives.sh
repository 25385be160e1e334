#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# The layers' static archives hold exactly the objects of their current
# sources: an archive is written from scratch, so the object of a source
# that was deleted or moved to another layer does not stay inside it (and
# get linked).  In a copy of the Makefile and base/, an extra source is
# added, the archive built, the source deleted and the archive built again:
# the second archive must not hold the deleted source's object.  The
# directory's time is then set to the archive's, as the kernel's coarse
# file clock leaves it when the deletion comes within a few ms of the
# archive (the CI once failed so), so that a rule on times alone fails
# every time rather than now and then.  Then the
# archives of $GLS_BIN (default build) are compared with the sources.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh

cp Makefile "$t/" && cp -r base "$t/base" || { echo "FAIL build_archives_from_scratch: cannot copy the tree"; exit 0; }
printf 'int gls_archive_probe(void);\nint gls_archive_probe(void) { return 1; }\n' >"$t/base/zz_archive_probe.c"
if make --no-print-directory -s -C "$t" B=out out/libglsbase.a >"$t/log" 2>&1 &&
    ar t "$t/out/libglsbase.a" | grep -qx zz_archive_probe.o; then
    rm "$t/base/zz_archive_probe.c"
    touch -r "$t/out/libglsbase.a" "$t/base"
    if ! make --no-print-directory -s -C "$t" B=out out/libglsbase.a >>"$t/log" 2>&1; then
        echo "FAIL build_archives_from_scratch: the rebuild failed: $(tail -1 "$t/log")"
    elif ar t "$t/out/libglsbase.a" | grep -qx zz_archive_probe.o; then
        echo "FAIL build_archives_from_scratch: the object of a deleted source stays in the archive"
    else
        echo "ok build_archives_from_scratch"
    fi
else
    echo "FAIL build_archives_from_scratch: the first build failed: $(tail -1 "$t/log")"
fi

# archive  its sources' directories (the runtime's rooms: runtime/*/)
# (without the tools' mains)  generated objects
while read -r lib dir extra; do
    [ -n "$lib" ] || continue
    [ -f "$B/$lib" ] || { echo "FAIL build_archives_$lib: no $B/$lib (run make)"; continue; }
    want=$( (for f in $dir/*.c; do basename "$f" .c; done | grep -v '_main$'; for e in $extra; do echo "$e"; done) |
        sed 's/$/.o/' | sort)
    got=$(ar t "$B/$lib" | sort)
    if [ "$want" = "$got" ]; then
        echo "ok build_archives_$lib"
    else
        echo "FAIL build_archives_$lib: members differ from $dir/*.c: $(printf '%s\n' "$want" "$got" | sort | uniq -u | tr '\n' ' ')"
    fi
done <<EOF
libglsbase.a base
libglsformat.a format
libglscompiler.a compiler lexer grammar
libglsruntime.a runtime/*
libglsroad.a roads
EOF
