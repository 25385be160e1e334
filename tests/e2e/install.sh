#!/bin/sh
# make install / make uninstall (Makefile, docs/install.md): into a
# temporary DESTDIR, exactly the listed files and nothing outside it; the
# installed tools run (--help) and render the road demo with the installed
# library bundle, byte for byte as the build's tools do; the man pages
# pass groff's and man's checks, and each has an entry for every option
# its tool's --help lists; a C program built against the installed
# libglscene with pkg-config (shared and static) renders the demo, and the
# installed Python binding imports and renders.  Prints ok/FAIL lines.
. tests/e2e/lib.sh
tmp=$t
# the sanitizer pass (GLS_SANITIZED=1) would install the same files again
[ "$GLS_SANITIZED" = 1 ] && exit 0
# a PREFIX that exists nowhere: if anything were written outside DESTDIR,
# it would appear there
PREFIX=/opt/glscene-install-test-$$
D=$tmp/dest
git status --porcelain --untracked-files=all >"$tmp/status.before" 2>/dev/null
# the make of this checkout, with its build in $BIN, not the suite's make
if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -s install B="$BIN" PREFIX="$PREFIX" \
    DESTDIR="$D" >"$tmp/log" 2>&1; then
    fail make_install "$(tail -5 "$tmp/log")"
    exit 0
fi
(cd "$D" && find . -type f -o -type l | sort) >"$tmp/files"
cat >"$tmp/want" <<EOF2
.$PREFIX/bin/glsc
.$PREFIX/bin/glsdis
.$PREFIX/bin/glsplay
.$PREFIX/bin/glsroad
.$PREFIX/include/glscene.h
.$PREFIX/lib/libglscene.a
.$PREFIX/lib/libglscene.so
.$PREFIX/lib/libglscene.so.0
.$PREFIX/lib/libglscene.so.0.1.0
.$PREFIX/lib/pkgconfig/glscene.pc
.$PREFIX/lib/python3/dist-packages/glscene/__init__.py
.$PREFIX/lib/python3/dist-packages/glscene/_lib.py
.$PREFIX/lib/python3/dist-packages/glscene/camera.py
.$PREFIX/lib/python3/dist-packages/glscene/player.py
.$PREFIX/share/glscene/scenelib.glsb
.$PREFIX/share/man/man1/glsc.1
.$PREFIX/share/man/man1/glsdis.1
.$PREFIX/share/man/man1/glsplay.1
.$PREFIX/share/man/man1/glsroad.1
EOF2
if cmp -s "$tmp/files" "$tmp/want"; then
    ok install_files
else
    fail install_files "$(diff "$tmp/want" "$tmp/files" | tr '\n' ' ')"
fi
git status --porcelain --untracked-files=all >"$tmp/status.after" 2>/dev/null
if [ ! -e "$PREFIX" ] && cmp -s "$tmp/status.before" "$tmp/status.after"; then
    ok install_nothing_outside_destdir
else
    fail install_nothing_outside_destdir "$PREFIX exists, or the checkout changed: $(diff "$tmp/status.before" "$tmp/status.after" | tr '\n' ' ')"
fi
P=$D$PREFIX
for t in glsc glsdis glsplay glsroad; do
    [ -x "$P/bin/$t" ] && cmp -s "$P/bin/$t" "$BIN/$t" || fail install_tools "$P/bin/$t is not $BIN/$t"
done
if "$P/bin/glsplay" --help >"$tmp/help" 2>&1 && grep -q '^usage: glsplay' "$tmp/help"; then
    ok installed_glsplay_help
else
    fail installed_glsplay_help "$(head -3 "$tmp/help")"
fi

