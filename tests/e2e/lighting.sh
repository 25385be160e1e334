#!/bin/sh
# Lighting and shadows (issue 16): light/ambient/normal/specular/shadows
# compiled, dumped, linked through a library bundle, explained, refused
# beyond 8 lights; point lights' shadows explained and drawn; the images
# against closed forms by tests/py/check_lighting.py, check_shadows.py and
# check_point_shadows.py
# (spec/camera.md "Lighting", "Shadows").  Compile errors: tests/errors/light_*, normal_*, specular_*;
# the validator's: test_bundle's test_lights_and_normals.  Prints
# "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh

mkdir -p "$t/src/lt" "$t/top"
printf 'light(point, 0, 2, 0, 1, 0.5, 0.25, 0.5);\nspecular(0.5, 0.5, 0.5, 20);\npoly { normal(0, 0, 2); vert(0, 0, 0); vert(1, 0, 0); vert(1, 1, 0); }\n' >"$t/src/lt/Lamp.scene"
printf 'ambient(0.1, 0.1, 0.2);\nlight(directional, 0, 1, 1, 1, 1, 1);\npush; trans(1, 0, 0); call("lt.Lamp"); pop;\npoly { vert(-1, 0, 0); vert(0, -1, 0); vert(0, 0, -1); }\n' >"$t/src/Top.scene"
cp "$t/src/Top.scene" "$t/top/"
"$BIN/glsc" -I "$t/src" -o "$t/top.glsb" "$t/src/Top.scene" 2>"$t/err" || { fail lighting_compile "$(cat "$t/err")"; exit 0; }

# the dump: the feature, each light, the normals on the vertex lines
"$BIN/glsdis" "$t/top.glsb" >"$t/dis" 2>&1
if grep -qx 'features: lights' "$t/dis" && grep -qx '  light ambient 0 0 0 0.1 0.1 0.2 0' "$t/dis" &&
    grep -qx '  light directional 0 1 1 1 1 1 0' "$t/dis" && grep -qx '  light point 0 2 0 1 0.5 0.25 0.5' "$t/dis" &&
    grep -qx '  specular 0.5 0.5 0.5 20' "$t/dis" && grep -qx '    vert 1 1 0  normal 0 0 1' "$t/dis"; then
    ok lighting_glsdis
else
    fail lighting_glsdis "$(cat "$t/dis")"
fi

# linked through a library bundle (normals imported): the same bytes
linked_same lighting_library_link "$t/src" "$t/top/Top.scene"

# --explain: the feature, each light where the transforms put it, the cost
printf 'width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 -1 0 0 0 -1\nT 0 0 5\nnear 0.1\nfar 100\n' >"$t/c.cam"
"$BIN/glsplay" "$t/top.glsb" --camera "$t/c.cam" --explain >"$t/explain" 2>&1
pad='                    '
if grep -qx '  lights         on  some object declares a light (light, ambient): shaded per pixel' "$t/explain" &&
    grep -qxF "${pad} light 1: ambient, colour (0.1, 0.1, 0.2) (light instruction of Top)" "$t/explain" &&
    grep -qxF "${pad} light 2: directional, towards (0, 1, 1) in the world, colour (1, 1, 1) (light instruction of Top)" "$t/explain" &&
    grep -qxF "${pad} light 3: point at (1, 2, 0) in the world, colour (1, 0.5, 0.25), attenuation 1/(1 + 0.5 d^2) (light instruction of lt.Lamp)" "$t/explain" &&
    grep -qxF "${pad} cost: per-pixel shading of every covered fragment of each colour pass, 2 directional/point lights (at most 8); +28 bytes per vertex; no extra pass" "$t/explain"; then
    ok lighting_explain
else
    fail lighting_explain "$(cat "$t/explain")"
