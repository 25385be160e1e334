#!/bin/sh
# glsplay --aa exact on textured and lit scenes (spec/antialiasing.md
# "Exact coverage in glsplay"): a region's colour is the mean of the
# shader, evaluated on the CPU as GL evaluates it, at the pixel's 64
# lattice points inside the region; measured against 65,536 lattice
# samples (--aa 256), which see every texel magnified (GL's base level)
# and carry 8-bit samples.  A planar quadrilateral tilted in depth, its
# texture magnified (a coarse 8x8 texture, about 3 px a texel, replace)
# and near one texel a pixel (modulate); one plain pass is far off, and
# the region's colour at its centroid alone is off by 0.27 on the fine
# one (checked by hand: the bound below fails it).  Prints "ok NAME" /
# "FAIL NAME: why".
. tests/e2e/lib.sh
PLAY=$B/glsplay
[ -x "$PLAY" ] || { fail player_aa_exact_shade "no $PLAY"; exit 0; }
mkdir -p "$t/lib/tx"
$PY -c "
import cv2, numpy as np
r = np.random.default_rng(5)
cv2.imwrite('$t/lib/tx/Check.png', (r.random((8, 8, 3)) * 255).astype(np.uint8))" ||
    { fail exact_shade_texture "no texture written"; exit 0; }
quad() { # texture mode, repeats
    printf 'color(1, 0.8, 0.6);\ntexture("tx.Check");\ntexmode(%s);\n' "$1"
    printf 'poly { tex(0, 0); vert(-1.25, -0.5, 3.75); tex(%s, 0); vert(0.75, -0.75, 5.75); ' "$2"
    printf 'tex(%s, %s); vert(1.0, 1.25, 6); tex(0, %s); vert(-1.0, 1.5, 4); }\n' "$2" "$2" "$2"
}
quad replace 1.5 >"$t/Coarse.scene"
quad modulate 6 >"$t/Fine.scene"
cat >"$t/c.cam" <<'CAM'
width 64
height 48
fx 100
fy 100
cx 31.3
cy 23.6
R 1 0 0 0 1 0 0 0 1
T 0 0 0
near 0.1
far 100
CAM
# render NAME: exact, 65,536 samples and one pass of $t/NAME.glsb
render() {
    for m in "--aa exact:ex" "--aa 256:ref" "--aa 1:one"; do
        p=$PLAY && [ "${m##*:}" = ref ] && p=$REF/glsplay # the reference: lib.sh's REF
        "$p" "$t/$1.glsb" --camera "$t/c.cam" ${m%%:*} --image-format pfm --outputs image -o "$t/$1_${m##*:}" \
            2>"$t/err" || { fail exact_shade_render_$1 "${m%%:*}: $(cat "$t/err")"; return 1; }
    done
}
# compare NAME TEST MAX MEAN: exact within MAX and MEAN of the reference,
# one pass not
compare() {
    $PY - "$t" "$@" <<'PYEOF'
import sys, cv2, numpy as np
t, name, test, bmax, bmean = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
def read(k):
    return cv2.imread('%s/%s_%s/c/image_000000.pfm' % (t, name, k), cv2.IMREAD_UNCHANGED).astype(np.float64)
ref = read('ref')
d, o = np.abs(read('ex') - ref), np.abs(read('one') - ref)
ok = d.max() <= bmax and d.mean() <= bmean and (o.max() > bmax or o.mean() > bmean)
print(('ok ' if ok else 'FAIL ') + test + ('' if ok else ': max %g mean %g (bounds %g, %g); one pass max %g mean %g'
                                           % (d.max(), d.mean(), bmax, bmean, o.max(), o.mean())))
print('  %s: exact against 65,536 samples: max %.3g mean %.3g; one pass: max %.3g mean %.3g'
      % (name, d.max(), d.mean(), o.max(), o.mean()))
PYEOF
}
for s in Coarse Fine; do
    "$B/glsc" -I "$t/lib" -o "$t/$s.glsb" "$t/$s.scene" 2>"$t/err" || { fail exact_shade_compile "$(cat "$t/err")"; exit 0; }
done
render Coarse && compare Coarse exact_texture_magnified_vs_65536 0.005 2e-4
render Fine && compare Fine exact_texture_fine_vs_65536 0.006 5e-4
# lit (lighting.c's shader on the CPU, in double): the same quadrilateral
# with vertex normals spread about the view axis, a point light near it
# (a highlight that saturates) and a directional one, specular; and lit
# and textured with flat normals (turned to face the camera)
cat >"$t/Lit.scene" <<'SCENE'
ambient(0.1, 0.1, 0.15);
light(point, 0.3, -0.4, 3, 1, 0.9, 0.8, 0.05);
light(directional, 0.2, -0.3, -1, 0.3, 0.3, 0.3);
color(0.8, 0.6, 0.4);
specular(0.6, 0.6, 0.6, 30);
poly { normal(-0.6, 0.2, -1); vert(-1.25, -0.5, 3.75); normal(0.5, 0.3, -1); vert(0.75, -0.75, 5.75);
       normal(0.4, -0.5, -1); vert(1.0, 1.25, 6); normal(-0.5, -0.4, -1); vert(-1.0, 1.5, 4); }
