#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# The build works with either GL library absent (spec/backends.md): glsplay
# is built in a temporary build directory with GLS_NO_EGL=1, then in the
# same directory with GLS_NO_OSMESA=1 (the Makefile acts as if pkg-config
# had not found that library), then with both.  Each one-backend build
# links only its library, renders the demo byte for byte as the normal
# build does through that backend, reports it in --explain, and refuses
# the missing one with one line and exit status 2 before reading any input;
# with neither, the build stops and says what to install.  Switching in
# one directory also checks that a changed choice rebuilds what it must.
# Prints "ok NAME" / "FAIL NAME: why"; needs $GLS_BIN (default build)
# built with both backends, for the reference images.
. tests/e2e/lib.sh
need build_backends glsc glsplay textures.stamp
"$B/glsc" -I examples/demo -I "$B/textures" -o "$t/demo.glsb" examples/demo/Demo.scene || exit 0
DEMO="$t/demo.glsb --camera examples/demo/left.cam --aa 2 --size 160x120"
# the make the test runs is not a sub-make of the one running the tests
unset MAKEFLAGS MFLAGS MAKELEVEL

# one NAME VAR HAS LIB MISSING MISSING_LINE: build with VAR=1, check it
one() {
    name=$1 var=$2 has=$3 lib=$4 missing=$5 line=$6
    if ! make --no-print-directory -s B="$t/b" "$var=1" "$t/b/glsplay" >"$t/log" 2>&1; then
        fail "build_backends_${name}_builds" "$(tail -5 "$t/log")"
        return
    fi
    ok "build_backends_${name}_builds"
    # links no GL library and not the other backend's; libEGL is linked,
    # libOSMesa opened when the first OSMesa context is made: what a run
    # that makes a context (--explain does) loads has its library and not
    # the other one
    other=$([ "$lib" = libEGL ] && echo libOSMesa || echo libEGL)
    needed=$(readelf -d "$t/b/glsplay" | grep NEEDED)
    # shellcheck disable=SC2086
    loaded=$(LIBGL_ALWAYS_SOFTWARE=1 LD_DEBUG=files "$t/b/glsplay" $DEMO --backend "$has" --explain 2>&1 >/dev/null |
        grep -o 'file=[^ ]*' | sort -u | tr '\n' ' ')
    if echo "$loaded" | grep -q "=$lib" && ! echo "$loaded" | grep -q "=$other" &&
        ! echo "$needed" | grep -q -e 'libGL\.' -e libOpenGL -e libOSMesa -e "$other"; then
        ok "build_backends_${name}_loads_only_$lib"
    else
        fail "build_backends_${name}_loads_only_$lib" "needed: $(echo "$needed" | tr -s ' \n' ' '); loaded: $loaded"
    fi
    # renders, with the backend it has (on llvmpipe), the same bytes as the
    # normal build
    # shellcheck disable=SC2086
    if LIBGL_ALWAYS_SOFTWARE=1 "$t/b/glsplay" $DEMO --backend "$has" -o "$t/$name" 2>"$t/err" &&
        LIBGL_ALWAYS_SOFTWARE=1 "$B/glsplay" $DEMO --backend "$has" -o "$t/ref_$name" 2>>"$t/err"; then
        cmp -s "$t/$name/left/image_000000.png" "$t/ref_$name/left/image_000000.png" &&
            cmp -s "$t/$name/left/depth_000000.pfm" "$t/ref_$name/left/depth_000000.pfm" &&
            ok "build_backends_${name}_renders" || fail "build_backends_${name}_renders" "differs from $B/glsplay --backend $has"
    else
        fail "build_backends_${name}_renders" "$(cat "$t/err")"
    fi
    # shellcheck disable=SC2086
    "$t/b/glsplay" $DEMO --explain >"$t/plan" 2>"$t/err"
    grep -q "^backend: ${has%%-*} (--backend auto" "$t/plan" && ok "build_backends_${name}_explain" ||
        fail "build_backends_${name}_explain" "$(grep '^backend' "$t/plan") $(cat "$t/err")"
    # the missing backend, by name: before any input is read (no such bundle)
    "$t/b/glsplay" "$t/nonexistent.glsb" --camera examples/demo/left.cam -o "$t/no" --backend "$missing" \
        >/dev/null 2>"$t/err"
    rc=$?
    if [ $rc -eq 2 ] && [ "$(cat "$t/err")" = "$line" ] && [ ! -e "$t/no" ]; then ok "build_backends_${name}_refuses_$missing"
    else fail "build_backends_${name}_refuses_$missing" "exit $rc: $(cat "$t/err")"; fi
}
one no_egl GLS_NO_EGL osmesa libOSMesa egl \
    "glsplay: error: --backend egl: this glsplay was built without EGL: libEGL was not found when it was built (Debian: install libegl-dev and rebuild)"