fi
# an unlit bundle's plan says so
printf 'poly { vert(0, 0, 0); vert(1, 0, 0); vert(1, 1, 0); }\n' >"$t/plain.scene"
"$BIN/glsc" -o "$t/plain.glsb" "$t/plain.scene" 2>"$t/err"
"$BIN/glsplay" "$t/plain.glsb" --camera "$t/c.cam" --explain >"$t/explain2" 2>&1
if grep -qx '  lights         off not used by this bundle' "$t/explain2" && ! grep -q 'light 1' "$t/explain2"; then
    ok lighting_explain_off
else
    fail lighting_explain_off "$(cat "$t/explain2")"
fi

# more than 8 directional and point lights (every call path counts)
mkdir -p "$t/many"
printf 'light(point, 0, 1, 0, 1, 1, 1);\n' >"$t/many/Bulb.scene"
printf 'repeat(i, 0, 9) { push; trans(i, 0, 0); call("Bulb"); pop; }\npoly { vert(0, 0, 0); vert(1, 0, 0); vert(1, 1, 0); }\n' >"$t/many/Top.scene"
"$BIN/glsc" -I "$t/many" -o "$t/many.glsb" "$t/many/Top.scene" 2>"$t/err"
"$BIN/glsplay" "$t/many.glsb" --camera "$t/c.cam" -o "$t/many_out" >"$t/out" 2>"$t/err"
rc=$?
want="glsplay: error: the scene has 9 directional and point lights (counting every call path); the player shades with at most 8"
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "$want" ] && ! ls "$t/many_out/c/image_000000.png" >/dev/null 2>&1; then
    ok lighting_too_many_lights
else
    fail lighting_too_many_lights "exit $rc, stderr: $(cat "$t/err")"
fi
# the same with shadows: their maps are made for the 8 shaded lights only
# (9 would overrun the maps' arrays), then the lights are refused alike
printf 'shadows(256);\n' >>"$t/many/Top.scene"
"$BIN/glsc" -I "$t/many" -o "$t/many_sh.glsb" "$t/many/Top.scene" 2>"$t/err"
"$BIN/glsplay" "$t/many_sh.glsb" --camera "$t/c.cam" -o "$t/many_sh_out" >"$t/out" 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$t/err")" = "$want" ] && ! ls "$t/many_sh_out/c/image_000000.png" >/dev/null 2>&1; then
    ok shadows_too_many_lights
else
    fail shadows_too_many_lights "exit $rc, stderr: $(cat "$t/err")"
fi

# shadows: explained
mkdir -p "$t/sh"
printf 'shadows(1024);\nlight(directional, 1, 2, 0.5, 1, 1, 1);\npoly { vert(-2, 0, -2); vert(2, 0, -2); vert(2, 0, 2); vert(-2, 0, 2); }\n' >"$t/sh/Top.scene"
"$BIN/glsc" -o "$t/sh.glsb" "$t/sh/Top.scene" 2>"$t/err"
"$BIN/glsplay" "$t/sh.glsb" --camera "$t/c.cam" --explain >"$t/explain3" 2>&1
if grep -qx '  shadows        on  some object asks for shadows (shadows): directional and point lights cast them' "$t/explain3" &&
    grep -qxF "${pad} maps: 1 of 1024x1024 (GL_DEPTH_COMPONENT32F, 4.0 MiB), one per directional light, fitted to the items the camera sees" "$t/explain3" &&
    grep -qxF "${pad} cost: 1 extra depth pass of every item per colour pass; bias t * (1 + 2 tan(theta), tan at most 10), t a map texel; 2x2 bilinear PCF" "$t/explain3"; then
    ok shadows_explain
else
    fail shadows_explain "$(cat "$t/explain3")"
