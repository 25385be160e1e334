/* The lattice pattern and the one-pass renderer (spec/antialiasing.md
 * "The lattice", "One pass"): lattice construction, basis reduction and
 * the fine map, the gather (constant colour, exact half-plane coverage,
 * tiles straddled by pixels), the K-pass split, one pass against the
 * multi-pass path of the same pattern, the accuracy of the default, and
 * the rasteriser's snapping in the fine framebuffer.  Long on purpose: a
 * list of independent tests, one function each, over one small rig. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "aa_onepass.h"
#include "aa_render.h"
#include "check.h"
#include "aa_scene.h"

static gls_glctx *ctx;

/* ---- lattice construction ------------------------------------------- */

static uint64_t gcd64(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b, b = t;
    }
    return a;
}

/* Smallest squared distance between two points of the pattern, pixels
 * repeating (torus distance), by brute force over all pairs; exact
 * integer, units of 1/m^2 px^2 (the positions are in units of 1/(2m)). */
static int64_t brute_len2(const gls_lattice *l)
{
    int64_t best = INT64_MAX, q = (int64_t)l->q;
    int64_t *x = malloc(l->m * sizeof *x), *y = malloc(l->m * sizeof *y);
    for (uint64_t i = 0; i < l->m; i++)
        gls_lattice_point(l, i, &x[i], &y[i]);
    for (uint64_t i = 0; i < l->m; i++)
        for (uint64_t j = i + 1; j < l->m; j++) {
            int64_t dx = llabs(x[i] - x[j]), dy = llabs(y[i] - y[j]);
            dx = dx < q - dx ? dx : q - dx, dy = dy < q - dy ? dy : q - dy;
            if (dx * dx + dy * dy < best)
                best = dx * dx + dy * dy;
        }
    free(x), free(y);
    return best / (GLS_LATTICE_UNIT * GLS_LATTICE_UNIT);
}

/* M points: exactly one in each 1/M strip in x, centred in it; in y the
 * multiples of g_h = gcd(a, M) (units 1/M), each g_h times, offset by
 * g_h / 2; the points' mean exactly the pixel centre; the documented
 * minimum distance (the reduced basis' shortest vector, checked by brute
 * force over the pairs); and the documented generators. */
static void test_lattice_points(void)
{
    static const uint64_t ms[] = {1, 2, 3, 4, 5, 16, 17, 64, 100, 256, 1000, 4096};
    for (size_t t = 0; t < sizeof ms / sizeof ms[0]; t++) {
        uint64_t m = ms[t];
        gls_lattice l;
        CHECK(gls_lattice_choose(m, &l) == 0);
        CHECK(l.m == m && l.q == GLS_LATTICE_UNIT * m && l.g0 == gcd64(l.a, m));
        uint64_t g = l.g0;
        uint8_t *sx = calloc(m, 1);
        uint64_t *sy = calloc(m, sizeof *sy);
        int bad = 0;
        int64_t sumx = 0, sumy = 0;
        for (uint64_t i = 0; i < m; i++) {
            int64_t x, y;
            gls_lattice_point(&l, i, &x, &y);
            sumx += x, sumy += y;
            if (x < 0 || y < 0 || x >= (int64_t)l.q || y >= (int64_t)l.q) {
                bad++;
                continue;
            }
            /* x: 2 i + 1; y: 2 k g + g */
            bad += x % GLS_LATTICE_UNIT != 1 || (y - (int64_t)g) % (GLS_LATTICE_UNIT * (int64_t)g) != 0;
            sx[x / GLS_LATTICE_UNIT]++;
            sy[y / GLS_LATTICE_UNIT]++;
        }
        for (uint64_t i = 0; i < m; i++)
            bad += sx[i] != 1 || sy[i] != (i % g == g / 2 ? g : 0);
        CHECK_MSG(bad == 0, "M %llu: %d points outside, off their strips or strips not hit as documented",
                  (unsigned long long)m, bad);
        /* mean (units 1/q) = q / 2 = m: the pixel centre, exactly */
        CHECK_MSG(sumx == (int64_t)(m * m) && sumy == (int64_t)(m * m), "M %llu: mean (%g, %g) px, not centred",
                  (unsigned long long)m, (double)sumx / (double)(m * l.q), (double)sumy / (double)(m * l.q));
        free(sx), free(sy);
        if (m > 1) {
            int64_t bd = brute_len2(&l);
            CHECK_MSG(bd == l.len2 && fabs(l.mindist - sqrt((double)bd) / (double)m) < 1e-15,
                      "M %llu: |e1|^2 %lld, brute force %lld", (unsigned long long)m, (long long)l.len2, (long long)bd);
            printf("  M %5llu: a = %llu, closest points %.5f px = %.4f / sqrt(M), points a position at 0/45/135 "
                   "degrees %llu/%llu/%llu: %.6f px\n",
                   (unsigned long long)m, (unsigned long long)l.a, l.mindist, l.mindist * sqrt((double)m),
                   (unsigned long long)l.g0, (unsigned long long)l.g45, (unsigned long long)l.g135, l.axis_diag);
        }
    }
    /* spec/antialiasing.md's table */
    static const uint64_t gen[][2] = {{16, 4},    {64, 28},      {256, 30},
                                      {1024, 271}, {4096, 70},    {65536, 25962},
                                      {4096ull * 4096, 7605516}};
    for (int i = 0; i < 7; i++) {
        gls_lattice l;
        CHECK_MSG(gls_lattice_choose(gen[i][0], &l) == 0 && l.a == gen[i][1], "M %llu: a = %llu, documented %llu",
                  (unsigned long long)gen[i][0], (unsigned long long)l.a, (unsigned long long)gen[i][1]);
    }
    /* the largest M: the search stays exact (no overflow) */
    gls_lattice big;
    CHECK(gls_lattice_choose(GLS_LATTICE_MAX_M, &big) == 0);
    CHECK(big.mindist * 4096 >= 1.0);
    int64_t x0, y0, x1, y1;
    gls_lattice_point(&big, GLS_LATTICE_MAX_M - 1, &x1, &y1);
    gls_lattice_point(&big, 0, &x0, &y0);
    CHECK(x1 >= 0 && x1 < (int64_t)big.q && y1 >= 0 && y1 < (int64_t)big.q && x1 != x0);
}

/* Worst per-row RMS edge error of lattice l over n directions (degrees),
 * computed from its points by bench/aa_scene.h. */
static double worst_measured(const gls_lattice *l, const double *deg, size_t n)
{
    double *x = malloc(l->m * sizeof *x), *y = malloc(l->m * sizeof *y), *s = malloc(l->m * sizeof *s), w = 0;
    for (uint64_t i = 0; i < l->m; i++) {
        int64_t X, Y;
        gls_lattice_point(l, i, &X, &Y);
        x[i] = (double)X / (double)l->q, y[i] = (double)Y / (double)l->q;
    }
    for (size_t k = 0; k < n; k++)
        w = fmax(w, as_pattern_rms(x, y, (long)l->m, deg[k], s));
    free(x), free(y), free(s);
    return w;
}

