#!/bin/sh
# glsc's unknown-texture message names where the build generates the
# scene library's textures (spec/language.md, 2.1): `glsc -I scenelib`
# alone cannot find them (in $GLS_BIN/textures).  Prints "ok NAME" /
# "FAIL NAME: why".
. tests/e2e/lib.sh
[ -x "$B/glsc" ] && [ -f "$B/textures/road/vegetation/tex/Birch.tga" ] || { echo "FAIL texture_hint: no $B/glsc or textures"; exit 0; }
"$B/glsc" -I scenelib -o "$t/box.glsb" scenelib/road/vegetation/Birch.scene 2>"$t/err"
rc=$?
want="scenelib/road/vegetation/Birch.scene:18:10: error: unknown texture 'road.vegetation.tex.Birch' (searched: scenelib; extensions .tga .png .jpg .jpeg .bmp); the build generates it in $B/textures: add -I $B/textures"
if [ $rc -eq 1 ] && [ "$(head -1 "$t/err")" = "$want" ] && [ "$(wc -l <"$t/err")" -eq 3 ]; then
    echo "ok texture_hint_scenelib"
else
    echo "FAIL texture_hint_scenelib: exit $rc: $(cat "$t/err")"
fi
# and the advice works
if "$B/glsc" -I scenelib -I "$B/textures" -o "$t/box.glsb" scenelib/road/vegetation/Birch.scene 2>"$t/err"; then
    echo "ok texture_hint_advice_works"
else
    echo "FAIL texture_hint_advice_works: $(cat "$t/err")"
fi
# a texture the build does not generate gets no such note
mkdir -p "$t/lib" && echo 'texture("tex.Missing"); poly { vert(0,0,0); vert(1,0,0); vert(0,1,0); }' >"$t/lib/Top.scene"
"$B/glsc" -I "$t/lib" -o "$t/top.glsb" "$t/lib/Top.scene" 2>"$t/err"
if grep -q "unknown texture 'tex.Missing'" "$t/err" && ! grep -q "generates" "$t/err"; then
    echo "ok texture_hint_only_generated"
else
    echo "FAIL texture_hint_only_generated: $(cat "$t/err")"
fi
# every object of the scene library is written in scenelib/ itself (its
# variants are parameterised objects there): the directory and the
# generated textures are the whole library, and an unknown object gets no
# note about the build
if "$B/glsc" -I scenelib -I "$B/textures" -o "$t/street.glsb" scenelib/scenes/Street.scene 2>"$t/err"; then
    echo "ok scenelib_directory_is_the_library"
else
    echo "FAIL scenelib_directory_is_the_library: $(head -3 "$t/err")"
fi
echo 'call("road.NoSuch");' >"$t/lib/Top.scene"
"$B/glsc" -I "$t/lib" -o "$t/top.glsb" "$t/lib/Top.scene" 2>"$t/err"
if grep -q "unknown object 'road.NoSuch' (searched: $t/lib)\$" "$t/err"; then
    echo "ok object_unknown_without_note"
else
    echo "FAIL object_unknown_without_note: $(head -1 "$t/err")"
fi
