#!/bin/sh
# The limits of a bundle and of the player's instanced load (spec/bundle.md
# section 10, 12.2 item 9): a scene is bounded by its call paths (2^22, the
# player's instances), not by the vertices it draws once its calls are
# unrolled (2^26 bounds only --flatten), and no bundle makes the load walk
# its objects once per call path.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
# refused NAME RC WANT [OUT]: the command just run (stderr in $t/err, exit
# status RC) was refused with exactly WANT, exit 1, and wrote no OUT
refused() {
    if [ "$2" -eq 1 ] && [ "$(cat "$t/err")" = "$3" ] && { [ -z "$4" ] || [ ! -e "$4" ]; }; then
        ok "$1"
    else
        fail "$1" "rc=$2 $(head -2 "$t/err")"
    fi
}
need_players load_limits

# levels DIR N CALLEE BODY: DIR/L0..L(N-1).scene, each BODY then two calls
# of the next level, 3 * 2^(N-1-i) units apart along x; the last calls
# CALLEE
levels() {
    i=0
    while [ $i -lt "$2" ]; do
        next=L$((i + 1))
        [ $((i + 1)) -eq "$2" ] && next=$3
        printf '%s\ncall("%s");\ntrans(%d, 0, 0);\ncall("%s");\n' "$4" "$next" $((3 << ($2 - 1 - i))) "$next" \
            >"$1/L$i.scene"
        i=$((i + 1))
    done
}

# ---- 2^27 vertices once unrolled: accepted, drawn instanced ------------------
# A fan of 65536 vertices (radius 0.5, blue) called on 2^11 paths, 3 units
# apart: 2^27 vertices unrolled, 4095 call paths.  The camera at z = -4
# sees only the fan at the origin (the next is 30 px off its 32 px view).
mkdir "$t/big"
cat >"$t/big/Fan.scene" <<'SCENE'
color(0, 0, 1);
tfan { vert(0, 0, 0); repeat(k, 1, 65536) { vert(0.5 * cos(k * 360 / 65535), 0.5 * sin(k * 360 / 65535), 0); } }
SCENE
levels "$t/big" 11 Fan ""
printf 'width 32\nheight 32\nfx 40\nfy 40\ncx 15.5\ncy 15.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 4\nnear 0.1\nfar 100\n' \
    >"$t/front.cam"
if "$B/glsc" -I "$t/big" -o "$t/big.glsb" L0 2>"$t/err"; then
    ok load_limits_beyond_2p26_compiles
else
    fail load_limits_beyond_2p26_compiles "$(head -2 "$t/err")"
fi
if [ -f "$t/big.glsb" ] && "$B/glsplay" "$t/big.glsb" --camera "$t/front.cam" --outputs image -o "$t/big_out" \
    --explain >"$t/explain" 2>"$t/err" && grep -q '^instances: 4095 (2048 with geometry of their own' "$t/explain"; then
    # the fan's disc: radius 5 px around the centre, pi 25 = 78.5 px of
    # blue, nothing else (exact coverage, the default: its edge pixels are
    # partly blue, and the blue sums to the disc's area)
    if $PY - "$t/big_out/front/image_000000.png" <<'PYEOF'; then
import sys, cv2, numpy as np
im = cv2.imread(sys.argv[1])  # BGR
b = im[:, :, 0] / 255.0
n = b.sum()
v, u = np.mgrid[0:im.shape[0], 0:im.shape[1]]
cu, cv_ = (b * u).sum() / n, (b * v).sum() / n
print("# 2^27 unrolled vertices drawn instanced: %.2f px of blue (disc %.2f), centroid (%.3f, %.3f)" % (n, np.pi * 25, cu, cv_))
sys.exit(0 if abs(n - np.pi * 25) < 0.2 and abs(cu - 15.5) < 0.02 and abs(cv_ - 15.5) < 0.02 and im[:, :, 1:].max() == 0 else 1)
PYEOF
        ok load_limits_beyond_2p26_renders
    else
        fail load_limits_beyond_2p26_renders "the fan's pixels are not where they should be"
    fi
else
    fail load_limits_beyond_2p26_renders "$(head -2 "$t/err") $(grep '^instances' "$t/explain")"
fi
# --flatten holds every vertex of every path: refused before it builds
"$B/glsplay" "$t/big.glsb" --camera "$t/front.cam" --outputs image -o "$t/big_flat" --flatten 2>"$t/err"
refused load_limits_flatten_refused $? "glsplay: error: $t/big.glsb: L0 draws more than 67108864 vertices once its calls are unrolled: too large to flatten (drop --flatten to draw it instanced)" \
    "$t/big_flat/front/image_000000.png"

