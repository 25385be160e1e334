#!/bin/sh
# glsplay --aa exact (spec/antialiasing.md "Exact coverage in glsplay"):
# a white quadrilateral whose edges lie at four directions, at sub-pixel
# positions, against the exact area computed in Python by clipping it to
# each pixel square (no code shared with the engine); a scene of vertex
# colours varying in depth against 65,536 lattice samples; the frame plan's
# exact pass in --explain; the 8-bit and 16-bit images are the float one
# rounded; what exact coverage refuses.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
PLAY=$B/glsplay
[ -x "$PLAY" ] || { fail player_aa_exact "no $PLAY"; exit 0; }
cat >"$t/Sq.scene" <<'SCENE'
color(1, 1, 1);
poly { vert(-1.25, -0.5, 5); vert(0.75, -0.75, 5); vert(1.0, 1.25, 5); vert(-1.0, 1.5, 5); }
SCENE
cat >"$t/Vc.scene" <<'SCENE'
poly { col(1, 0, 0); vert(-1.25, -0.5, 3); col(0, 1, 0); vert(0.75, -0.75, 6); col(0, 0, 1); vert(1.0, 1.25, 8); }
poly { col(1, 1, 0); vert(-1.0, 1.5, 4); col(0, 1, 1); vert(0.5, -1.0, 5); col(1, 0, 1); vert(0.25, 1.0, 3.5); }
SCENE
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
"$B/glsc" -o "$t/sq.glsb" "$t/Sq.scene" 2>"$t/err" && "$B/glsc" -o "$t/vc.glsb" "$t/Vc.scene" 2>>"$t/err" ||
    { fail exact_compile "$(cat "$t/err")"; exit 0; }
for f in pfm png16 png8; do
    "$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --image-format $f --outputs image -o "$t/sq_$f" 2>"$t/err" ||
        fail exact_render_$f "$(cat "$t/err")"
done
"$PLAY" "$t/vc.glsb" --camera "$t/c.cam" --aa exact --image-format pfm --outputs image -o "$t/vc" 2>"$t/err" ||
    fail exact_render_vc "$(cat "$t/err")"
"$REF/glsplay" "$t/vc.glsb" --camera "$t/c.cam" --samples 65536 --image-format pfm --outputs image -o "$t/vc64k" 2>"$t/err" ||
    fail exact_render_vc64k "$(cat "$t/err")"
$PY - "$t" <<'PYEOF'
import sys, cv2, numpy as np
t = sys.argv[1]
def res(name, cond, why=''):
    print(('ok ' if cond else 'FAIL ') + name + ('' if cond else ': ' + why))
def read(p):
    return cv2.imread(t + p, cv2.IMREAD_UNCHANGED)
# the quadrilateral's corners as the scene gives them (float32-exact), projected
P = [(-1.25, -0.5), (0.75, -0.75), (1.0, 1.25), (-1.0, 1.5)]
poly = [(100 * x / 5 + 31.3, 100 * y / 5 + 23.6) for x, y in P]
def clip(pg, a, b, c):  # keep a x + b y + c >= 0
    out = []
    for k in range(len(pg)):
        p, q = pg[k], pg[(k + 1) % len(pg)]
        fp, fq = a * p[0] + b * p[1] + c, a * q[0] + b * q[1] + c
        if fp >= 0:
            out.append(p)
        if (fp > 0 > fq) or (fp < 0 < fq):
            s = fp / (fp - fq)
            out.append((p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])))
    return out
def area(pg):
    n = len(pg)
    return 0.5 * abs(sum(pg[k][0] * pg[(k + 1) % n][1] - pg[(k + 1) % n][0] * pg[k][1] for k in range(n)))
img = read('/sq_pfm/c/image_000000.pfm')
h, w = img.shape[:2]
ref = np.zeros((h, w))
for j in range(h):
    for i in range(w):
        pg = poly
        for a, b, c in ((1, 0, -(i - .5)), (-1, 0, i + .5), (0, 1, -(j - .5)), (0, -1, j + .5)):
            pg = clip(pg, a, b, c)
            if len(pg) < 3:
                break
        ref[j, i] = area(pg) if len(pg) >= 3 else 0
d = np.abs(img - ref[:, :, None]).max()
mixed = ((ref > 0) & (ref < 1)).sum()
# float32 output: the exact area to float precision
res('exact_edges_analytic', d <= 1e-6 and mixed > 100, 'max error %g over %d edge pixels' % (d, mixed))
print('  exact against the analytic area: max per-pixel error %.3g over %d edge pixels' % (d, mixed))
p16, p8 = read('/sq_png16/c/image_000000.png'), read('/sq_png8/c/image_000000.png')
res('exact_png16_rounded', p16 is not None and np.array_equal(p16.astype(np.int64), np.floor(img.astype(np.float64) * 65535 + 0.5).astype(np.int64)),
    'png16 is not the float image rounded')
