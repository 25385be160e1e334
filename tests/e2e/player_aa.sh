#!/bin/sh
# End-to-end tests of glsplay's anti-aliasing flags: formats read back
# with OpenCV, determinism of stratified jitter, --explain plan, --aa 1 is
# the plain image, depth unchanged by anti-aliasing, usage errors.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
PLAY=$B/glsplay
run() { name=$1; shift; if "$@" >"$t/stdout" 2>"$t/stderr"; then ok "$name"; else fail "$name" "exit $?: $(cat "$t/stderr")"; fi; }
usage() { name=$1; shift; "$@" >/dev/null 2>"$t/stderr"; rc=$?
    [ $rc -eq 2 ] && [ "$(wc -l <"$t/stderr")" -eq 1 ] && ok "$name" || fail "$name" "exit $rc: $(cat "$t/stderr")"; }

[ -x "$PLAY" ] || { fail player_aa "no $PLAY"; exit 0; }
$B/tests/test_player --write "$t" >/dev/null || { fail player_aa "cannot write test scenes"; exit 0; }
S="$t/proj.glsb --camera $t/proj.cam"

# the plain one-sample render (--aa 1; the default is exact coverage,
# player_aa_default.sh), and one lattice sample, which must be it
run aa_plain $PLAY $S -o "$t/plain" --aa 1
run aa_one $PLAY $S -o "$t/one" --samples 1
cmp -s "$t/plain/proj/image_000000.png" "$t/one/proj/image_000000.png" && ok aa_one_is_plain || fail aa_one_is_plain "images differ"
run aa_16 $PLAY $S -o "$t/a16" --aa 4 --filter gauss:0.6 --pattern stratified --seed 5 --image-format png16 --outputs image,depth,edges
run aa_16_again $PLAY $S -o "$t/b16" --aa 4 --filter gauss:0.6 --pattern stratified --seed 5 --image-format png16 --outputs image,depth,edges
cmp -s "$t/a16/proj/image_000000.png" "$t/b16/proj/image_000000.png" && ok aa_deterministic || fail aa_deterministic "stratified runs differ"
run aa_seed6 $PLAY $S -o "$t/c16" --aa 4 --filter gauss:0.6 --pattern stratified --seed 6 --image-format png16 --outputs image
cmp -s "$t/a16/proj/image_000000.png" "$t/c16/proj/image_000000.png" && fail aa_seed_matters "seeds 5 and 6 give the same image" || ok aa_seed_matters
cmp -s "$t/plain/proj/depth_000000.pfm" "$t/a16/proj/depth_000000.pfm" && ok aa_depth_unjittered || fail aa_depth_unjittered "depth changed"
run aa_pfm $PLAY $S -o "$t/pf" --subpixel 1/8 --image-format pfm --outputs image
# the same samples as a16, written as float: png16 must agree with it
run aa_16_pfm $PLAY $S -o "$t/a16pf" --aa 4 --filter gauss:0.6 --pattern stratified --seed 5 --image-format pfm --outputs image
[ -s "$t/pf/proj/image_000000.pfm" ] && head -c 3 "$t/pf/proj/image_000000.pfm" | grep -q '^PF' && ok aa_pfm_header || fail aa_pfm_header "no PF file"
run aa_lattice_edges $PLAY $S -o "$t/lat" --aa 4 --image-format pfm --outputs image,edges
if [ -x $PY ] && $PY -c 'import cv2' 2>/dev/null; then
    $PY - "$t" <<'PYEOF'
import sys, cv2, numpy as np
t = sys.argv[1]
plain = cv2.imread(t + '/plain/proj/image_000000.png', cv2.IMREAD_UNCHANGED).astype(float) / 255
a16 = cv2.imread(t + '/a16/proj/image_000000.png', cv2.IMREAD_UNCHANGED)
pf = cv2.imread(t + '/pf/proj/image_000000.pfm', cv2.IMREAD_UNCHANGED)
mask = cv2.imread(t + '/a16/proj/edges_000000.png', cv2.IMREAD_UNCHANGED)
def res(name, cond, why=''):
    print(('ok ' if cond else 'FAIL ') + name + ('' if cond else ': ' + why))
res('aa_png16_depth', a16.dtype == np.uint16 and a16.shape == plain.shape, str(a16.dtype))
# anti-aliased values between 0 and 1 that 8 bits cannot hold
res('aa_png16_fine', np.any(a16 % 257 != 0), 'all values multiples of 257')
# png16 and pfm of the same samples agree on every pixel, mid-greys
# included (a byte swap is invisible on multiples of 257 only)
a16pf = cv2.imread(t + '/a16pf/proj/image_000000.pfm', cv2.IMREAD_UNCHANGED)
d16 = np.abs(a16.astype(float) / 65535 - a16pf) if a16pf is not None and a16pf.shape == a16.shape else None
res('aa_png16_matches_pfm', d16 is not None and d16.max() <= 1 / 65535 and np.any(a16 % 257 != 0),
    'max difference %s' % (None if d16 is None else d16.max() * 65535))
