#!/bin/sh
# Every file in tests/errors/ is a scene that must fail to compile with
# exactly the diagnostics written in it on lines starting with "//> "
# (message, source line and caret, verbatim).  A case is either NAME.scene
# (compiled with -I tests/errors) or NAME/Top.scene (compiled with -I NAME).
# Each must exit with status 1 and leave no output file behind.
# tests/warnings/ holds cases the same way that compile, with warnings:
# exit status 0, the bundle written, the diagnostics exactly as written.
. tests/e2e/lib.sh
tmp=$t
for f in tests/errors/*.scene tests/errors/*/Top.scene tests/warnings/*.scene tests/warnings/*/Top.scene; do
    [ -f "$f" ] || continue
    case $f in tests/warnings/*) dir=tests/warnings want=0 kind=warning ;; *) dir=tests/errors want=1 kind=error ;; esac
    root=$dir
    [ "$(basename "$f")" = Top.scene ] && root=$(dirname "$f")
    name=$(echo "$f" | sed "s|$dir/||; s|/Top.scene||; s|\.scene\$||")
    sed -n 's|^//> \{0,1\}||p' "$f" >"$tmp/expected"
    "$BIN/glsc" -I "$root" -o "$tmp/out.glsb" "$f" >"$tmp/stdout" 2>"$tmp/actual"
    rc=$?
    if [ $rc -ne $want ]; then
        echo "FAIL ${kind}_$name: exit status $rc, expected $want"
    elif [ $want -ne 0 ] && { [ -e "$tmp/out.glsb" ] || ls "$tmp"/out.glsb.tmp* >/dev/null 2>&1; }; then
        echo "FAIL ${kind}_$name: an output file was left behind"
    elif [ $want -eq 0 ] && [ ! -s "$tmp/out.glsb" ]; then
        echo "FAIL ${kind}_$name: no bundle written"
    elif ! cmp -s "$tmp/expected" "$tmp/actual"; then
        echo "FAIL ${kind}_$name: diagnostics differ (expected, actual):"
        diff "$tmp/expected" "$tmp/actual" | sed 's/^/    /'
    elif [ ! -s "$tmp/expected" ]; then
        echo "FAIL ${kind}_$name: no expected diagnostics written in the file"
    else
        echo "ok ${kind}_$name"
    fi
    rm -f "$tmp/out.glsb"
done