res('exact_png8_rounded', p8 is not None and np.array_equal(p8[:, :, :3].astype(np.int64), np.floor(img.astype(np.float64) * 255 + 0.5).astype(np.int64)),
    'png8 is not the float image rounded')
# vertex colours: the region's colour at its centroid against 65,536
# lattice samples (which carry their own edge error, about 0.27/256 px,
# and 8-bit samples)
e, s = read('/vc/c/image_000000.pfm'), read('/vc64k/c/image_000000.pfm')
dv = np.abs(e - s)
res('exact_vertex_colours_vs_65536', dv.max() <= 1e-3, 'max difference %g' % dv.max())
print('  exact against 65,536 samples, vertex colours: max %.3g, mean %.3g' % (dv.max(), dv.mean()))
PYEOF
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --outputs image --explain >"$t/plan" 2>&1
grep -q "^  frame plan: passes exact$" "$t/plan" && grep -q "^  exact coverage: each pixel the exact areas" "$t/plan" &&
    grep -q "exact colour 48.0 KiB" "$t/plan" && ok exact_explain || fail exact_explain "$(grep -A3 'frame plan' "$t/plan")"
# through a lens (distort_exact.h): exact in the undistorted image the
# lens path resamples, resampled at 64 lattice positions a pixel; against
# the sampled lens path at 4,096 samples (--aa 64), within 4e-3 (one
# plain pass is 0.61 off; 16 positions instead of 64 give 0.010)
{ cat "$t/c.cam"; echo "distortion 0.1 0 0 0"; } >"$t/lens.cam"
for m in "exact:x" "64:ref" "1:one"; do
    p=$PLAY && [ "${m##*:}" = ref ] && p=$REF/glsplay # the reference: lib.sh's REF
    "$p" "$t/sq.glsb" --camera "$t/lens.cam" --aa ${m%%:*} --image-format pfm --outputs image -o "$t/lens_${m##*:}" \
        2>"$t/err" || fail exact_lens_render "--aa ${m%%:*}: $(cat "$t/err")"
done
$PY - "$t" <<'PYEOF'
import sys, glob, cv2, numpy as np
t = sys.argv[1]
read = lambda k: cv2.imread(glob.glob(t + '/lens_%s/*/image_000000.pfm' % k)[0], cv2.IMREAD_UNCHANGED).astype(np.float64)
ref = read('ref')
d, o = np.abs(read('x') - ref), np.abs(read('one') - ref)
ok = d.max() <= 4e-3 and d.mean() <= 1e-4 and o.max() > 4e-3
print(('ok ' if ok else 'FAIL ') + 'exact_lens_vs_4096' + ('' if ok else ': max %g mean %g; one pass %g' % (d.max(), d.mean(), o.max())))
print('  through a lens: exact against 4,096 samples: max %.3g mean %.3g; one pass max %.3g' % (d.max(), d.mean(), o.max()))
PYEOF
# coverage through a lens: refused (its areas would be the undistorted image's)
"$PLAY" "$t/sq.glsb" --camera "$t/lens.cam" --aa exact --outputs image,coverage -o "$t/l" 2>"$t/err"
rc=$?
[ $rc -eq 1 ] && grep -q "^glsplay: error: camera lens: --outputs coverage needs a pinhole camera: through a lens" "$t/err" &&
    [ ! -e "$t/l" ] && ok exact_lens_refuses_coverage || fail exact_lens_refuses_coverage "exit $rc: $(cat "$t/err")"
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --filter gauss -o "$t/g" 2>"$t/err"
rc=$?
[ $rc -eq 2 ] && grep -q "^glsplay: error: --aa exact is the box filter's exact value; leave out --filter gauss" "$t/err" &&
    ok exact_refuses_gauss || fail exact_refuses_gauss "exit $rc: $(cat "$t/err")"