SCENE
{ printf 'ambient(0.2, 0.2, 0.2);\nlight(point, 0.3, -0.4, 3, 1, 1, 1, 0.02);\n'; quad modulate 3; } >"$t/LitTex.scene"
for s in Lit LitTex; do
    "$B/glsc" -I "$t/lib" -o "$t/$s.glsb" "$t/$s.scene" 2>"$t/err" || { fail exact_shade_compile "$(cat "$t/err")"; exit 0; }
done
render Lit && compare Lit exact_lit_vs_65536 0.003 1e-4
# a non-uniformly scaled lit instance far from the camera for its size
# (not re-anchored, render.c): GL carries its normals by the normal matrix
# kept at their lengths, as for re-anchored items and as the exact path
# does (lighting.c); before, their lengths weighed GL's interpolation and
# the exact path was 0.16 off here
mkdir -p "$t/llib/lt"
grep -v '^ambient\|^light' "$t/Lit.scene" >"$t/llib/lt/Q.scene"
printf 'ambient(0.1, 0.1, 0.15);\nlight(point, 0.03, -0.04, 49.7, 1, 0.9, 0.8, 5);\nlight(directional, 0.2, -0.3, -1, 0.3, 0.3, 0.3);\npush; trans(0, 0, 50); scale(1, 0.5, 1); scale(0.1, 0.1, 0.1); trans(0, 0, -5); call("lt.Q"); pop;\n' >"$t/LitFar.scene"
"$B/glsc" -I "$t/llib" -o "$t/LitFar.glsb" "$t/LitFar.scene" 2>"$t/err" || { fail exact_shade_compile "$(cat "$t/err")"; exit 0; }
cp "$t/c.cam" "$t/c0.cam" && sed 's/^fx 100$/fx 12000/; s/^fy 100$/fy 12000/' "$t/c0.cam" >"$t/c.cam"
render LitFar && compare LitFar exact_lit_scaled_far_vs_65536 0.003 1e-4
cp "$t/c0.cam" "$t/c.cam"
render LitTex && compare LitTex exact_lit_textured_vs_65536 0.006 3e-4
# refused: shadows (a shadow map is a sampled depth image)
printf 'shadows(256);\n' | cat - "$t/Lit.scene" >"$t/Shadow.scene"
if "$B/glsc" -o "$t/shadow.glsb" "$t/Shadow.scene" 2>"$t/err"; then
    "$PLAY" "$t/shadow.glsb" --camera "$t/c.cam" --aa exact -o "$t/sh" 2>"$t/err"
    rc=$?
    [ $rc -eq 1 ] && grep -q "^glsplay: error: .*shadow.glsb: --aa exact does not draw shadows" "$t/err" &&
        [ ! -e "$t/sh" ] && ok exact_refuses_shadows || fail exact_refuses_shadows "exit $rc: $(cat "$t/err")"
else
    fail exact_refuses_shadows "$(cat "$t/err")"
fi
# a texture with transparent texels (the alpha test, GL discarding where
# alpha < 0.5) in front of a flat quadrilateral: the pixels it shows in
# are point-sampled at the 64 lattice points, each the nearest surface
# whose alpha passes; coverage and edge_segments, which promise exact
# areas, are refused there
mkdir -p "$t/alib/tx"
$PY -c "
import cv2, numpy as np
r = np.random.default_rng(7)
a = (r.random((8, 8, 4)) * 255).astype(np.uint8); a[:, :, 3] = np.where(r.random((8, 8)) < 0.4, 0, 255)
cv2.imwrite('$t/alib/tx/Holes.png', a)"
{ printf 'color(0.2, 0.4, 0.9);\npoly { vert(-3, -3, 7); vert(3, -3, 7); vert(3, 3, 7); vert(-3, 3, 7); }\n'
  quad replace 2 | sed 's/tx.Check/tx.Holes/'; } >"$t/Holes.scene"
if "$B/glsc" -I "$t/alib" -o "$t/Holes.glsb" "$t/Holes.scene" 2>"$t/err"; then
    render Holes && compare Holes exact_alpha_test_vs_65536 0.02 1.5e-3
    "$PLAY" "$t/Holes.glsb" --camera "$t/c.cam" --aa exact --outputs image,coverage -o "$t/h" 2>"$t/err"
    rc=$?
    [ $rc -eq 1 ] && grep -q "^glsplay: error: .*Holes.glsb: --outputs coverage needs exact areas, and the scene has textures with transparent texels" \
        "$t/err" && [ ! -e "$t/h" ] && ok exact_alpha_test_refuses_coverage || fail exact_alpha_test_refuses_coverage "exit $rc: $(cat "$t/err")"
else
    fail exact_alpha_test_vs_65536 "$(cat "$t/err")"
fi