/* ... at 0, 45, 90 and 135 degrees (independently of the gcd formula the
 * criterion uses). */
static double axis_diag_measured(const gls_lattice *l)
{
    static const double deg[] = {0, 45, 90, 135};
    return worst_measured(l, deg, 4);
}

/* The criterion, checked by brute force over every a in 1..M-1 (not only
 * those coprime to M): the chosen generator has the longest shortest
 * vector (from the pairs of points for M <= 256, from the reduction
 * above), no generator with that length does better at 0/45/90/135
 * degrees (measured from the points) or as well with a smaller a, and
 * the chosen one's value is the formula's.  256 -> 30 and 4096 -> 70 are
 * cross-checked here. */
static void test_lattice_criterion(void)
{
    static const uint64_t ms[] = {16, 64, 100, 256, 1000, 1024, 4096};
    for (size_t t = 0; t < sizeof ms / sizeof ms[0]; t++) {
        uint64_t m = ms[t];
        gls_lattice l;
        CHECK(gls_lattice_choose(m, &l) == 0);
        double mine = axis_diag_measured(&l), best = 1e9;
        CHECK_MSG(fabs(mine - l.axis_diag) < 1e-9, "M %llu: measured %.9f, formula %.9f", (unsigned long long)m, mine,
                  l.axis_diag);
        int64_t bestd = 0;
        uint64_t besta = 0;
        for (uint64_t a = 1; a < m; a++) {
            gls_lattice o;
            CHECK(gls_lattice_make(m, a, &o) == 0);
            int64_t d = m <= 256 ? brute_len2(&o) : o.len2;
            bestd = d > bestd ? d : bestd;
        }
        for (uint64_t a = 1; a < m; a++) {
            gls_lattice o;
            if (gls_lattice_make(m, a, &o) == 0 && o.len2 == bestd) {
                double e = axis_diag_measured(&o);
                if (e < best - 1e-12)
                    best = e, besta = a;
            }
        }
        CHECK_MSG(l.len2 == bestd && fabs(mine - best) < 1e-12 && l.a == besta,
                  "M %llu: a = %llu (|e1|^2 %lld, %.6f px), brute force a = %llu (|e1|^2 %lld, %.6f px)",
                  (unsigned long long)m, (unsigned long long)l.a, (long long)l.len2, mine, (unsigned long long)besta,
                  (long long)bestd, best);
        if (m == 256)
            CHECK(besta == 30);
        if (m == 4096)
            CHECK(besta == 70);
    }
}

/* ... at issue 13's listed angles. */
static double listed_measured(const gls_lattice *l)
{
    static const double listed[] = {0.5, 1, 3, 10, 22.5, 30, 45, 60, 80};
    return worst_measured(l, listed, sizeof listed / sizeof listed[0]);
}

/* What spec/antialiasing.md ("Accuracy") says of issue 13's 1/2048 px
 * target at 4096 samples: the issue's own rule, the largest minimum
 * distance, leaves exactly two generators, a = 70 and its mirror image
 * a = 4026, and neither meets the target at the listed angles (0.0047 and
 * 0.0024 px), while some other generators do (a = 2618: 0.00017 px), only
 * because their bad directions fall between those angles. */
static void test_issue_rule_at_4096(void)
{
    const uint64_t m = 4096;
    int64_t bestd = 0;
    for (uint64_t a = 1; a < m; a++) {
        gls_lattice o;
        CHECK(gls_lattice_make(m, a, &o) == 0);
        bestd = o.len2 > bestd ? o.len2 : bestd;
    }
    uint64_t ties[4], nties = 0;
    for (uint64_t a = 1; a < m; a++) {
        gls_lattice o;
        if (gls_lattice_make(m, a, &o) == 0 && o.len2 == bestd && nties < 4)
            ties[nties++] = a;
    }
    CHECK_MSG(nties == 2 && ties[0] == 70 && ties[1] == 4026, "%llu generators with the largest distance",
              (unsigned long long)nties);
    static const struct {
        uint64_t a;
        double listed;
    } want[] = {{70, 0.004693}, {4026, 0.002364}, {2618, 0.000172}};
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
        gls_lattice o;
        CHECK(gls_lattice_make(m, want[k].a, &o) == 0);
        double e = listed_measured(&o);
        CHECK_MSG(fabs(e - want[k].listed) < 1e-6, "a = %llu: %.6f px at the listed angles, spec %.6f",
                  (unsigned long long)want[k].a, e, want[k].listed);
        CHECK((e > 1.0 / 2048) == (k < 2));
    }
    /* Read with generators coprime to M (the usual Korobov form), the rule
     * leaves a = 671, 1697, 2399 and 3425; each puts 32 samples a position
     * across one diagonal, and 2399 meets the target at the listed angles
     * only because its bad diagonal, 135 degrees, is not listed. */
    int64_t bestc = 0;
    for (uint64_t a = 1; a < m; a += 2) {
        gls_lattice o;
        CHECK(gls_lattice_make(m, a, &o) == 0);
        bestc = o.len2 > bestc ? o.len2 : bestc;
    }
    static const uint64_t cop[] = {671, 1697, 2399, 3425};
    size_t ncop = 0;
    for (uint64_t a = 1; a < m; a += 2) {
        gls_lattice o;
        if (gls_lattice_make(m, a, &o) == 0 && o.len2 == bestc) {
            CHECK_MSG(ncop < 4 && a == cop[ncop], "coprime generator %llu with the largest distance",
                      (unsigned long long)a);
            ncop++;
            CHECK(o.axis_diag > 31.0 / (4096 * sqrt(12.0)) && o.axis_diag < 33.0 / (4096 * sqrt(12.0)));
        }
    }
    CHECK(ncop == 4);
    gls_lattice o;
    CHECK(gls_lattice_make(m, 2399, &o) == 0);
    CHECK(listed_measured(&o) < 1.0 / 2048);
    CHECK_MSG(fabs(o.axis_diag - 0.002255) < 1e-6, "a = 2399: %.6f px at 0/45/90/135 degrees", o.axis_diag);
}

/* The gather's run sum against byte-by-byte addition: every length up to
 * 1030 (odd and even, across the 256-pixel emptying of its 16-bit lanes),
 * at every alignment of 4, on all-255 pixels (the largest lane sums) and
 * on splitmix64 noise, added to nonzero starting sums. */