# the road demo with the installed tools and library bundle, run from
# elsewhere (nothing of the checkout but the demo's inputs)
cp -r examples/road "$tmp/in"
(
    cd "$tmp" &&
        "$P/bin/glsroad" in/demo.road -o road >/dev/null &&
        "$P/bin/glsc" -I road -I "$P/share/glscene/scenelib.glsb" -o road.glsb road/road.scene &&
        "$P/bin/glsplay" road.glsb --camera in/rig/left.cam --camera in/rig/right.cam --trajectory road/trajectory.txt \
            --frames 0:2 --motion lead=road/motion/lead.txt -o inst
) >"$tmp/log" 2>&1
rc=$?
"$BIN/glsroad" examples/road/demo.road -o "$tmp/road_b" >/dev/null 2>&1 &&
    "$BIN/glsc" -I "$tmp/road_b" -I "$BIN/scenelib.glsb" -o "$tmp/road_b.glsb" "$tmp/road_b/road.scene" &&
    "$BIN/glsplay" "$tmp/road_b.glsb" --camera examples/road/rig/left.cam --camera examples/road/rig/right.cam \
        --trajectory "$tmp/road_b/trajectory.txt" --frames 0:2 --motion lead="$tmp/road_b/motion/lead.txt" \
        -o "$tmp/ref" 2>>"$tmp/log"
# every output file the same; the frame records differ in their inputs
# digest only: the bundles name their sources by other paths
# (spec/road.md "Resuming a sequence")
if [ $rc -eq 0 ] && [ -f "$tmp/inst/left/image_000001.png" ] && diff -r -x '.frame_*' "$tmp/ref" "$tmp/inst" >>"$tmp/log" 2>&1 &&
    (for r in "$tmp"/ref/*/.frame_*.done; do
        i=$tmp/inst/${r#"$tmp/ref/"}
        [ "$(grep -v '^inputs ' "$r")" = "$(grep -v '^inputs ' "$i")" ] || { echo "records differ: $r" >>"$tmp/log"; exit 1; }
    done); then
    ok installed_tools_render_demo
else
    fail installed_tools_render_demo "exit $rc: $(tail -5 "$tmp/log")"
fi

# libglscene through pkg-config (docs/install.md "Use it from C"): the .pc names
# the install's prefix; --define-variable moves it into DESTDIR.  The
# program renders the demo's left camera and checks the depth at a pixel
# of the road (the plane y = 0.01) against the camera model.
cat >"$tmp/use.c" <<'EOF2'
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <glscene.h>
int main(int argc, char **argv)
{
    glscene_error e;
    glscene_camera c;
    if (argc != 5)
        return 2;
    const char *roots[] = {argv[2], argv[3]};
    if (glscene_compile(argv[1], roots, 2, argv[4], &e) || glscene_camera_from_file("left.cam", &c, &e)) {
        printf("%s\n", e.message);
        return 1;
    }
    glscene_player *p = glscene_open(argv[4], NULL, &e);
    float *z = malloc(sizeof *z * c.width * c.height);
    glscene_buffers b = {0};
    b.depth = z;
    if (!p || !z || glscene_render(p, &c, &b, &e)) {
        printf("%s\n", e.message);
        return 1;
    }
    /* pixel (400, 460): ray d = K^-1 (u, v, 1); world P = R^T (Zc d - T), P_y = 0.01 */
    double d[3] = {(400 - c.cx) / c.fx, (460 - c.cy) / c.fy, 1}, rd = 0, rt = 0;
    for (int i = 0; i < 3; i++)
        rd += c.R[3 * i + 1] * d[i], rt += c.R[3 * i + 1] * c.T[i];
    double want = (0.01 + rt) / rd, got = z[460 * c.width + 400];
    printf("%s depth %.7g want %.7g\n", glscene_version(), got, want);
    glscene_close(p);
    free(z);
    return fabs(got - want) <= 1e-5 * want ? 0 : 1;
}
EOF2
PC="env PKG_CONFIG_PATH=$P/lib/pkgconfig pkg-config --define-variable=prefix=$P"
cp examples/demo/left.cam "$tmp/left.cam"
# shared: -lglscene finds libglscene.so; static: pkg-config --static adds
# Libs.private, and -Bstatic makes -lglscene take libglscene.a
libs_shared=$($PC --libs glscene)
libs_static=$($PC --static --libs glscene | sed 's/-lglscene/-Wl,-Bstatic -lglscene -Wl,-Bdynamic/')
for kind in shared static; do
    eval "libs=\$libs_$kind"
    # shellcheck disable=SC2086
    if ! ${CC:-cc} -o "$tmp/use_$kind" "$tmp/use.c" $($PC --cflags glscene) $libs -lm >"$tmp/log" 2>&1; then
        fail "pkg_config_${kind}_build" "$(tail -5 "$tmp/log")"
        continue
    fi
    (cd "$tmp" && LD_LIBRARY_PATH=$P/lib ./use_$kind "$OLDPWD/examples/demo/Demo.scene" "$OLDPWD/examples/demo" \
        "$OLDPWD/$BIN/textures" demo_$kind.glsb) >"$tmp/log" 2>&1
    if [ $? -eq 0 ]; then
        ok "pkg_config_${kind}_render_demo"
    else
        fail "pkg_config_${kind}_render_demo" "$(tail -3 "$tmp/log")"
    fi
