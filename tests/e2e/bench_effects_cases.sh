#!/bin/sh
# make bench-effects' cases (bench/effects.cases): the file parses, every
# case's keys file and scene exist, and each case renders one 64x48 frame of
# its own scene (the plan's top object)
# through bench/effects.sh's own functions (--check: no timing asserted).
# A broken case (a missing keys file, keys glsplay refuses, a line of three
# fields, a scene file that does not compile) fails with its reason.  A
# keys file's recipe line (fisheye.keys') runs as written.  Not
# under the sanitizers (CI's second pass builds no bench/play_bench; the
# normal pass checks the same script).  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
[ "$GLS_SANITIZED" = 1 ] && exit 0

# every case line renders: as many "ok case" lines as case lines, each case
# with its own scene (the plan's top object: road, terrain, or FILE's name
# for road:FILE)
sh bench/effects.sh --check "$BIN" >"$t/out" 2>"$t/err"
rc=$?
want=$(grep -cv '^[[:space:]]*\(#\|$\)' bench/effects.cases)
got=$(grep -c '^ok case ' "$t/out")
missing=""
grep -v '^[[:space:]]*\(#\|$\)' bench/effects.cases | tr -d ' ' | cut -d'|' -f1,2 | tr '|' ' ' >"$t/names"
while read -r n sc; do
    case $sc in road:*) top=$(basename "${sc#road:}" .scene) ;; *) top=$sc ;; esac
    grep -qxF "ok case $n ($sc): top object $top" "$t/out" || missing="$missing $n ($sc, top object $top)"
done <"$t/names"
if [ $rc -eq 0 ] && [ "$want" -gt 0 ] && [ "$got" -eq "$want" ] && [ -z "$missing" ]; then
    ok bench_effects_cases_render
else
    fail bench_effects_cases_render "status $rc, $got of $want cases, missing:$missing; $(cat "$t/out" "$t/err")"
fi

# broken CASE-LINE EXPECTED NAME: a case file of that one line fails with
# the expected message on stderr
broken() {
    printf '%s\n' "$1" >"$t/broken.cases"
    BE_CASES="$t/broken.cases" sh bench/effects.sh --check "$BIN" >"$t/out" 2>"$t/err"
    rc=$?
    if [ $rc -ne 0 ] && grep -qF "$2" "$t/err" && ! grep -q '^ok case' "$t/out"; then
        ok "$3"
    else
        fail "$3" "status $rc, want the message '$2'; $(cat "$t/out" "$t/err")"
    fi
}
printf 'shutter 2\n' >"$t/bad.keys"
printf 'light(directional, 0, 1, 0, 1, 1, 1);\ncall("no_such_unit");\n' >"$t/Bad.scene"
broken "gone | road | $t/none.keys | -" "bench-effects: case gone: no camera keys file $t/none.keys" \
    bench_effects_cases_missing_keys
broken "refused | road | $t/bad.keys | -" "bench-effects: case refused: glsplay failed" \
    bench_effects_cases_refused_keys
broken "short | road | -" "$t/broken.cases:1: 3 fields, want 4: name | scene | camera keys | options" \
    bench_effects_cases_fields
broken "lit | road:$t/Bad.scene | - | -" "bench-effects: case lit: glsc failed on $t/Bad.scene" \
    bench_effects_cases_scene
broken "odd | moon | - | -" "$t/broken.cases:1: unknown scene 'moon' (road, terrain or road:FILE)" \
    bench_effects_cases_unknown_scene

# The recipe a keys file gives in its comment ("#     sh
# bench/effects/with_keys.sh CAMERA KEYS >OUT.cam", fisheye.keys') runs as
# written, its output in the test's directory: the camera has the keys
# file's values in place of its own, each key once, and glsplay takes it.
# Appending the file instead is refused, as the comment says.
mkdir "$t/recipe"
printf 'color(0.5, 0.5, 0.5);\npoly { vert(-1, -1, 10); vert(1, -1, 10); vert(0, 1, 10); }\n' >"$t/recipe/Tri.scene"
"$BIN/glsc" -o "$t/recipe/tri.glsb" "$t/recipe/Tri.scene" 2>"$t/err" || fail bench_effects_keys_recipe "glsc: $(cat "$t/err")"
grep -l '^#     sh bench/effects/with_keys.sh ' bench/effects/*.keys >"$t/recipes"
grep -qx bench/effects/fisheye.keys "$t/recipes" || fail bench_effects_keys_recipe "fisheye.keys gives no recipe line"
while read -r k; do
    cmd=$(sed -n 's/^#     \(sh bench\/effects\/with_keys\.sh .*\)$/\1/p' "$k")
    out=${cmd##*>}
    cmd="${cmd%>*}>\"$t/recipe/$out\""
    cam=$(echo "$cmd" | cut -d' ' -f3)
    if ! sh -c "$cmd" 2>"$t/err"; then
        fail bench_effects_keys_recipe "$k: '$cmd' failed: $(cat "$t/err")"
        continue
    fi
    # every key of the keys file once, with the file's values
    bad=$(grep -v '^#' "$k" | while read -r key vals; do
        [ -n "$key" ] || continue
        [ "$(grep -c "^$key " "$t/recipe/$out")" -eq 1 ] && grep -qxF "$key $vals" "$t/recipe/$out" || echo "$key"
    done)
    if [ -n "$bad" ]; then
        fail bench_effects_keys_recipe "$k: not once with the file's values: $bad"
    elif ! "$BIN/glsplay" "$t/recipe/tri.glsb" --camera "$t/recipe/$out" --explain >/dev/null 2>"$t/err"; then
        fail bench_effects_keys_recipe "$k: glsplay refuses the camera: $(cat "$t/err")"
    else
        ok "bench_effects_keys_recipe_$(basename "$k" .keys)"
    fi
    # appended instead: refused on a key the camera has (fisheye: fx)
    cat "$cam" "$k" >"$t/recipe/appended.cam"
    dup=$(grep -v '^#' "$k" | cut -d' ' -f1 | while read -r key; do grep -q "^$key " "$cam" && echo "$key" && break; done)
    if [ -n "$dup" ]; then
        "$BIN/glsplay" "$t/recipe/tri.glsb" --camera "$t/recipe/appended.cam" --explain >/dev/null 2>"$t/err" &&
            fail bench_effects_keys_appended "$k appended to $cam is accepted" ||
            { grep -qF "key '$dup' given twice" "$t/err" && ok "bench_effects_keys_appended_$(basename "$k" .keys)" ||
                fail bench_effects_keys_appended "$k appended: $(cat "$t/err")"; }
    fi
done <"$t/recipes"