static void test_sum_run(void)
{
    enum { N = 1030 };
    uint8_t *buf = malloc(4 * (N + 4));
    for (int fill = 0; fill < 2; fill++) {
        uint64_t st = 12345;
        for (size_t i = 0; i < 4 * (N + 4); i++) {
            st += 0x9E3779B97F4A7C15ull;
            uint64_t z = st;
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            buf[i] = fill ? (uint8_t)(z >> 56) : 255;
        }
        int bad = 0;
        for (uint32_t len = 0; len <= N; len++)
            for (uint32_t at = 0; at < 4; at++) {
                uint32_t got[3] = {7, 8, 9}, want[3] = {7, 8, 9};
                const uint8_t *q = buf + 4 * at;
                gls_aa_sum_run(q, len, got);
                for (uint32_t i = 0; i < len; i++)
                    want[0] += q[4 * i], want[1] += q[4 * i + 1], want[2] += q[4 * i + 2];
                if (memcmp(got, want, sizeof got) && !bad++)
                    CHECK_MSG(0, "fill %d, length %u at %u: %u %u %u, want %u %u %u", fill, len, at, got[0], got[1],
                              got[2], want[0], want[1], want[2]);
            }
        CHECK(bad == 0);
    }
    free(buf);
}

/* The mean per-row edge displacement over edge offsets, computed directly
 * (not from the points' mean): a row of pixels u = -3..3 crossed by an
 * edge x = c + y cot(theta) (steep; flat edges per column, x and y
 * swapped), the samples left of it counted, the exact covered area
 * c + cot / 2 + 3 subtracted; over c uniform in [0, 1) sample i of pixel
 * u counts with probability 1 - clamp(u + x_i - y_i cot, 0, 1). */
static double mean_row_displacement(const gls_lattice *l, double deg)
{
    double t = deg * AS_PI / 180, q = (double)l->q;
    int steep = fabs(sin(t)) >= fabs(cos(t));
    double sl = steep ? cos(t) / sin(t) : sin(t) / cos(t);
    long double count = 0;
    for (uint64_t i = 0; i < l->m; i++) {
        int64_t X, Y;
        gls_lattice_point(l, i, &X, &Y);
        double x = (double)X / q, y = (double)Y / q, p = steep ? x - y * sl : y - x * sl;
        for (int u = -3; u <= 3; u++)
            count += 1 - fmin(fmax(u + p, 0), 1);
    }
    return (double)(count / (long double)l->m) - (0.5 + sl / 2 + 3);
}

/* Centring: no systematic edge shift at any direction, for generators
 * with gcd(a, M) = 1, 2 and 4 (with the offset 1/2 instead of g_h / 2
 * the mean is off by up to (g_h - 1) / (2 M) px). */
static void test_lattice_centred(void)
{
    static const uint64_t cases[][2] = {{256, 19}, {256, 30}, {256, 76}, {4096, 475}, {4096, 70},
                                        {4096, 1100}, {1000, 3}, {1000, 302}, {1000, 212}, {64, 28}};
    static const double dirs[] = {0, 45, 90, 135, 30};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        gls_lattice l;
        CHECK(gls_lattice_make(cases[c][0], cases[c][1], &l) == 0);
        for (int d = 0; d < 5; d++) {
            double mean = mean_row_displacement(&l, dirs[d]);
            CHECK_MSG(fabs(mean) < 1e-12, "M %llu a %llu (gcd %llu) at %g deg: mean displacement %.3g px",
                      (unsigned long long)l.m, (unsigned long long)l.a, (unsigned long long)l.g0, dirs[d], mean);
        }
    }
}

/* ---- basis reduction and the fine map -------------------------------- */

static int64_t dot(gls_iv2 a, gls_iv2 b) { return a.x * b.x + a.y * b.y; }

/* Reduction: shortest first, |b1| <= |b2| <= |b2 +- b1|, same lattice.
 * The fine map: every sample of a pass maps to a fine pixel centre
 * exactly (integer arithmetic) and through the float map to within
 * 1e-6 fine px; a block of pixels' samples are distinct fine pixels,
 * L per pixel. */
