#!/bin/sh
# glsplay renders the demo scene once (small, 160x120, all outputs) under
# valgrind memcheck, through each GL backend this glsplay has (EGL and
# OSMesa, spec/backends.md): no invalid access, no use of uninitialised
# values, no definite leak outside Mesa (tests/valgrind.supp: OSMesa keeps
# one block per context; EGL needs no suppression).  Prints ok/FAIL.
B=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! command -v valgrind >/dev/null; then
    echo "FAIL valgrind_glsplay: valgrind is not installed"
    exit 0
fi
"$B/glsc" -I examples/demo -I "$B/textures" -o "$tmp/demo.glsb" examples/demo/Demo.scene || {
    echo "FAIL valgrind_glsplay: the demo does not compile"
    exit 0
}
for be in egl osmesa; do
    if ! "$B/glsplay" --backend $be --help >/dev/null 2>&1; then
        echo "note: valgrind: this glsplay has no $be backend"
        continue
    fi
    valgrind --error-exitcode=3 --leak-check=full --errors-for-leak-kinds=definite --show-leak-kinds=definite \
        --suppressions=tests/valgrind.supp "$B/glsplay" "$tmp/demo.glsb" --camera examples/demo/left.cam \
        --camera examples/demo/right.cam --size 160x120 --backend $be -o "$tmp/out_$be" >"$tmp/log" 2>&1
    rc=$?
    if [ $rc -eq 0 ] && [ -f "$tmp/out_$be/right/points_000000.ply" ]; then
        echo "ok valgrind_glsplay_$be ($(grep -o 'ERROR SUMMARY: [0-9]* errors' "$tmp/log"))"
    else
        grep -E 'Invalid|uninitialised|definitely lost|ERROR SUMMARY' "$tmp/log" | head -10 | sed 's/^/  /'
        echo "FAIL valgrind_glsplay_$be: valgrind exit status $rc"
    fi
done