# the last --aa wins, as for every option
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --aa 4 --outputs image --explain >"$t/plan4" 2>&1
grep -q "^  frame plan: passes samples$" "$t/plan4" && ok exact_last_aa_wins || fail exact_last_aa_wins "$(grep 'frame plan' "$t/plan4")"
# the frame record says exact: --resume does not take a one-sample frame
# for an exact one
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --outputs image -o "$t/rec" 2>/dev/null
rec=$t/rec/c/.frame_000000.done
[ -f "$rec" ] && grep -qx "aa exact" "$rec" && ok exact_frame_record || fail exact_frame_record "$(cat "$rec" 2>/dev/null)"
# coverage: two instances, one partly in front of the other, white on black;
# ids as the instance image's, areas summing to 1, and the white one's
# areas the exact image's
mkdir -p "$t/lib"
echo 'color(1, 1, 1); poly { vert(-1.25, -0.5, 5); vert(0.75, -0.75, 5); vert(1.0, 1.25, 5); vert(-1.0, 1.5, 5); }' >"$t/lib/A.scene"
echo 'color(0, 0, 0); poly { vert(-0.3, -0.2, 4); vert(0.6, -0.1, 4); vert(0.2, 0.7, 4); }' >"$t/lib/B.scene"
printf 'call("A");\ncall("B");\n' >"$t/Two.scene"
if "$B/glsc" -I "$t/lib" -o "$t/two.glsb" "$t/Two.scene" 2>"$t/err"; then
    "$PLAY" "$t/two.glsb" --camera "$t/c.cam" --aa exact --image-format pfm --outputs image,coverage,instance \
        -o "$t/cov" 2>"$t/err" || fail exact_coverage_render "$(cat "$t/err")"
    $PY - "$t" <<'PYEOF'
import sys, csv, cv2, numpy as np
t = sys.argv[1]
def res(name, cond, why=''):
    print(('ok ' if cond else 'FAIL ') + name + ('' if cond else ': ' + why))
rows = list(csv.reader(open(t + '/cov/c/coverage_000000.csv')))
img = cv2.imread(t + '/cov/c/image_000000.pfm', cv2.IMREAD_UNCHANGED)[:, :, 0]
inst = cv2.imread(t + '/cov/c/instance_000000.png', cv2.IMREAD_UNCHANGED)
sums, per = {}, {}
for x, y, i, a in rows[1:]:
    k = (int(y), int(x))
    sums[k] = sums.get(k, 0) + float(a)
    per.setdefault(k, {})[int(i)] = float(a)
worst = max(abs(v - 1) for v in sums.values()) if sums else 1
res('exact_coverage_sums_to_1', rows[0] == ['x', 'y', 'id', 'area'] and len(sums) > 100 and worst <= 1e-6,
    'worst |sum - 1| %g over %d pixels' % (worst, len(sums)))
# ids: every pixel whose centre the instance image gives to an instance
# lists that instance
ids = set(int(i) for _, _, i, _ in rows[1:]) - {0}
bad = [(j, i) for j, i in zip(*np.nonzero(inst)) if int(inst[j, i]) not in per.get((j, i), {})]
res('exact_coverage_ids', ids == set(np.unique(inst)) - {0} and not bad, 'ids %s, %d pixels missing their id' % (ids, len(bad)))
# the white instance's area is the image's value (black instance, black background)
white = min(ids)  # A is called first: the smaller id
d = max(abs(img[j, i] - per.get((j, i), {}).get(white, 0)) for j in range(img.shape[0]) for i in range(img.shape[1]))
res('exact_coverage_matches_image', d <= 1e-6, 'max difference %g' % d)
PYEOF
else
    fail exact_coverage_compile "$(cat "$t/err")"
fi
# coverage with samples asked for: a usage error (the default, exact where
# it can draw, writes it: player_aa_default.sh)
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa 1 --outputs coverage -o "$t/nc" 2>"$t/err"
rc=$?
[ $rc -eq 2 ] && grep -q "^glsplay: error: --outputs coverage needs --aa exact" "$t/err" && ok exact_coverage_needs_exact ||
    fail exact_coverage_needs_exact "exit $rc: $(cat "$t/err")"
# edge_segments (spec/outputs.md "Edge segments"): the quadrilateral's
# segments lie on its projected edges within 1e-6 px, the instance on the
# inside and the background outside, and together they are its outline
# clipped to the image (the diagonal between its two triangles is none)
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --aa exact --outputs edge_segments,instance -o "$t/seg" 2>"$t/err" ||
    fail exact_edge_segments_render "$(cat "$t/err")"
$PY - "$t" <<'PYEOF'
import sys, csv, math, cv2
t = sys.argv[1]
def res(name, cond, why=''):
    print(('ok ' if cond else 'FAIL ') + name + ('' if cond else ': ' + why))