static void test_basis_and_map(void)
{
    static const uint64_t pairs[][2] = {{256, 71}, {256, 3}, {1000, 3}, {4096, 231}, {97, 40}, {2, 1}, {65536, 22807}};
    for (int i = 0; i < 7; i++) {
        gls_iv2 b1 = {1, (int64_t)pairs[i][1]}, b2 = {0, (int64_t)pairs[i][0]};
        gls_lattice_reduce(&b1, &b2);
        gls_iv2 s = {b2.x + b1.x, b2.y + b1.y}, d = {b2.x - b1.x, b2.y - b1.y};
        CHECK(dot(b1, b1) <= dot(b2, b2) && dot(b2, b2) <= dot(s, s) && dot(b2, b2) <= dot(d, d));
        int64_t det = b1.x * b2.y - b1.y * b2.x;
        CHECK(det == (int64_t)pairs[i][0] || det == -(int64_t)pairs[i][0]);
        /* (1, a) and (0, M) are integer combinations of b1, b2 */
        int64_t g[2][2] = {{1, (int64_t)pairs[i][1]}, {0, (int64_t)pairs[i][0]}};
        for (int k = 0; k < 2; k++) {
            int64_t p = g[k][0] * b2.y - g[k][1] * b2.x, q = b1.x * g[k][1] - b1.y * g[k][0];
            CHECK(p % det == 0 && q % det == 0);
        }
    }
    char err[128];
    struct {
        gls_aa_pattern pat;
        uint64_t m, max_l;
        gls_aa_filter f;
    } cases[] = {{GLS_AA_LATTICE, 16, 0, GLS_AA_BOX},   {GLS_AA_LATTICE, 256, 0, GLS_AA_BOX},
                 {GLS_AA_LATTICE, 1000, 0, GLS_AA_BOX}, {GLS_AA_LATTICE, 256, 64, GLS_AA_BOX},
                 {GLS_AA_LATTICE, 17, 0, GLS_AA_GAUSS}, {GLS_AA_GRID, 64, 0, GLS_AA_BOX},
                 {GLS_AA_GRID, 64, 16, GLS_AA_BOX},     {GLS_AA_LATTICE, 4096, 0, GLS_AA_BOX},
                 {GLS_AA_LATTICE, 16, 4, GLS_AA_BOX},   {GLS_AA_LATTICE, 4096, 64, GLS_AA_BOX}};
    for (size_t t = 0; t < sizeof cases / sizeof cases[0]; t++) {
        gls_aa_opts o = gls_aa_defaults();
        o.samples = cases[t].m;
        o.pattern = cases[t].pat;
        o.filter = cases[t].f;
        gls_aa_plan p;
        gls_aa_fine f;
        CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
        CHECK(gls_aa_fine_init(&f, &p, cases[t].max_l ? cases[t].max_l : 65536) == 0);
        CHECK(f.k * f.l == p.m && f.a[0][0] * f.a[1][1] - f.a[0][1] * f.a[1][0] == (int64_t)f.l);
        /* image rows run along fine rows (aa_fine.c: the gather's order) */
        CHECK(llabs(f.a[1][0]) <= llabs(f.a[0][0]));
        int64_t(*pos)[2] = malloc(f.l * sizeof *pos), (*c)[2] = malloc(f.l * sizeof *c);
        int bad_exact = 0, bad_float = 0, dup = 0;
        double worst = 0;
        for (uint64_t r = 0; r < f.k; r++) {
            int64_t sh[2];
            gls_aa_fine_pass(&f, r, sh, pos, c);
            double m[6];
            gls_aa_fine_map(&f, sh, 123, -45, m);
            for (uint64_t j = 0; j < f.l; j++) {
                __int128 dx = pos[j][0] - sh[0], dy = pos[j][1] - sh[1];
                bad_exact += f.a[0][0] * dx + f.a[0][1] * dy != (__int128)f.q * c[j][0] ||
                             f.a[1][0] * dx + f.a[1][1] * dy != (__int128)f.q * c[j][1];
                for (int px = 0; px < 2; px++) {
                    double u = px ? 37 : 0, v = px ? 11 : 0;
                    double iu = u - 0.5 + (double)pos[j][0] / (double)f.q, iv = v - 0.5 + (double)pos[j][1] / (double)f.q;
                    double wx = m[0] * iu + m[1] * iv + m[2], wy = m[3] * iu + m[4] * iv + m[5];
                    double ex = (double)(c[j][0] + (int64_t)u * f.a[0][0] + (int64_t)v * f.a[0][1] - 123) + 0.5;
                    double ey = (double)(c[j][1] + (int64_t)u * f.a[1][0] + (int64_t)v * f.a[1][1] + 45) + 0.5;
                    double e = fmax(fabs(wx - ex), fabs(wy - ey));
                    worst = fmax(worst, e);
                    bad_float += e > 1e-6;
                }
            }
            /* 3 x 3 pixels: 9 L distinct fine pixels */
            uint64_t n = 9 * f.l;
            int64_t *key = malloc(n * sizeof *key);
            for (uint64_t k = 0; k < n; k++) {
                uint64_t px = k / f.l, j = k % f.l;
                int64_t u = (int64_t)(px % 3), v = (int64_t)(px / 3);
                int64_t X = c[j][0] + u * f.a[0][0] + v * f.a[0][1], Y = c[j][1] + u * f.a[1][0] + v * f.a[1][1];
                key[k] = (X + (1 << 20)) * (1 << 22) + (Y + (1 << 20));
            }
            for (uint64_t a = 0; a < n && n <= 9 * 4096; a++)
                for (uint64_t b = a + 1; b < n; b++)
                    dup += key[a] == key[b];
            free(key);
        }
        CHECK_MSG(bad_exact == 0 && bad_float == 0 && dup == 0, "case %zu: %d not exact, %d float (worst %g), %d dup",
                  t, bad_exact, bad_float, worst, dup);
        free(pos), free(c);
    }
}

/* How many passes: the fewest with L <= max_l (K dividing M; for the grid
 * K = k^2 with k dividing N); a divisor below the need only while L stays
 * within 16 max_l, so a prime M far above max_l (or a grid of prime N) is
 * M passes of one sample, never one pass whose pixels each span millions
 * of fine pixels. */
static void test_pass_split_choice(void)
{
    static const struct {
        gls_aa_pattern pat;
        uint64_t m, max_l, k;
    } cases[] = {{GLS_AA_LATTICE, 256, 65536, 1},          {GLS_AA_LATTICE, 262144, 65536, 4},
                 {GLS_AA_LATTICE, 65537, 65536, 1},        {GLS_AA_LATTICE, 16777213, 65536, 16777213},
                 {GLS_AA_LATTICE, 16777216, 65536, 256},   {GLS_AA_GRID, 4093ull * 4093, 65536, 4093ull * 4093},
                 {GLS_AA_GRID, 4096ull * 4096, 65536, 256}, {GLS_AA_GRID, 64, 16, 4}};
    char err[128];
    for (size_t t = 0; t < sizeof cases / sizeof cases[0]; t++) {
        gls_aa_opts o = gls_aa_defaults();
        o.samples = cases[t].m;
        o.pattern = cases[t].pat;
        gls_aa_plan p;
        gls_aa_fine f;
        CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
        CHECK(gls_aa_fine_init(&f, &p, cases[t].max_l) == 0);
        CHECK_MSG(f.k == cases[t].k && f.k * f.l == cases[t].m, "M %llu: K %llu L %llu, expected K %llu",
                  (unsigned long long)cases[t].m, (unsigned long long)f.k, (unsigned long long)f.l,
                  (unsigned long long)cases[t].k);
    }
}

/* ---- rendering helpers ---------------------------------------------- */

typedef struct {
    gls_scene s;
    gls_renderer *r;
} rig;

static int rig_open(rig *g, const gls_bundle *b)
{
    char err[256];
    memset(g, 0, sizeof *g);
    if (gls_scene_flatten(b, &g->s, err, sizeof err) || !(g->r = gls_renderer_create(ctx, b, &g->s, err, sizeof err))) {
        printf("  %s\n", err);
        return -1;
    }
    return 0;
}

static void rig_close(rig *g)
{
    gls_renderer_destroy(g->r);
    gls_scene_free(&g->s);
}

/* One-pass render of options o (max_tile, max_l: 0 automatic) of image
 * rows v0..v1-1 into acc (initialised here, with the mask). */
static int fine_rows(rig *g, const gls_camera *c, const gls_aa_opts *o, uint32_t max_tile, uint64_t max_l, uint32_t v0,
                     uint32_t v1, gls_accum *acc, gls_aa_fine_stats *st)
{
    char err[256];
    gls_aa_plan p;
    if (gls_aa_plan_init(&p, o, err, sizeof err) || gls_accum_init(acc, c->width, c->height, gls_aa_weighted(&p), 1)) {
        printf("  plan: %s\n", err);
        return -1;
    }
    if (gls_renderer_set_size(g->r, c->width, c->height, err, sizeof err))
        return -1;
    gls_aa_fine_opts fo = {0, max_tile, max_l, NULL, NULL, NULL, NULL};
    if (gls_aa_render_fine_rows(g->r, c, &p, &fo, v0, v1, acc, st, err, sizeof err)) {
        printf("  render: %s\n", err);
        gls_accum_free(acc);
        return -1;
    }
    return 0;
}

/* The same, every row (what gls_aa_render_fine draws). */
static int fine(rig *g, const gls_camera *c, const gls_aa_opts *o, uint32_t max_tile, uint64_t max_l, gls_accum *acc,
                gls_aa_fine_stats *st)
{
    return fine_rows(g, c, o, max_tile, max_l, 0, c->height, acc, st);
}

