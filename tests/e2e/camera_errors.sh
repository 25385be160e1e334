#!/bin/sh
# Every file in tests/errors/camera/ is a camera file (.cam, or OpenCV YAML .yml) that glsplay must
# refuse with exactly the diagnostics written in it on lines starting with
# "#> " (message, source line, caret), exit status 1, and no output.
. tests/e2e/lib.sh
tmp=$t
"$BIN/glsc" -I tests/compiler/lang -o "$tmp/leaf.glsb" pkg.Leaf || { echo "FAIL camera_errors: setup"; exit 0; }
for f in tests/errors/camera/*.cam tests/errors/camera/*.yml; do
    cam=$(basename "$f" | sed 's/\.\(cam\|yml\)$//') # its output name
    name=camera_error_$cam
    sed -n 's/^#> //p' "$f" >"$tmp/expected"
    "$BIN/glsplay" "$tmp/leaf.glsb" --camera "$f" -o "$tmp/out" >/dev/null 2>"$tmp/actual"
    rc=$?
    if [ $rc -ne 1 ]; then
        echo "FAIL $name: exit status $rc, expected 1"
    elif [ -e "$tmp/out/$cam" ] && [ -n "$(ls "$tmp/out/$cam")" ]; then
        echo "FAIL $name: output written"
    elif [ ! -s "$tmp/expected" ] || ! cmp -s "$tmp/expected" "$tmp/actual"; then
        echo "FAIL $name: diagnostics differ (expected, actual):"
        diff "$tmp/expected" "$tmp/actual" | sed 's/^/    /'
    else
        echo "ok $name"
    fi
done
