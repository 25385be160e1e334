#!/bin/sh
# Named instances (spec/language.md 7, spec/bundle.md 7.8): a call with an
# instance name compiles to calln, glsdis shows it with its name, a library
# keeps the names of its objects' calls, and the player draws a named
# instance where the same call without a name is drawn: the same image,
# byte for byte.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
D=examples/demo
mkdir -p "$t/named" "$t/plain" "$t/lib/v"
# the demo scene with two of its objects named
sed 's|call("demo.BoxRed");|call("demo.BoxRed", "box_red");|; s|call("demo.Board");|call("demo.Board", "board-1.a");|' \
    "$D/Demo.scene" >"$t/named/Demo.scene"
cp "$D/Demo.scene" "$t/plain/Demo.scene"
for v in named plain; do
    "$B/glsc" -I "$D" -I "$B/textures" -I "$B/scenelib.glsb" -o "$t/$v.glsb" "$t/$v/Demo.scene" 2>"$t/err_$v" ||
        fail "instances_compile_$v" "$(cat "$t/err_$v")"
done
"$B/glsdis" "$t/named.glsb" >"$t/named.dis"
if grep -q '^  calln demo.BoxRed "box_red"$' "$t/named.dis" && grep -q '^  calln demo.Board "board-1.a"$' "$t/named.dis" &&
    grep -q '^instance names: 2$' "$t/named.dis"; then
    ok instances_glsdis_calln
else
    fail instances_glsdis_calln "$(grep -n 'calln\|instance' "$t/named.dis")"
fi
# the dump differs only in those two lines and the count
"$B/glsdis" "$t/plain.glsb" >"$t/plain.dis"
n=$(diff "$t/plain.dis" "$t/named.dis" | grep -c '^[<>]')
[ "$n" -eq 5 ] && ok instances_dump_only_names || fail instances_dump_only_names "$n lines differ"

# drawn as the call without a name: identical images
for v in named plain; do
    "$B/glsplay" "$t/$v.glsb" --camera "$D/left.cam" --outputs image -o "$t/out_$v" 2>"$t/perr_$v" ||
        fail "instances_render_$v" "$(cat "$t/perr_$v")"
done
a=$(ls "$t"/out_named/*/image_000000.png 2>/dev/null | head -1)
b=$(ls "$t"/out_plain/*/image_000000.png 2>/dev/null | head -1)
if [ -s "$a" ] && cmp -s "$a" "$b"; then ok instances_render_as_call; else fail instances_render_as_call "images differ or missing ($a, $b)"; fi

# a library keeps its objects' names; a scene that draws the object once
# gets them, one that draws it twice is refused
printf 'poly { vert(0, 0, 0); vert(1, 0, 0); vert(1, 1, 0); }\n' >"$t/lib/v/Car.scene"
printf 'call("v.Car", "lead");\ntrans(4, 0, 0);\ncall("v.Car");\n' >"$t/lib/v/Pair.scene"
(cd "$t/lib" && "$OLDPWD/$B/glsc" --lib . -o "$t/lib.glsb") 2>"$t/lerr" || fail instances_library "$(cat "$t/lerr")"
printf 'call("v.Pair");\n' >"$t/Once.scene"
printf 'call("v.Pair");\ncall("v.Pair");\n' >"$t/Twice.scene"
if "$B/glsc" -I "$t/lib.glsb" -o "$t/once.glsb" "$t/Once.scene" 2>"$t/oerr" &&
    "$B/glsdis" "$t/once.glsb" | grep -q '^  calln v.Car "lead"$'; then
    ok instances_library_names_kept
else
    fail instances_library_names_kept "$(cat "$t/oerr")"
fi
"$B/glsc" -I "$t/lib.glsb" -o "$t/twice.glsb" "$t/Twice.scene" 2>"$t/terr"
rc=$?
if [ $rc -eq 1 ] && grep -q 'instance name "lead" is on a call reached 2 times through the call tree (v.Pair is drawn 2 times)' "$t/terr" &&
    [ ! -e "$t/twice.glsb" ]; then
    ok instances_library_reached_twice
else
    fail instances_library_reached_twice "exit $rc: $(cat "$t/terr")"
fi