/* Multi-pass render of the same plan (aa_render.h). */
static int multi(rig *g, const gls_camera *c, const gls_aa_opts *o, gls_accum *acc)
{
    char err[256];
    gls_aa_plan p;
    if (gls_aa_plan_init(&p, o, err, sizeof err) || gls_accum_init(acc, c->width, c->height, gls_aa_weighted(&p), 1) ||
        gls_renderer_set_size(g->r, c->width, c->height, err, sizeof err))
        return -1;
    gls_aa_run_opts ro = {0, 0, NULL, NULL, NULL, NULL};
    if (gls_aa_render(g->r, c, &p, &ro, acc, NULL, err, sizeof err)) {
        printf("  render: %s\n", err);
        gls_accum_free(acc);
        return -1;
    }
    return 0;
}

static int same_acc(const gls_accum *a, const gls_accum *b)
{
    size_t n = (size_t)a->width * a->height * 4;
    if (a->weighted != b->weighted || a->wsum != b->wsum)
        return 0;
    if (a->weighted ? memcmp(a->sum64, b->sum64, n * 8) : memcmp(a->sum32, b->sum32, n * 4))
        return 0;
    return !a->mixed || !b->mixed || memcmp(a->mixed, b->mixed, n / 4) == 0;
}

/* ---- gather ---------------------------------------------------------- */

/* A constant colour stays exactly that colour through the fine path, for
 * any M (primes, squares, powers of two), both filters, the grid, tiny
 * tiles (pixels straddling many tiles) and automatic ones. */
static void test_gather_constant(void)
{
    gls_bundle *b = tb_wall();
    rig g;
    CHECK(rig_open(&g, b) == 0);
    gls_camera c = tb_front_camera(21, 13);
    size_t n = 21 * 13;
    float *f = malloc(n * 12);
    uint16_t *p16 = malloc(n * 6);
    static const uint64_t ms[] = {2, 7, 16, 17, 64, 256};
    for (size_t i = 0; i < sizeof ms / sizeof ms[0]; i++)
        for (int v = 0; v < 4; v++) {
            gls_aa_opts o = gls_aa_defaults();
            o.samples = ms[i];
            o.filter = v == 1 ? GLS_AA_GAUSS : GLS_AA_BOX;
            if (v == 3) {
                if (ms[i] != 16 && ms[i] != 64 && ms[i] != 256)
                    continue;
                o.pattern = GLS_AA_GRID;
            }
            gls_accum a;
            gls_aa_fine_stats st;
            CHECK(fine(&g, &c, &o, v == 2 ? 5 : 0, 0, &a, &st) == 0);
            gls_accum_rgbf(&a, f);
            gls_accum_rgb16(&a, p16);
            int bad = 0, mixed = 0;
            for (size_t k = 0; k < n; k++) {
                static const int want[3] = {77, 154, 231};
                for (int ch = 0; ch < 3; ch++)
                    bad += p16[3 * k + ch] != want[ch] * 257 || f[3 * k + ch] != (float)(want[ch] / 255.0);
                mixed += a.mixed[k];
            }
            CHECK_MSG(bad == 0 && mixed == 0, "M %llu variant %d: %d values off, %d mixed", (unsigned long long)ms[i], v,
                      bad, mixed);
            if (v == 2)
                CHECK(st.tiles_drawn > 4);
            gls_accum_free(&a);
        }
    free(f), free(p16);
    rig_close(&g);
    gls_bundle_free(b);
}

/* White half-plane n . p < d in the image (n at angle phi), drawn as a
 * quad reaching 64 px beyond the image at depth 5 through tb_front_camera
 * (not much further: float vertex coordinates far away would tilt the
 * edge by more than the clearance these tests keep). */