# ---- more than 2^22 call paths: refused by the compiler ----------------------
# 22 levels of two calls: 2^23 - 1 call paths to objects that draw nothing
mkdir "$t/paths"
echo 'color(1, 0, 0);' >"$t/paths/Leaf.scene"
levels "$t/paths" 22 Leaf ""
"$B/glsc" -I "$t/paths" -o "$t/paths.glsb" L0 2>"$t/err"
refused load_limits_call_paths_refused $? "glsc: error: L0 has more than 4194304 call paths (instances to draw) once its calls are unrolled: too many to render" \
    "$t/paths.glsb"

# ---- an object on many call paths is decoded once ---------------------------
# 17 levels, each with 100,000 colour instructions and two calls: 2^18 - 1
# call paths.  Walked once per path, that is 2.6e10 instructions (minutes);
# with each object's walk recorded and replayed, 1.8e6 and 262143 instances.
mkdir "$t/wide"
levels "$t/wide" 17 Leaf "repeat(k, 0, 100000) { color(1, 0, 0); }"
cp "$t/paths/Leaf.scene" "$t/wide/"
"$B/glsc" -I "$t/wide" -o "$t/wide.glsb" L0 2>"$t/err" || fail load_limits_replay_compiles "$(head -2 "$t/err")"
timeout 60 "$B/glsplay" "$t/wide.glsb" --explain >"$t/explain" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && grep -q '^instances: 262143 (0 with geometry of their own, 18 protos' "$t/explain"; then
    ok load_limits_replay_loads_quickly
else
    fail load_limits_replay_loads_quickly "rc=$rc (124: over 60 s) $(head -2 "$t/err")"
fi

# ---- the loader's instruction budget -----------------------------------------
# One object of 2,000,000 instructions entered with 150 colours: 150 protos,
# each walked once: 3e8 instructions, more than 2^28
mkdir "$t/budget"
echo 'repeat(k, 0, 2000000) { color(1, 1, 1); }' >"$t/budget/Heavy.scene"
echo 'repeat(i, 0, 150) { color(i / 149, 0, 0); call("Heavy"); }' >"$t/budget/Top.scene"
"$B/glsc" -I "$t/budget" -o "$t/budget.glsb" Top 2>"$t/err" || fail load_limits_budget_compiles "$(head -2 "$t/err")"
# 3 s here; a sanitized build is several times slower
timeout $([ "$GLS_SANITIZED" = 1 ] && echo 600 || echo 60) "$B/glsplay" "$t/budget.glsb" --explain >"$t/explain" 2>"$t/err"
refused load_limits_walk_budget_refused $? "glsplay: error: $t/budget.glsb: more than 268435456 instructions to walk (objects once per drawing state, inlined calls once per call): too large to load"

# ---- lights on all call paths --------------------------------------------------
# an ambient light called 65537 times: each path places one
mkdir "$t/lights"
echo 'ambient(0.001, 0.001, 0.001);' >"$t/lights/Amb.scene"
echo 'repeat(i, 0, 65537) { call("Amb"); }' >"$t/lights/Top.scene"
"$B/glsc" -I "$t/lights" -o "$t/lights.glsb" Top 2>"$t/err" || fail load_limits_lights_compiles "$(head -2 "$t/err")"
timeout 60 "$B/glsplay" "$t/lights.glsb" --explain >"$t/explain" 2>"$t/err"
refused load_limits_lights_refused $? "glsplay: error: $t/lights.glsb: more than 65536 lights (lights on every call path): too many to shade"

# ---- draw items: instances times the chunks of their geometry ------------------
# 65536 triangles, each in its own 64-unit cell: the chunk budget
# (spec/bundle.md 9.3) packs them in 256-unit cells, 4,096 chunks; called
# 16,385 times: 67,112,960 items, more than 2^26
mkdir "$t/items"
echo 'repeat(i, 0, 256) { repeat(j, 0, 256) { poly { vert(64 * i, 64 * j, 0); vert(64 * i + 1, 64 * j, 0); vert(64 * i, 64 * j + 1, 0); } } }' \
    >"$t/items/Spread.scene"
echo 'repeat(i, 0, 16385) { call("Spread"); }' >"$t/items/Top.scene"
"$B/glsc" -I "$t/items" -o "$t/items.glsb" Top 2>"$t/err" || fail load_limits_items_compiles "$(head -2 "$t/err")"
timeout 60 "$B/glsplay" "$t/items.glsb" --explain >"$t/explain" 2>"$t/err"
refused load_limits_items_refused $? "glsplay: error: $t/items.glsb: more than 67108864 draw items (instances times the chunks of their geometry): too many to draw"