one no_osmesa GLS_NO_OSMESA egl-surfaceless libEGL osmesa \
    "glsplay: error: --backend osmesa: this glsplay was built without OSMesa: libOSMesa was not found when it was built (Debian 12: install libosmesa6-dev and rebuild; Mesa 25.1 and later have no OSMesa: use --backend egl)"
# the EGL-only build has both EGL platforms
"$t/b/glsplay" "$t/demo.glsb" --explain --backend egl-device >"$t/plan" 2>&1 &&
    grep -q '^backend: egl (--backend egl-device), platform: device' "$t/plan" && ok build_backends_no_osmesa_egl_device ||
    fail build_backends_no_osmesa_egl_device "$(grep -E '^backend|error' "$t/plan")"

# libOSMesa (which brings LLVM: about 90 ms at each start of a process) is
# opened only when an OSMesa context is made: not by a run that makes
# none (--version, an input error, --aa exact alone), nor by EGL's
files() { LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -o 'file=[^ ]*' | sort -u | tr '\n' ' '; }
v=$(files "$B/glsplay" --version)
e=$(files "$B/glsplay" "$t/demo.glsb" --camera examples/demo/left.cam --size 160x120 --aa exact --outputs image \
    -o "$t/lazy_exact")
g=$(LIBGL_ALWAYS_SOFTWARE=1 files "$B/glsplay" $DEMO --backend egl -o "$t/lazy_egl")
o=$(files "$B/glsplay" $DEMO --backend osmesa -o "$t/lazy_osmesa")
if ! echo "$v$e$g" | grep -q libOSMesa && echo "$o" | grep -q '=libOSMesa' && [ -f "$t/lazy_exact/left/image_000000.png" ]; then
    ok build_backends_osmesa_opened_when_used
else
    fail build_backends_osmesa_opened_when_used "--version: $v; exact: $e; egl: $g; osmesa: $o"
fi

# neither: the build stops with what to install
if make --no-print-directory -s B="$t/b" GLS_NO_EGL=1 GLS_NO_OSMESA=1 "$t/b/glsplay" >"$t/log" 2>&1; then
    fail build_backends_none_refused "the build succeeded with no backend"
elif grep -q '^glscene: no GL backend to build: pkg-config finds neither egl (Debian: libegl-dev) nor osmesa (libosmesa6-dev); GLS_NO_EGL=1 / GLS_NO_OSMESA=1 left out what it finds$' "$t/log"; then
    ok build_backends_none_refused
else
    fail build_backends_none_refused "$(head -3 "$t/log")"
fi

# back to both: the directory recompiles glctx.c alone (both backends'
# objects are there from the two builds above) and relinks
make --no-print-directory B="$t/b" "$t/b/glsplay" >"$t/log" 2>&1
compiled=$(grep -o ' -c [^ ]*\.c' "$t/log" | sed 's/ -c //' | tr '\n' ' ')
if [ "$compiled" = "runtime/gl/glctx.c " ]; then
    ok build_backends_switch_rebuilds_glctx
else
    fail build_backends_switch_rebuilds_glctx "compiled: ${compiled:-nothing} $(grep -i error "$t/log" | head -2)"
fi
"$t/b/glsplay" "$t/demo.glsb" --explain --backend osmesa >/dev/null 2>&1 &&
    "$t/b/glsplay" "$t/demo.glsb" --explain --backend egl >/dev/null 2>&1 &&
    ok build_backends_both_again || fail build_backends_both_again "a backend is missing after the switch back"