static gls_bundle *halfplane(const gls_camera *c, double phi, double d)
{
    double nx = cos(phi), ny = sin(phi), tx = -ny, ty = nx, z = 5;
    double q[4][3];
    double px = nx * d, py = ny * d; /* a point on the edge */
    double L = 64 + c->width + c->height;
    double pts[4][2] = {{px - L * tx, py - L * ty}, {px + L * tx, py + L * ty},
                        {px + L * tx - L * nx, py + L * ty - L * ny},
                        {px - L * tx - L * nx, py - L * ty - L * ny}};
    for (int i = 0; i < 4; i++) {
        q[i][0] = (pts[i][0] - c->cx) * z / c->fx;
        q[i][1] = (pts[i][1] - c->cy) * z / c->fy;
        q[i][2] = z;
    }
    tb t;
    tb_init(&t);
    tb_object(&t, "half", 1);
    tb_color(&t, 1, 1, 1, 1);
    tb_poly(&t, 4, (const double(*)[3])q);
    return tb_finish(&t);
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* An edge n . p = d (n at angle phi) for a w x h image of plan p's
 * samples that keeps as clear as possible of every sample of every pixel
 * (and a pixel around): the middle of the largest gap between the
 * samples' projections within [d0, d0 + 1).  *clear: half that gap. */
static double clear_edge(const gls_aa_plan *p, uint32_t w, uint32_t h, double phi, double d0, double *clear)
{
    double nx = cos(phi), ny = sin(phi);
    size_t n = 0, cap = (size_t)(w + 2) * (h + 2) * p->m + 2;
    double *pr = malloc(cap * sizeof *pr);
    for (int v = -1; v <= (int)h; v++)
        for (int u = -1; u <= (int)w; u++)
            for (uint64_t k = 0; k < p->m; k++) {
                int64_t x, y;
                gls_lattice_point(&p->lat, k, &x, &y);
                double pv = nx * (u - 0.5 + (double)x / (double)p->lat.q) + ny * (v - 0.5 + (double)y / (double)p->lat.q);
                if (pv >= d0 && pv < d0 + 1)
                    pr[n++] = pv;
            }
    pr[n++] = d0, pr[n++] = d0 + 1;
    qsort(pr, n, sizeof *pr, cmp_dbl);
    double best = -1, d = d0;
    for (size_t i = 0; i + 1 < n; i++)
        if (pr[i + 1] - pr[i] > best)
            best = pr[i + 1] - pr[i], d = (pr[i] + pr[i + 1]) / 2;
    free(pr);
    *clear = best / 2;
    return d;
}

/* The gather against the exact coverage of the lattice points, computed
 * independently from the plan's sample positions: a half-plane at an
 * angle, placed where no sample is within the rasteriser's reach (the
 * largest gap between the samples' projections), so every pixel must be
 * exactly (samples inside) / M; with tiny tiles and automatic ones, and
 * the mask exactly where 0 < count < M. */
static void test_gather_halfplane(void)
{
    static const uint64_t ms[] = {7, 16, 64, 100};
    /* normals (1, 0), (2, 1), (1, 3), (-1, 2): rational slopes, so the
     * samples' projections bunch and leave gaps wider than the
     * rasteriser's snapping and the float vertices' rounding (about
     * 1e-4 px here); at irrational slopes the clearance over a whole
     * image is only a few 1e-4 px */
    const double phis[] = {0, atan2(1, 2), atan2(3, 1), atan2(2, -1)};
    gls_camera c = tb_front_camera(24, 18);
    size_t n = 24 * 18;
    uint16_t *p16 = malloc(n * 6);
    char err[128];
    for (size_t i = 0; i < sizeof ms / sizeof ms[0]; i++)
        for (size_t a = 0; a < sizeof phis / sizeof phis[0]; a++) {
            gls_aa_opts o = gls_aa_defaults();
            o.samples = ms[i];
            gls_aa_plan p;
            CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
            double nx = cos(phis[a]), ny = sin(phis[a]), best;
            double dd = clear_edge(&p, 24, 18, phis[a], nx * 12 + ny * 9, &best);
            gls_bundle *b = halfplane(&c, phis[a], dd);
            rig g;
            CHECK(rig_open(&g, b) == 0);
            for (int tiny = 0; tiny < 3; tiny++) {
                gls_accum acc;
                CHECK(fine(&g, &c, &o, tiny == 2 ? 3 : tiny ? 7 : 0, 0, &acc, NULL) == 0);
                gls_accum_rgb16(&acc, p16);
                int bad = 0, badmask = 0;
                for (int v = 0; v < 18; v++)
                    for (int u = 0; u < 24; u++) {
                        uint64_t in = 0;
                        for (uint64_t k = 0; k < p.m; k++) {
                            int64_t x, y;
                            gls_lattice_point(&p.lat, k, &x, &y);
                            double sx = u - 0.5 + (double)x / (double)p.lat.q, sy = v - 0.5 + (double)y / (double)p.lat.q;
                            in += nx * sx + ny * sy < dd;
                        }
                        unsigned want = (unsigned)((in * 65535 * 2 + p.m) / (2 * p.m));
                        bad += p16[3 * (v * 24 + u)] != want;
                    }
                CHECK_MSG(bad == 0 && badmask == 0, "M %llu phi %g tiny %d (clearance %.2g px): %d pixels, %d mask",
                          (unsigned long long)p.m, phis[a], tiny, best, bad, badmask);
                gls_accum_free(&acc);
            }
            rig_close(&g);
            gls_bundle_free(b);
        }
    free(p16);
}

/* The scene of the tile tests below: squares whose edges pass
 * arbitrarily close to samples, 48 x 36, its camera, bundle and rig. */
typedef struct {
    as_scene s;
    gls_camera c;
    gls_bundle *b;
    rig g;
} close_edges;

static int close_edges_open(close_edges *t)
{
    as_layout(&t->s, 48, 36, 2, 1, 14);
    t->c = as_camera(&t->s, 1, 100);
    t->b = as_bundle(&t->s, &t->c);
    return rig_open(&t->g, t->b);
}

static void close_edges_close(close_edges *t)
{
    rig_close(&t->g);
    gls_bundle_free(t->b);
}

/* The two filters the tile tests run: 0 the box with M = 64, 1 the
 * Gaussian with M = 9. */
static gls_aa_opts close_edges_opts(int fl)
{
    gls_aa_opts o = gls_aa_defaults();
    o.samples = fl ? 9 : 64;
    o.filter = fl ? GLS_AA_GAUSS : GLS_AA_BOX;
    return o;
}

/* Pixels straddling tiles on a scene whose edges pass arbitrarily close
 * to samples: tiles of 3, 7 and 64 fine pixels against automatic tiles,
 * box and Gaussian.  Each tile has its own projection (its origin moves
 * the map's constant), so a sample within float rounding of an edge may
 * fall either way; the exact gather across tiles is test_gather_halfplane
 * (tiles of 3 and 7).  Here: the sums agree except for such samples, at
 * most 2 per pixel and in under 3% of the pixels (measured, printed: up
 * to 2 of 1728 pixels, by 1 sample, box, M = 64, a = 28; none for the
 * Gaussian at M = 9). */
static void test_tiles_straddle(void)
{
    close_edges e;
    CHECK(close_edges_open(&e) == 0);
    rig *g = &e.g;
    const gls_camera *c = &e.c;
    size_t n = (size_t)e.s.w * e.s.h;
    for (int fl = 0; fl < 2; fl++) {
        gls_aa_opts o = close_edges_opts(fl);
        gls_accum ref;
        gls_aa_fine_stats st;
        CHECK(fine(g, c, &o, 0, 0, &ref, &st) == 0);
        static const uint32_t sides[] = {3, 7, 64};
        for (int i = 0; i < 3; i++) {
            gls_accum a;
            gls_aa_fine_stats st2;
            CHECK(fine(g, c, &o, sides[i], 0, &a, &st2) == 0);
            CHECK(st2.tiles_drawn > st.tiles_drawn && a.wsum == ref.wsum);
            double worst = 0;
            long diff = 0;
            for (size_t k = 0; k < n; k++) {
                double d = a.weighted ? fabs((double)a.sum64[4 * k] - (double)ref.sum64[4 * k])
                                      : fabs((double)a.sum32[4 * k] - (double)ref.sum32[4 * k]);
                d /= 255.0 * (double)a.wsum / (double)o.samples; /* in samples (box) */
                worst = fmax(worst, d);
                diff += d > 0;
            }
            printf("  %s, tiles of %u: %ld of %zu pixels differ from automatic tiles, by at most %.2f samples\n",
                   fl ? "gauss" : "box", sides[i], diff, n, worst);
            CHECK_MSG(worst <= 2 && diff * 100 < 3 * (long)n, "filter %d tiles %u: %ld pixels differ, %.2f samples",
                      fl, sides[i], diff, worst);
            gls_accum_free(&a);
        }
        gls_accum_free(&ref);
    }
    close_edges_close(&e);
}

/* Some rows only (gls_aa_render_fine_rows, a rolling shutter's band):
 * those rows' sums and mixed pixels are the whole render's bit for bit,
 * box and Gaussian, automatic and tiny tiles, bands at the top, inside
 * and at the bottom; a narrow band draws fewer tiles. */
static void test_fine_rows(void)
{
    close_edges e;
    CHECK(close_edges_open(&e) == 0);
    rig *g = &e.g;
    const gls_camera *c = &e.c;
    static const uint32_t band[3][2] = {{0, 5}, {17, 18}, {29, 36}}, sides[2] = {0, 7};
    for (int fl = 0; fl < 2; fl++)
        for (int t = 0; t < 2; t++) {
            gls_aa_opts o = close_edges_opts(fl);
            gls_accum ref;
            gls_aa_fine_stats st;
            CHECK(fine(g, c, &o, sides[t], 0, &ref, &st) == 0);
            for (int i = 0; i < 3; i++) {
                gls_accum a;
                gls_aa_fine_stats st2;
                CHECK(fine_rows(g, c, &o, sides[t], 0, band[i][0], band[i][1], &a, &st2) == 0);
                size_t p0 = (size_t)e.s.w * band[i][0], p1 = (size_t)e.s.w * band[i][1];
                int same = a.wsum == ref.wsum && memcmp(a.mixed + p0, ref.mixed + p0, p1 - p0) == 0 &&
                           (a.weighted ? memcmp(a.sum64 + 4 * p0, ref.sum64 + 4 * p0, 4 * (p1 - p0) * 8)
                                       : memcmp(a.sum32 + 4 * p0, ref.sum32 + 4 * p0, 4 * (p1 - p0) * 4)) == 0;
                CHECK_MSG(same, "filter %d tiles %u rows %u..%u: not the whole render's", fl, sides[t], band[i][0],
                          band[i][1] - 1);
                if (sides[t])
                    CHECK_MSG(st2.tiles_drawn < st.tiles_drawn, "rows %u..%u: %llu tiles drawn, whole %llu",
                              band[i][0], band[i][1] - 1, (unsigned long long)st2.tiles_drawn,
                              (unsigned long long)st.tiles_drawn);
                gls_accum_free(&a);
            }
            gls_accum_free(&ref);
        }
    close_edges_close(&e);
}

/* ---- K passes ---------------------------------------------------------- */

static int cmp_pair(const void *a, const void *b)
{
    const int64_t *x = a, *y = b;
    return x[0] != y[0] ? (x[0] < y[0] ? -1 : 1) : (x[1] < y[1] ? -1 : x[1] > y[1]);
}

/* The K passes' samples are exactly the plan's (as sets of exact
 * positions), also where the pass lattice's generator a mod L shares a
 * factor with L or is 0 (M = 16, a = 4, L = 4), and a scene whose edges
 * keep clear of every sample renders bit for bit the same with K = 1 and
 * K = 4 (16 for the grid). */
static void test_kpass_split(void)
{
    char err[128];
    static const struct {
        gls_aa_pattern pat;
        uint64_t m, max_l, k;
    } sets[] = {{GLS_AA_LATTICE, 256, 64, 4}, {GLS_AA_GRID, 256, 16, 16},   {GLS_AA_LATTICE, 16, 4, 4},
                {GLS_AA_LATTICE, 4096, 64, 64}, {GLS_AA_LATTICE, 1000, 100, 10}, {GLS_AA_LATTICE, 1000, 1, 1000}};
    for (size_t t = 0; t < sizeof sets / sizeof sets[0]; t++) {
        uint64_t m = sets[t].m;
        gls_aa_opts o = gls_aa_defaults();
        o.samples = m;
        o.pattern = sets[t].pat;
        gls_aa_plan p;
        gls_aa_fine f1, fk;
        CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
        CHECK(gls_aa_fine_init(&f1, &p, 65536) == 0 && f1.k == 1);
        CHECK(gls_aa_fine_init(&fk, &p, sets[t].max_l) == 0 && fk.k == sets[t].k);
        int64_t(*all)[2] = malloc(m * sizeof *all), (*un)[2] = malloc(m * sizeof *un), (*c)[2] = malloc(m * sizeof *c);
        int64_t sh[2];
        gls_aa_fine_pass(&f1, 0, sh, all, c);
        for (uint64_t r = 0; r < fk.k; r++)
            gls_aa_fine_pass(&fk, r, sh, un + r * fk.l, c);
        qsort(all, m, sizeof *all, cmp_pair);
        qsort(un, m, sizeof *un, cmp_pair);
        CHECK_MSG(memcmp(all, un, m * sizeof *all) == 0, "M %llu (a = %llu), K = %llu: the passes' samples differ",
                  (unsigned long long)m, (unsigned long long)p.lat.a, (unsigned long long)fk.k);
        free(all), free(un), free(c);
    }
    /* the image: a half-plane at 0.7 rad whose edge keeps clear of all
     * samples by more than the snapping */
    gls_camera cam = tb_front_camera(20, 16);
    gls_aa_opts o = gls_aa_defaults();
    o.samples = 256;
    gls_aa_plan p;
    CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
    double phi = atan2(3, 4), best, dd = clear_edge(&p, 20, 16, phi, cos(phi) * 10 + sin(phi) * 8, &best);
    gls_bundle *b = halfplane(&cam, phi, dd);
    rig g;
    CHECK(rig_open(&g, b) == 0);
    gls_accum a1, a4;
    gls_aa_fine_stats s1, s4;
    CHECK(fine(&g, &cam, &o, 0, 0, &a1, &s1) == 0 && s1.lay.f.k == 1);
    CHECK(fine(&g, &cam, &o, 0, 64, &a4, &s4) == 0 && s4.lay.f.k == 4);
    CHECK_MSG(same_acc(&a1, &a4), "K = 4 differs from K = 1 (clearance %.3g px)", best);
    gls_accum_free(&a1), gls_accum_free(&a4);
    rig_close(&g);
    gls_bundle_free(b);
}

/* ---- one pass against multi-pass ------------------------------------- */

/* The same lattice drawn as one fine framebuffer and as M jittered passes
 * (aa_render.h): equal up to rasteriser rounding of samples within a snap
 * step of an edge (the multi-pass path snaps to 1/256 px, the fine one to
 * 1/256 of a fine pixel).  Measured here on the small-angle squares (the
 * figures are printed; spec/antialiasing.md quotes them): at most 8
 * samples' worth in a pixel, under 2% of the pixels, per-row RMS edge
 * error within 5e-4 px. */
static void test_onepass_vs_multipass(void)
{
    as_scene s;
    as_layout(&s, 96, 72, 2, 2, 24);
    gls_camera c = as_camera(&s, 1, 100);
    gls_bundle *b = as_bundle(&s, &c);
    rig g;
    CHECK(rig_open(&g, b) == 0);
    size_t n = (size_t)s.w * s.h;
    float *f1 = malloc(n * 12), *f2 = malloc(n * 12);
    double *img = malloc(n * sizeof *img);
    static const uint64_t ms[] = {16, 64, 256};
    for (int i = 0; i < 3; i++)
        for (int fl = 0; fl < 2 && !(fl && ms[i] > 16); fl++) {
            gls_aa_opts o = gls_aa_defaults();
            o.samples = ms[i];
            o.filter = fl ? GLS_AA_GAUSS : GLS_AA_BOX;
            gls_accum a, m;
            CHECK(fine(&g, &c, &o, 0, 0, &a, NULL) == 0 && multi(&g, &c, &o, &m) == 0);
            gls_accum_rgbf(&a, f1);
            gls_accum_rgbf(&m, f2);
            double dmax = 0;
            long ndiff = 0;
            for (size_t k = 0; k < n; k++) {
                double d = fabs((double)f1[3 * k] - f2[3 * k]);
                dmax = fmax(dmax, d);
                ndiff += d > 0;
            }
            for (size_t k = 0; k < n; k++)
                img[k] = f1[3 * k];
            as_err e1 = as_edge_error(&s, img, fl, o.sigma);
            for (size_t k = 0; k < n; k++)
                img[k] = f2[3 * k];
            as_err e2 = as_edge_error(&s, img, fl, o.sigma);
            printf("  M %3llu %-5s: one pass vs %llu passes: %ld of %zu pixels differ, by at most %.5f (%.2f samples); "
                   "row rms %.6f vs %.6f px\n",
                   (unsigned long long)o.samples, fl ? "gauss" : "box", (unsigned long long)o.samples, ndiff, n, dmax,
                   dmax * (double)o.samples, e1.row_rms, e2.row_rms);
            CHECK(dmax <= 8.0 / (double)o.samples + 1e-7 && ndiff * 50 < (long)n);
            CHECK(fabs(e1.row_rms - e2.row_rms) <= 5e-4);
            gls_accum_free(&a), gls_accum_free(&m);
        }
    free(f1), free(f2), free(img);
    rig_close(&g);
    gls_bundle_free(b);
}

/* ---- accuracy -------------------------------------------------------- */

/* The default pattern's per-row edge error through the renderer agrees
 * with the error computed from the sample positions alone (the
 * rasteriser adds nothing measurable at M = 256: its snapping is 1/256 of
 * a fine pixel): straight edges at the issue's listed angles, 6 squares
 * each, 640x480, one pass, float.  Within 20% per angle (45 degrees
 * excepted: all rows of one edge share one offset there, so 12 edges
 * sample 12 offsets), and the worst within 20% of the analytic worst.
 * The issue's target at these angles, 1/256 px with 256 samples, is met
 * (a = 30: analytic worst 0.003715 px at 30 degrees, rendered 0.00373):
 * asserted with a 2% margin, below 0.98 / 256 = 0.00383 px (the rendered
 * worst over 16 sub-pixel placements of this scene: 0.00363 to 0.00379
 * px).  Not asserted, because not met with a margin or not met at all:
 * the mirror images 180 - theta (rendered up to 0.00387 px over those
 * placements, at 157.5 degrees), 4096 samples (0.0047 px at 30 degrees,
 * target 1/2048) and the worst over all directions (about 0.27 / sqrt(M)
 * px for any lattice); spec/antialiasing.md "Accuracy". */
static void test_accuracy_matches_analytic(void)
{
    static const double ang[] = {0.5, 1, 3, 10, 22.5, 30, 45, 60, 80};
    static as_scene sc;
    CHECK(as_layout_angles(&sc, 640, 480, ang, 9, 6));
    gls_camera c = as_camera(&sc, 1, 100);
    gls_bundle *b = as_bundle(&sc, &c);
    rig g;
    CHECK(rig_open(&g, b) == 0);
    gls_aa_opts o = gls_aa_defaults();
    o.samples = 256;
    gls_accum a;
    CHECK(fine(&g, &c, &o, 0, 0, &a, NULL) == 0);
    size_t n = 640 * 480;
    float *f = malloc(n * 12);
    double *img = malloc(n * sizeof *img);
    gls_accum_rgbf(&a, f);
    for (size_t k = 0; k < n; k++)
        img[k] = f[3 * k];
    gls_aa_plan p;
    char err[128];
    CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
    double x[256], y[256], scratch[256], wr = 0, wa = 0;
    for (uint64_t k = 0; k < 256; k++) {
        double du, dv;
        uint64_t w;
        gls_aa_sample(&p, k, &du, &dv, &w);
        x[k] = du + 0.5, y[k] = dv + 0.5;
    }
    for (int i = 0; i < 9; i++) {
        double r = as_dir_rms(&sc, img, ang[i], NULL), an = as_pattern_rms(x, y, 256, ang[i], scratch);
        printf("  %4g deg: renderer %.6f px, analytic %.6f px\n", ang[i], r, an);
        if (ang[i] != 45)
            CHECK_MSG(fabs(r - an) <= 0.2 * an, "%g deg: renderer %.6f, analytic %.6f", ang[i], r, an);
        wr = fmax(wr, r), wa = fmax(wa, an);
    }
    CHECK_MSG(wr <= 1.2 * wa, "worst: renderer %.6f, analytic %.6f", wr, wa);
    printf("  worst: renderer %.6f px, analytic %.6f px; target 1/256 = %.6f px, asserted below %.6f px\n", wr, wa,
           1 / 256.0, 0.98 / 256);
    CHECK_MSG(wr <= 0.98 / 256, "256 samples, listed angles: worst %.6f px, not 2%% below 1/256 px", wr);
    free(f), free(img);
    gls_accum_free(&a);
    rig_close(&g);
    gls_bundle_free(b);
}

/* llvmpipe snaps vertices to 1/256 of a framebuffer pixel; in the fine
 * framebuffer that is 1/256 of a fine pixel, so an edge's displacement by
 * snapping shrinks with the fine pixel: at most half a step, 1/512 px for
 * a plain pass and 1/(512 N) px through the grid's fine framebuffer of
 * N x N (bench/aa_scene.h as_snap_worst sweeps an edge across a sample in
 * 1/(4096 N) px steps). */
static void test_snapping_fine(void)
{
    static const uint32_t ns[] = {1, 4, 16};
    for (int i = 0; i < 3; i++) {
        double w = as_snap_worst(ctx, ns[i]);
        printf("  N %2u: largest displacement by snapping %.7f px (bound %.7f)\n", ns[i], w, 1.0 / (512.0 * ns[i]));
        CHECK_MSG(w >= 0 && w <= 1.0 / (512.0 * ns[i]) + 1e-12, "N %u: %g px", ns[i], w);
    }
}

int main(void)
{
    ctx = tb_glctx(GLS_BACKEND_AUTO, "test_aa_lattice");
    RUN(test_lattice_points);
    RUN(test_lattice_criterion);
    RUN(test_issue_rule_at_4096);
    RUN(test_sum_run);
    RUN(test_lattice_centred);
    RUN(test_basis_and_map);
    RUN(test_pass_split_choice);
    RUN(test_gather_constant);
    RUN(test_gather_halfplane);
    RUN(test_tiles_straddle);
    RUN(test_fine_rows);
    RUN(test_kpass_split);
    RUN(test_onepass_vs_multipass);
    RUN(test_accuracy_matches_analytic);
    RUN(test_snapping_fine);
    gls_glctx_destroy(ctx);
    CHECK_EXIT();
}
