#!/bin/sh
# glsplay's default anti-aliasing, --aa auto (spec/antialiasing.md "The
# default: --aa auto"): exact coverage where the run allows it, one sample
# a pixel where it cannot (a camera's sensor effects, a scene's shadows,
# the Gaussian filter), for every camera of the run; --explain says which
# and why; coverage follows the choice.  Each image is compared byte for
# byte with the run that asks for the same thing by name (--aa exact or
# --aa 1).  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
PLAY=$B/glsplay
[ -x "$PLAY" ] || { fail player_aa_default "no $PLAY"; exit 0; }
cat >"$t/Sq.scene" <<'SCENE'
color(1, 1, 1);
poly { vert(-1.25, -0.5, 5); vert(0.75, -0.75, 5); vert(1.0, 1.25, 5); vert(-1.0, 1.5, 5); }
SCENE
printf 'shadows(256);\nlight(directional, 0, 0, -1, 1, 1, 1);\n' | cat - "$t/Sq.scene" >"$t/Shadow.scene"
cam='width 64
height 48
fx 100
fy 100
cx 31.3
cy 23.6
R 1 0 0 0 1 0 0 0 1
T 0 0 0
near 0.1
far 100'
echo "$cam" >"$t/c.cam"
printf '%s\ngain 1.5\n' "$cam" >"$t/s.cam"
"$B/glsc" -o "$t/sq.glsb" "$t/Sq.scene" 2>"$t/err" && "$B/glsc" -o "$t/sh.glsb" "$t/Shadow.scene" 2>>"$t/err" ||
    { fail default_compile "$(cat "$t/err")"; exit 0; }

# render NAME ARGS...: the image as PFM into $t/NAME; the explain into $t/NAME.plan
render() {
    name=$1
    shift
    "$PLAY" "$@" --outputs image --image-format pfm -o "$t/$name" 2>"$t/err" &&
        "$PLAY" "$@" --outputs image --explain >"$t/$name.plan" 2>>"$t/err" || fail "default_render_$name" "$(cat "$t/err")"
}
# same NAME A B [CAM]: the two renders' images are the same bytes
same() {
    cmp -s "$t/$2/${4:-c}/image_000000.pfm" "$t/$3/${4:-c}/image_000000.pfm" && ok "$1" || fail "$1" "$2 and $3 differ"
}
# said NAME RENDER LINE: the explain of RENDER has LINE
said() { grep -qxF "$3" "$t/$2.plan" && ok "$1" || fail "$1" "$(grep '^anti-aliasing' "$t/$2.plan")"; }

render def "$t/sq.glsb" --camera "$t/c.cam"
render auto "$t/sq.glsb" --camera "$t/c.cam" --aa auto
render exact "$t/sq.glsb" --camera "$t/c.cam" --aa exact
render one "$t/sq.glsb" --camera "$t/c.cam" --aa 1
same default_is_exact def exact
same default_is_aa_auto def auto
cmp -s "$t/def/c/image_000000.pfm" "$t/one/c/image_000000.pfm" && fail default_not_one_sample "the same bytes" ||
    ok default_not_one_sample
said default_explain_exact def "anti-aliasing: exact coverage (--aa auto, the default): each pixel the exact visible areas times their colours, in double on the CPU, no samples"
said default_explain_named_exact exact "anti-aliasing: exact coverage (--aa exact): each pixel the exact visible areas times their colours, in double on the CPU, no samples"
grep -q '^  frame plan: passes exact$' "$t/def.plan" && ok default_plan_exact_pass || fail default_plan_exact_pass "$(grep 'frame plan' "$t/def.plan")"

# what exact coverage cannot draw: one sample a pixel, the reason said
render sensor "$t/sq.glsb" --camera "$t/s.cam"
render sensor1 "$t/sq.glsb" --camera "$t/s.cam" --aa 1
same default_sensor_one_sample sensor sensor1 s
said default_sensor_explain sensor "anti-aliasing: one sample a pixel, as --aa 1 (--aa auto, the default, chose samples: exact coverage does not draw camera s's sensor effects)"
render shadow "$t/sh.glsb" --camera "$t/c.cam"
render shadow1 "$t/sh.glsb" --camera "$t/c.cam" --aa 1
same default_shadows_one_sample shadow shadow1
said default_shadows_explain shadow "anti-aliasing: one sample a pixel, as --aa 1 (--aa auto, the default, chose samples: exact coverage does not draw shadows (their maps are sampled depth images))"
render gauss "$t/sq.glsb" --camera "$t/c.cam" --filter gauss
render gauss1 "$t/sq.glsb" --camera "$t/c.cam" --filter gauss --aa 1
same default_gauss_one_sample gauss gauss1
said default_gauss_explain gauss "anti-aliasing: one sample a pixel, as --aa 1 (--aa auto, the default, chose samples: exact coverage does not draw the Gaussian filter (--filter gauss))"

# one choice for the run: a pair with one sensor camera is drawn with
# samples in both (a rig's images are made the same way)
render pair "$t/sq.glsb" --camera "$t/c.cam" --camera "$t/s.cam"
same default_pair_one_sample pair one

# coverage under the default: written when it chooses exact coverage (the
# same file as --aa exact's), refused with the reason when it cannot
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --outputs coverage -o "$t/cov" 2>"$t/err" &&
    "$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --outputs coverage -o "$t/cove" 2>>"$t/err" &&
    [ -s "$t/cov/c/coverage_000000.csv" ] && cmp -s "$t/cov/c/coverage_000000.csv" "$t/cove/c/coverage_000000.csv" &&
    ok default_coverage || fail default_coverage "$(cat "$t/err")"
"$PLAY" "$t/sq.glsb" --camera "$t/s.cam" --outputs coverage -o "$t/covs" 2>"$t/err"
rc=$?
[ $rc -eq 1 ] && [ ! -e "$t/covs" ] &&
    grep -qxF "glsplay: error: --outputs coverage needs exact coverage, which does not draw camera s's sensor effects; leave out coverage" "$t/err" &&
    ok default_coverage_refused || fail default_coverage_refused "exit $rc: $(cat "$t/err")"
# --aa exact still refuses what it cannot draw
"$PLAY" "$t/sh.glsb" --camera "$t/c.cam" --aa exact -o "$t/she" 2>"$t/err"
rc=$?
[ $rc -eq 1 ] && [ ! -e "$t/she" ] && grep -q "^glsplay: error: .*--aa exact does not draw shadows" "$t/err" &&
    ok default_named_exact_refuses || fail default_named_exact_refuses "exit $rc: $(cat "$t/err")"
# the depth is the pixel centre's whichever is chosen
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --outputs depth -o "$t/zd" 2>"$t/err" &&
    "$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --outputs depth --aa 1 -o "$t/z1" 2>>"$t/err" &&
    cmp -s "$t/zd/c/depth_000000.pfm" "$t/z1/c/depth_000000.pfm" && ok default_depth_centre ||
    fail default_depth_centre "$(cat "$t/err")"