fi
# a point light casts shadows through a cube map: explained, drawn
printf 'light(point, 0, 3, 0, 1, 1, 1);\n' >>"$t/sh/Top.scene"
"$BIN/glsc" -o "$t/shp.glsb" "$t/sh/Top.scene" 2>"$t/err"
"$BIN/glsplay" "$t/shp.glsb" --camera "$t/c.cam" --explain >"$t/explain4" 2>&1
"$BIN/glsplay" "$t/shp.glsb" --camera "$t/c.cam" -o "$t/shp_out" >"$t/out" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && [ ! -s "$t/err" ] && [ -s "$t/shp_out/c/image_000000.png" ] &&
    grep -qxF "${pad} light 2: cube map of 6 x 1024x1024 (24.0 MiB) at (0, 3, 0), near 0.000412: 6 depth passes of every item at 1024x1024" "$t/explain4" &&
    grep -qxF "${pad} cost: 6 extra depth passes (6 per point light) of every item per colour pass; bias t * (1 + 2 tan(theta), tan at most 10) along the face's axis, t = 2 z / 1024 the texel at the point's depth z; 2x2 bilinear PCF across the faces (seamless)" "$t/explain4" &&
    ! grep -q 'refused' "$t/explain4"; then
    ok shadows_point_light
else
    fail shadows_point_light "exit $rc, stderr: $(cat "$t/err"), explain: $(cat "$t/explain4")"
fi

# turned instances: one near the camera (re-anchored at the camera centre,
# render.c, its normals carried into the world with it) and one far off,
# each turned 60 degrees about y under a light along the view: each
# shades to cos 60 = 0.5 of white, instanced as flattened (GL's shading
# at the pixel centres: --aa 1)
mkdir -p "$t/turn"
printf 'poly { vert(-1, -1, 0); vert(1, -1, 0); vert(1, 1, 0); vert(-1, 1, 0); }\n' >"$t/turn/Quad.scene"
printf 'ambient(0, 0, 0);\nlight(directional, 0, 0, -1, 1, 1, 1);\npush; trans(-1.5, 0, 6); rot(60, 0, 1, 0); call("Quad"); pop;\npush; trans(6, 0, 24); rot(60, 0, 1, 0); scale(2); call("Quad"); pop;\n' >"$t/turn/Top.scene"
printf 'width 160\nheight 120\nfx 100\nfy 100\ncx 79.5\ncy 59.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n' >"$t/turn/c.cam"
if "$BIN/glsc" -I "$t/turn" -o "$t/turn.glsb" "$t/turn/Top.scene" 2>"$t/err" &&
    "$BIN/glsplay" "$t/turn.glsb" --camera "$t/turn/c.cam" --aa 1 -o "$t/turn_i" >/dev/null 2>>"$t/err" &&
    "$BIN/glsplay" "$t/turn.glsb" --camera "$t/turn/c.cam" --aa 1 --flatten -o "$t/turn_f" >/dev/null 2>>"$t/err"; then
    got=$("$PY" -c '
import sys, cv2
i = cv2.imread(sys.argv[1]); f = cv2.imread(sys.argv[2])
print(" ".join("%d %d" % (i[60, u, 1], f[60, u, 1]) for u in (55, 104)))' \
        "$t/turn_i/c/image_000000.png" "$t/turn_f/c/image_000000.png" 2>&1)
    if echo "$got" | awk '{ for (k = 1; k <= 4; k++) if ($k < 126 || $k > 129) exit 1; if ($1 - $2 > 1 || $2 - $1 > 1 || $3 - $4 > 1 || $4 - $3 > 1) exit 1 }'; then
        ok lighting_turned_instances
    else
        fail lighting_turned_instances "green near (instanced, flattened), far (instanced, flattened): $got; want 126..129 each"
    fi
else
    fail lighting_turned_instances "$(cat "$t/err")"
fi

# the images against closed forms
mkdir -p "$t/py"
"$PY" tests/py/check_lighting.py "$BIN" "$t/py" 2>"$t/pyerr"
[ -s "$t/pyerr" ] && fail lighting_images "$(tail -5 "$t/pyerr")"
mkdir -p "$t/pysh"
"$PY" tests/py/check_shadows.py "$BIN" "$t/pysh" 2>"$t/pyerr"
[ -s "$t/pyerr" ] && fail shadows_images "$(tail -5 "$t/pyerr")"
mkdir -p "$t/pypt"
"$PY" tests/py/check_point_shadows.py "$BIN" "$t/pypt" 2>"$t/pyerr"
[ -s "$t/pyerr" ] && fail point_shadows_images "$(tail -5 "$t/pyerr")"
exit 0
