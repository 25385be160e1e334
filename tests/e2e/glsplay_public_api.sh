#!/bin/sh
# sanitizers: not rerun (it checks the build: the sanitizer pass builds no shared library, tests/run.sh)
# glsplay is built on libglscene's public API (docs/api.md "How glsplay
# uses it"): its main object reaches the library through the functions
# include/glscene.h declares and libglscene.so exports (lib/glscene.map),
# and nothing else of it; the tools' own helpers (base/usage.c,
# base/stdout_check.c, which the library leaves out) and the C library
# aside.  So the same main linked against the shared library, which hides
# every internal symbol, links, and renders the same bytes as glsplay.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
main=$B/apps/glsplay_main.o
so=$B/libglscene.so
for f in "$main" "$so" "$B/libglscene.a" "$B/base/usage.o" "$B/base/stdout_check.o"; do
    [ -e "$f" ] || { echo "FAIL glsplay_public_api: no $f (run make all)"; exit 0; }
done

# the symbols main needs that the library or base define, and what may be
# taken from them: the exported API and the two tool helpers
nm -u "$main" | awk '{ print $2 }' | sort -u >"$t/needed"
{ nm --defined-only "$B/libglscene.a"; nm --defined-only "$B/libglsbase.a"; } 2>/dev/null |
    awk 'NF == 3 && $2 ~ /[TDBRC]/ { print $3 }' | sort -u >"$t/ours"
{ nm -D --defined-only "$so" | awk '$2 == "T" { print $3 }' | sed 's/@.*//'
  nm --defined-only "$B/base/usage.o" "$B/base/stdout_check.o" | awk 'NF == 3 && $2 == "T" { print $3 }'; } |
    sort -u >"$t/allowed"
bad=$(comm -12 "$t/needed" "$t/ours" | comm -23 - "$t/allowed" | tr '\n' ' ')
uses=$(comm -12 "$t/needed" "$t/allowed" | grep -c '^glscene_')
if [ -z "$bad" ] && [ "$uses" -gt 0 ]; then
    echo "ok glsplay_main_uses_public_api_only"
else
    echo "FAIL glsplay_main_uses_public_api_only: glsplay_main.o refers to internal symbols: ${bad:-none}; glscene_* used: $uses"
fi

if ${CC:-cc} "$main" "$B/base/usage.o" "$B/base/stdout_check.o" -L"$B" -lglscene -o "$t/glsplay_so" 2>"$t/link.err"; then
    echo "ok glsplay_links_against_shared_library"
else
    echo "FAIL glsplay_links_against_shared_library: $(head -c 600 "$t/link.err" | tr '\n' ' ')"
    exit 0
fi
# the same render through both: the same files, byte for byte
"$B/glsc" -I examples/demo -I "$B/textures" -o "$t/demo.glsb" examples/demo/Demo.scene 2>"$t/err" ||
    { echo "FAIL glsplay_on_shared_library_same_files: glsc: $(head -c 300 "$t/err")"; exit 0; }
args="--camera examples/demo/left.cam --camera examples/demo/right.cam --size 160x120 --aa 2 --outputs image,depth,points,instance,normals"
"$B/glsplay" "$t/demo.glsb" $args -o "$t/a" >"$t/a.out" 2>&1
rca=$?
LD_LIBRARY_PATH=$B "$t/glsplay_so" "$t/demo.glsb" $args -o "$t/b" >"$t/b.out" 2>&1
rcb=$?
if [ $rca = 0 ] && [ $rcb = 0 ] && diff -r "$t/a" "$t/b" >/dev/null && [ -s "$t/a/left/image_000000.png" ]; then
    echo "ok glsplay_on_shared_library_same_files"
else
    echo "FAIL glsplay_on_shared_library_same_files: rc $rca/$rcb: $(diff -r "$t/a" "$t/b" 2>&1 | head -3 | tr '\n' ' ') $(head -c 300 "$t/b.out")"
fi
# and the same usage error, word for word
"$B/glsplay" "$t/demo.glsb" --aa 0 >"$t/ua" 2>&1
rca=$?
LD_LIBRARY_PATH=$B "$t/glsplay_so" "$t/demo.glsb" --aa 0 >"$t/ub" 2>&1
rcb=$?
if [ $rca = 2 ] && [ $rcb = 2 ] && cmp -s "$t/ua" "$t/ub" &&
    grep -qx "glsplay: error: --aa needs N in 1..4096, exact or auto, got '0' (try glsplay --help)" "$t/ub"; then
    echo "ok glsplay_on_shared_library_same_usage_error"
else
    echo "FAIL glsplay_on_shared_library_same_usage_error: rc $rca/$rcb: $(cat "$t/ub")"
fi
