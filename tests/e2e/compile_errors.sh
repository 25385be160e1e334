#!/bin/sh
# Every file in tests/errors/ is a scene that must fail to compile with
# exactly the diagnostics written in it on lines starting with "//> "
# (message, source line and caret, verbatim).  A case is either NAME.scene
# (compiled with -I tests/errors) or NAME/Top.scene (compiled with -I NAME).
# Each must exit with status 1 and leave no output file behind.
BIN=${GLS_BIN:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for f in tests/errors/*.scene tests/errors/*/Top.scene; do
    [ -f "$f" ] || continue
    root=tests/errors
    [ "$(basename "$f")" = Top.scene ] && root=$(dirname "$f")
    name=$(echo "$f" | sed 's|tests/errors/||; s|/Top.scene||; s|\.scene$||')
    sed -n 's|^//> \{0,1\}||p' "$f" >"$tmp/expected"
    "$BIN/glsc" -I "$root" -o "$tmp/out.glsb" "$f" >"$tmp/stdout" 2>"$tmp/actual"
    rc=$?
    if [ $rc -ne 1 ]; then
        echo "FAIL error_$name: exit status $rc, expected 1"
    elif [ -e "$tmp/out.glsb" ] || ls "$tmp"/out.glsb.tmp* >/dev/null 2>&1; then
        echo "FAIL error_$name: an output file was left behind"
    elif ! cmp -s "$tmp/expected" "$tmp/actual"; then
        echo "FAIL error_$name: diagnostics differ (expected, actual):"
        diff "$tmp/expected" "$tmp/actual" | sed 's/^/    /'
    elif [ ! -s "$tmp/expected" ]; then
        echo "FAIL error_$name: no expected diagnostics written in the file"
    else
        echo "ok error_$name"
    fi
    rm -f "$tmp/out.glsb"
done