done
# the shared program loads the installed libglscene.so.0, the static one none
LD_LIBRARY_PATH=$P/lib ldd "$tmp/use_shared" 2>/dev/null | grep -q "libglscene.so.0 => $P/lib/libglscene.so.0" &&
    ! LD_LIBRARY_PATH=$P/lib ldd "$tmp/use_static" 2>/dev/null | grep -q libglscene &&
    ok pkg_config_shared_and_static_links ||
    fail pkg_config_shared_and_static_links "$(LD_LIBRARY_PATH=$P/lib ldd "$tmp/use_shared" "$tmp/use_static" | grep -e glscene -e :)"

# the installed Python binding finds the installed library (PREFIX/lib)
# by itself
if (cd "$tmp" && PYTHONDONTWRITEBYTECODE=1 PYTHONPATH=$P/lib/python3/dist-packages /usr/bin/python3 -c '
import glscene, sys
assert glscene._lib._name.startswith(sys.argv[1]), glscene._lib._name
c = glscene.Camera.from_file("left.cam")
z = glscene.Player("demo_shared.glsb").render(c, outputs=("depth",))["depth"]
print(z.shape, z[460, 400])' "$P/lib/") >"$tmp/log" 2>&1; then
    ok installed_python_binding
else
    fail installed_python_binding "$(tail -3 "$tmp/log")"
fi

# the man pages: clean under groff's and man's warnings, and every option
# of each tool's --help with an entry in its page
manbad=0
for t in glsc glsdis glsplay glsroad; do
    page=$P/share/man/man1/$t.1
    w=$(groff -man -ww -z "$page" 2>&1; man --warnings -l "$page" 2>&1 >/dev/null)
    [ -z "$w" ] || { fail man_page_lint "$t.1: $w"; manbad=1; }
    # the tags of the page's option entries (the line after each .TP), as
    # written: \- is -, font escapes dropped; an option must have an entry
    # of its own, not just a mention in another's text
    sed 's/\\-/-/g; s/\\f[BIRP]//g' "$page" | awk 'tag { print; tag = 0 } /^\.TP/ { tag = 1 }' >"$tmp/page"
    missing=""
    for opt in $("$BIN/$t" --help | grep -oE '(^|[^A-Za-z0-9_-])--?[A-Za-z][A-Za-z0-9-]*' | sed -E 's/^[^-]+//' | sort -u); do
        grep -qE -- "(^|[^A-Za-z0-9-])$opt([^A-Za-z0-9-]|\$)" "$tmp/page" || missing="$missing $opt"
    done
    [ -z "$missing" ] || { fail man_page_options "$t.1 has no entry for$missing (in $t --help)"; manbad=1; }
done
[ $manbad -eq 0 ] && ok man_pages_lint_and_options

# make uninstall: every installed file and link gone, the package's own
# directories too
if env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -s uninstall B="$BIN" PREFIX="$PREFIX" \
    DESTDIR="$D" >"$tmp/log" 2>&1 && [ -z "$(find "$D" -type f -o -type l)" ] && [ ! -e "$P/share/glscene" ] &&
    [ ! -e "$P/lib/python3/dist-packages/glscene" ]; then
    ok make_uninstall
else
    fail make_uninstall "$(cat "$tmp/log"; find "$D" -type f -o -type l; ls -d "$P/lib/python3/dist-packages/glscene" 2>&1)"
fi