res('aa_pfm_float', pf.dtype == np.float32 and pf.shape == plain.shape and np.isfinite(pf).all(), str(pf.dtype))
# same picture: far from edges the anti-aliased image equals the plain one
flat = mask == 0
res('aa_pfm_matches_plain', np.abs(pf - plain)[flat].max() < 1e-6 if flat.any() else False, 'differs away from edges')
res('aa_edges_map', 0 < (mask > 0).sum() < mask.size // 4, '%d mixed' % (mask > 0).sum())
# the mask marks exactly the pixels whose anti-aliased value is not a plain colour
inner = (a16.astype(float) / 65535)
res('aa_edges_where_blended', np.abs(inner - plain)[~flat].max() > 0.01, 'mask marks nothing blended')
# the same through the lattice's one pass (the default)
lat = cv2.imread(t + '/lat/proj/image_000000.pfm', cv2.IMREAD_UNCHANGED)
lmask = cv2.imread(t + '/lat/proj/edges_000000.png', cv2.IMREAD_UNCHANGED)
lflat = lmask == 0
res('aa_lattice_matches_plain', lat is not None and np.abs(lat - plain)[lflat].max() < 1e-6 and 0 < (~lflat).sum() < lmask.size // 4,
    'differs away from edges')
res('aa_lattice_edges_where_blended', np.abs(lat - plain)[~lflat].max() > 0.01, 'mask marks nothing blended')
PYEOF
else
    fail player_aa_opencv "no OpenCV under $PY"
fi
run aa_explain $PLAY $S --explain --aa 8 --filter gauss --outputs image
grep -q "anti-aliasing: 8x8 = 64 samples per pixel, Gaussian" "$t/stdout" && grep -q "accumulator: uint64" "$t/stdout" &&
    ok aa_explain_plan || fail aa_explain_plan "$(cat "$t/stdout")"
# the lattice is the default; any M; the plan names the generator (256
# samples: a = 30, gcd(a, 256) = 2, spec/antialiasing.md), the points a
# position across axis and diagonal edges, the passes, the tiles and the
# memory
run aa_explain_lattice $PLAY $S --explain --samples 256 --outputs image
grep -qF "anti-aliasing: 16x16 = 256 samples per pixel, box filter, lattice pattern: generator a = 30, closest samples 0.0650 px apart; samples a position across 0, 45 and 135 degree edges: 2, 1 and 1 (gcd(a, M), gcd(a - 1, M), gcd(a + 1, M); positions g/256 px apart)" "$t/stdout" &&
    grep -q "passes: one fine framebuffer whose pixel centres are the samples" "$t/stdout" &&
    grep -q "^  anti-aliasing: 1 pass of 256 samples per pixel; fine framebuffer [0-9]*x[0-9]* (A = \[" "$t/stdout" &&
    grep -q "^  tiles: [0-9]* per pass of [0-9]*x[0-9]* (at most; those no pixel needs are skipped), [0-9.]* MiB of framebuffer and read-backs (--aa-memory 256 MiB)" "$t/stdout" &&
    ok aa_explain_lattice_plan || fail aa_explain_lattice_plan "$(cat "$t/stdout")"
run aa_explain_kpass $PLAY $S --explain --samples 262144 --outputs image
grep -q "^  anti-aliasing: 4 passes of 65536 samples per pixel" "$t/stdout" &&
    ok aa_explain_kpass_plan || fail aa_explain_kpass_plan "$(grep -A1 '^  anti-aliasing' "$t/stdout")"
run aa_explain_default $PLAY $S --explain --aa 4 --outputs image
grep -q "lattice pattern: generator a = 4," "$t/stdout" && ok aa_default_is_lattice || fail aa_default_is_lattice "$(grep anti-al "$t/stdout")"
run aa_samples_prime $PLAY $S -o "$t/p17" --samples 17 --outputs image
[ -s "$t/p17/proj/image_000000.png" ] && ok aa_samples_prime_image || fail aa_samples_prime_image "no image"
run aa_explain_one $PLAY $S --explain --aa 1
grep -q "no accumulator" "$t/stdout" && ok aa_explain_one_pass || fail aa_explain_one_pass "$(grep passes "$t/stdout")"
usage aa_usage_zero $PLAY $S -o "$t/x" --aa 0
usage aa_usage_big $PLAY $S -o "$t/x" --aa 4097
usage aa_usage_both $PLAY $S -o "$t/x" --aa 4 --subpixel 1/4
usage aa_usage_filter $PLAY $S -o "$t/x" --filter tent
usage aa_usage_format $PLAY $S -o "$t/x" --image-format jpg
usage aa_usage_subpixel $PLAY $S -o "$t/x" --subpixel 1/5000
# exact () {NAME LINE -- command}: exit 2 and stderr exactly LINE
exact2() { name=$1 line=$2; shift 3; "$@" >/dev/null 2>"$t/stderr"; rc=$?
    [ $rc -eq 2 ] && [ "$(cat "$t/stderr")" = "$line" ] && ok "$name" || fail "$name" "exit $rc: $(cat "$t/stderr")"; }
exact2 aa_usage_samples_zero "glsplay: error: --samples needs M in 1..16777216, got '0' (try glsplay --help)" -- \
    $PLAY $S -o "$t/x" --samples 0
exact2 aa_usage_samples_big "glsplay: error: --samples needs M in 1..16777216, got '16777217' (try glsplay --help)" -- \
    $PLAY $S -o "$t/x" --samples 16777217
exact2 aa_usage_samples_and_aa "glsplay: error: --aa, --samples and --subpixel all choose the samples; give one (try glsplay --help)" -- \
    $PLAY $S -o "$t/x" --aa 4 --samples 16
exact2 aa_usage_grid_square "glsplay: error: --pattern grid needs a square --samples (N x N), got 17; the lattice takes any M (try glsplay --help)" -- \
    $PLAY $S -o "$t/x" --samples 17 --pattern grid
exact2 aa_usage_pattern "glsplay: error: --pattern takes one of: lattice, grid, stratified (not 'hex') (try glsplay --help)" -- \
    $PLAY $S -o "$t/x" --pattern hex
exact2 aa_usage_memory "glsplay: error: --aa-memory needs MB in 16..1048576, got '8' (try glsplay --help)" -- \
    $PLAY $S -o "$t/x" --aa-memory 8
# a render projected beyond a minute says so first: 4096 x 4096 samples at
# 640x480 are 16.7 million passes with stratified jitter (hours at any
# speed), and millions of tiles of the lattice's fine framebuffer; the
# projection is made after 2 s, and the render is stopped once it is there
long_render() { # NAME UNITS COUNT_RE PLAY_OPTIONS...
    # each run its own file: a killed run still writing (seen under load)
    # must not put its note into the next run's
    name=$1 units=$2 count=$3
    shift 3
    $PLAY $S -o "$t/long" --aa 4096 --size 640x480 --outputs image "$@" 2>"$t/err_$name" &
    pid=$!
    i=0
    # up to 150 s: the plan at 4096^2 (a generator search over 16.7
    # million candidates) and the first tiles take seconds natively; under
    # ASan on a loaded machine a CI run had printed nothing after 60 s
    while [ $i -lt 600 ] && ! grep -q "estimated render time" "$t/err_$name"; do sleep 0.25; i=$((i + 1)); done
    kill "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    grep -q "^glsplay: note: estimated render time [0-9a-z ]*: 1 camera frame x $count anti-aliasing $units x [0-9.]* [mu]*s (measured on the first [0-9]* $units; --explain shows the plan)\$" \
        "$t/err_$name" && ok "$name" || fail "$name" "$(cat "$t/err_$name")"
}
long_render aa_estimate_before_long_render passes 16777216 --pattern stratified
long_render aa_estimate_before_long_render_lattice tiles '[0-9]*'
# --resume knows the samples: a frame rendered with 16 samples is complete
# for --samples 16, not for --samples 64, nor for the grid's 16
resume() { "$PLAY" $S -o "$t/res" --outputs image --resume "$@" 2>&1 >/dev/null | grep -o '[0-9]* of 1 frame complete'; }
$PLAY $S -o "$t/res" --outputs image --samples 16 2>/dev/null
[ "$(resume --samples 16)" = "1 of 1 frame complete" ] && ok aa_resume_same_samples || fail aa_resume_same_samples "$(resume --samples 16)"
[ "$(resume --samples 64)" = "0 of 1 frame complete" ] && ok aa_resume_other_samples || fail aa_resume_other_samples "$(resume --samples 64)"
$PLAY $S -o "$t/res" --outputs image --samples 16 2>/dev/null
[ "$(resume --aa 4 --pattern grid)" = "0 of 1 frame complete" ] && ok aa_resume_other_pattern || fail aa_resume_other_pattern "$(resume --aa 4 --pattern grid)"
# progress only on a terminal: stderr to a file stays empty
$PLAY $S -o "$t/q" --aa 16 --outputs image 2>"$t/err"
[ ! -s "$t/err" ] && ok aa_no_progress_when_not_tty || fail aa_no_progress_when_not_tty "$(cat "$t/err")"