rows = list(csv.reader(open(t + '/seg/c/edge_segments_000000.csv')))
inst = cv2.imread(t + '/seg/c/instance_000000.png', cv2.IMREAD_UNCHANGED)
P = [(-1.25, -0.5), (0.75, -0.75), (1.0, 1.25), (-1.0, 1.5)]
poly = [(100 * x / 5 + 31.3, 100 * y / 5 + 23.6) for x, y in P]
cx, cy = sum(p[0] for p in poly) / 4, sum(p[1] for p in poly) / 4
qid = int(inst[int(round(cy)), int(round(cx))])
def dist(x, y, a, b):  # from (x, y) to segment a-b
    dx, dy = b[0] - a[0], b[1] - a[1]
    s = max(0, min(1, ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.hypot(x - a[0] - s * dx, y - a[1] - s * dy)
def clipped(a, b):  # length of a-b inside the image [-0.5, w - 0.5] x [-0.5, h - 0.5]
    s0, s1 = 0.0, 1.0
    for p, d, lo, hi in ((a[0], b[0] - a[0], -0.5, 63.5), (a[1], b[1] - a[1], -0.5, 47.5)):
        if d == 0:
            continue
        u, v = sorted(((lo - p) / d, (hi - p) / d))
        s0, s1 = max(s0, u), min(s1, v)
    return max(0, s1 - s0) * math.hypot(b[0] - a[0], b[1] - a[1])
worst, length, badids = 0, [0] * 4, 0
for x0, y0, x1, y1, l, r in (map(float, row) for row in rows[1:]):
    d = [max(dist(x0, y0, poly[k], poly[(k + 1) % 4]), dist(x1, y1, poly[k], poly[(k + 1) % 4])) for k in range(4)]
    k = d.index(min(d))
    worst = max(worst, d[k])
    length[k] += math.hypot(x1 - x0, y1 - y0)
    # the quad's centre on the left (image left normal (dy, -dx)): left is the quad
    side = (cx - x0) * (y1 - y0) - (cy - y0) * (x1 - x0)
    badids += (l, r) != ((qid, 0) if side > 0 else (0, qid))
res('exact_edge_segments_on_edges', rows[0] == ['x0', 'y0', 'x1', 'y1', 'left_id', 'right_id'] and len(rows) > 20
    and worst <= 1e-6, 'worst distance %g px over %d segments' % (worst, len(rows) - 1))
res('exact_edge_segments_ids', qid != 0 and badids == 0, 'quad id %d, %d segments with wrong ids' % (qid, badids))
want = [clipped(poly[k], poly[(k + 1) % 4]) for k in range(4)]
d = max(abs(a - b) for a, b in zip(length, want))
res('exact_edge_segments_outline', d <= 1e-6, 'lengths %s, want %s' % (length, want))
PYEOF
# edge_segments with samples asked for: a usage error
"$PLAY" "$t/sq.glsb" --camera "$t/c.cam" --samples 16 --outputs edge_segments -o "$t/ns" 2>"$t/err"
rc=$?
[ $rc -eq 2 ] && grep -q "^glsplay: error: --outputs edge_segments needs --aa exact" "$t/err" &&
    [ ! -e "$t/ns" ] && ok exact_edge_segments_needs_exact || fail exact_edge_segments_needs_exact "exit $rc: $(cat "$t/err")"
# A run whose frames need no GL pass (exact coverage alone) creates no GL
# context (spec/antialiasing.md "Exact coverage in glsplay"): with EGL's
# driver made unloadable, --aa exact still renders, the same pixels, and
# the frame plan's exact line says so; depth (a GL pass) fails there, so
# the driver really was unloadable.  Skipped where --backend egl does not
# render at all (a build or machine without EGL).
if "$PLAY" "$t/vc.glsb" --camera "$t/c.cam" --aa exact --backend egl --outputs image -o "$t/gl_ok" 2>"$t/err"; then
    LIBGL_DRIVERS_PATH="$t/no_drivers" "$PLAY" "$t/vc.glsb" --camera "$t/c.cam" --aa exact --backend egl --outputs image \
        -o "$t/gl_none" 2>"$t/err"
    rc=$?
    LIBGL_DRIVERS_PATH="$t/no_drivers" "$PLAY" "$t/vc.glsb" --camera "$t/c.cam" --aa exact --backend egl \
        --outputs image,depth -o "$t/gl_depth" 2>"$t/err2"
    rc2=$?
    [ $rc -eq 0 ] && [ $rc2 -ne 0 ] && cmp -s "$t/gl_ok/c/image_000000.png" "$t/gl_none/c/image_000000.png" &&
        ok exact_without_gl_context ||
        fail exact_without_gl_context "exit $rc (image) and $rc2 (image and depth, which needs GL): $(cat "$t/err" "$t/err2" | head -3)"
    "$PLAY" "$t/vc.glsb" --camera "$t/c.cam" --aa exact --outputs image --explain >"$t/ex_nogl" 2>&1
    "$PLAY" "$t/vc.glsb" --camera "$t/c.cam" --aa exact --outputs image,depth --explain >"$t/ex_gl" 2>&1
    grep -q "^  exact coverage: .*; no GL pass (a run whose frames all need none creates no GL context" "$t/ex_nogl" &&
        ! grep -q "no GL pass" "$t/ex_gl" && ok exact_explain_no_gl ||
        fail exact_explain_no_gl "$(grep 'exact coverage' "$t/ex_nogl" "$t/ex_gl")"
else
    echo "# exact_without_gl_context: skipped (--backend egl does not render here: $(head -1 "$t/err"))"
fi
