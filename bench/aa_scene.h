/* The anti-aliasing test scene and its exact answer, shared by make
 * bench-aa (bench/aa_bench.c) and the unit tests (tests/unit/test_aa.c).
 *
 * Scene: white squares on black, rotated by small angles (no edge is
 * pixel-aligned, several are within a degree of it: the hard case for a
 * grid of samples), centred at sub-pixel positions, in a fronto-parallel
 * plane, so their projections are exactly known squares in the image.
 *
 * Exact answer, computed here in double independently of the renderer:
 *  box filter:      the area of each pixel square covered by the square
 *                   (polygon clipping, shoelace formula);
 *  Gaussian filter: the integral of the truncated, normalised Gaussian
 *                   window (+-3 sigma per axis, as the renderer's) over
 *                   the covered part of the plane, for pixels near one
 *                   edge only (the half-plane of that edge): an outer
 *                   Simpson integral, split at its kinks, of erf.
 *
 * Edge-localisation error: along every pixel row crossing a near-vertical
 * edge (every column crossing a near-horizontal one), away from the
 * corners, the intensities of the pixels within reach of the edge are
 * summed, minus the exact values: moving a straight edge by d pixels
 * changes that sum by exactly d (contrast 1), so the difference is the
 * edge's local displacement in pixels.  Edge error: a straight line is
 * fitted (least squares) to these displacements along each edge, as a
 * sub-pixel line detector would place the edge; the error of the edge is
 * the larger displacement of that line at the two ends of the measured
 * span.  RMS and max over all edges; the unfitted per-row displacements
 * are reported too (row_rms, row_max: local error, pixel by pixel). */
#ifndef GLS_AA_SCENE_H
#define GLS_AA_SCENE_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "player_scene.h"
#include "aa_onepass.h"

#define AS_PI 3.14159265358979323846
#define AS_MAXSQ 512

typedef struct {
    uint32_t w, h;
    int nsq;
    double c[AS_MAXSQ][4][2];   /* projected corners, image pixels */
    double angle[AS_MAXSQ];     /* rotation of each square, degrees */
    double origin[3];           /* world offset of everything (far tests) */
    double depth;               /* Zc of the plane */
} as_scene;

/* nx x ny squares of side `side` px on a w x h image, angles 0.3..9.8
 * degrees, centres off the pixel grid by irrational-ish fractions. */
static inline void as_layout(as_scene *s, uint32_t w, uint32_t h, int nx, int ny, double side)
{
    memset(s, 0, sizeof *s);
    s->w = w, s->h = h;
    s->depth = 10;
    int k = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx && k < AS_MAXSQ; i++, k++) {
            double a = (0.3 + 9.5 * k / (nx * ny > 1 ? nx * ny - 1 : 1)) * AS_PI / 180;
            double cx = w * (i + 0.5) / nx + fmod(0.137 * (k + 1) * 7.31, 1.0);
            double cy = h * (j + 0.5) / ny + fmod(0.291 * (k + 1) * 3.17, 1.0);
            for (int q = 0; q < 4; q++) {
                double x = (q == 1 || q == 2) ? side / 2 : -side / 2, y = q >= 2 ? side / 2 : -side / 2;
                s->c[k][q][0] = cx + cos(a) * x - sin(a) * y;
                s->c[k][q][1] = cy + sin(a) * x + cos(a) * y;
            }
            s->angle[k] = a * 180 / AS_PI;
        }
    s->nsq = k;
}

/* Squares rotated by the given angles (degrees), reps of each at
 * different sub-pixel positions (fractions spread by the golden ratio, so
 * that edges whose rows all see one offset, like 45 degrees, are measured
 * at several), in a grid of cells filling w x h.  A square at angle a has
 * edges in the directions a and a + 90.  Returns 0 if they do not fit. */
static inline int as_layout_angles(as_scene *s, uint32_t w, uint32_t h, const double *ang, int nang, int reps)
{
    memset(s, 0, sizeof *s);
    s->w = w, s->h = h;
    s->depth = 10;
    int n = nang * reps;
    if (n > AS_MAXSQ)
        return 0;
    int nx = (int)ceil(sqrt((double)n * w / h)), ny = (n + nx - 1) / nx;
    /* corners stay 4 px inside the cell whatever the angle, so that no
     * row measured near one square reaches into the next */
    double cw = (double)w / nx, ch = (double)h / ny, side = (fmin(cw, ch) - 8) / 1.415;
    for (int k = 0; k < n; k++) {
        int i = k % nx, j = k / nx;
        double a = ang[k % nang] * AS_PI / 180;
        double g = 0.6180339887498949 * (k + 1);
        double cx = cw * (i + 0.5) + (g - floor(g)) - 0.5, cy = ch * (j + 0.5) + fmod(0.7548776662 * (k + 1), 1.0) - 0.5;
        for (int q = 0; q < 4; q++) {
            double x = (q == 1 || q == 2) ? side / 2 : -side / 2, y = q >= 2 ? side / 2 : -side / 2;
            s->c[k][q][0] = cx + cos(a) * x - sin(a) * y;
            s->c[k][q][1] = cy + sin(a) * x + cos(a) * y;
        }
        s->angle[k] = ang[k % nang];
    }
    s->nsq = n;
    return 1;
}

/* Direction of edge q of square k in degrees, in [0, 180). */
static inline double as_edge_dir(const as_scene *s, int k, int q)
{
    double d = fmod(s->angle[k] + 90.0 * q, 180.0);
    return d < 0 ? d + 180 : d;
}

/* Camera: identity rotation at `origin` looking along +Z (world = camera
 * frame shifted by origin), f = 500 px, principal point centred. */
static inline gls_camera as_camera(const as_scene *s, double near, double far)
{
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double T[3] = {-s->origin[0], -s->origin[1], -s->origin[2]};
    return tb_camera(s->w, s->h, 500, 500, (s->w - 1) / 2.0, (s->h - 1) / 2.0, 0, R, T, near, far);
}

/* The bundle: each projected square lifted back onto the plane Zc =
 * depth through the camera (the exact inverse of the projection). */
static inline gls_bundle *as_bundle(const as_scene *s, const gls_camera *c)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "squares", 1);
    tb_color(&t, 1, 1, 1, 1);
    for (int k = 0; k < s->nsq; k++) {
        double q[4][3];
        for (int i = 0; i < 4; i++) {
            double Z = s->depth;
            q[i][0] = (s->c[k][i][0] - c->cx) * Z / c->fx + s->origin[0];
            q[i][1] = (s->c[k][i][1] - c->cy) * Z / c->fy + s->origin[1];
            q[i][2] = Z + s->origin[2];
        }
        tb_poly(&t, 4, (const double(*)[3])q);
    }
    return tb_finish(&t);
}

/* ---- exact coverage ------------------------------------------------- */

/* Clip convex polygon p (n corners) to the half-plane sgn * (coord[axis]
 * - lim) <= 0; returns the new corner count. */
static inline int as_clip(double (*p)[2], int n, int axis, double lim, double sgn, double (*out)[2])
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *a = p[i], *b = p[(i + 1) % n];
        double da = sgn * (a[axis] - lim), db = sgn * (b[axis] - lim);
        if (da <= 0)
            out[m][0] = a[0], out[m][1] = a[1], m++;
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
            double t = da / (da - db);
            out[m][0] = a[0] + t * (b[0] - a[0]);
            out[m][1] = a[1] + t * (b[1] - a[1]);
            m++;
        }
    }
    return m;
}

/* Area of square k inside the pixel square centred at (u, v). */
static inline double as_box_cover(const as_scene *s, int k, double u, double v)
{
    double a[12][2], b[12][2];
    int n = 4;
    memcpy(a, s->c[k], sizeof s->c[k]);
    n = as_clip(a, n, 0, u - 0.5, -1, b);
    n = as_clip(b, n, 0, u + 0.5, 1, a);
    n = as_clip(a, n, 1, v - 0.5, -1, b);
    n = as_clip(b, n, 1, v + 0.5, 1, a);
    double area = 0;
    for (int i = 0; i < n; i++)
        area += a[i][0] * a[(i + 1) % n][1] - a[(i + 1) % n][0] * a[i][1];
    return fabs(area) / 2;
}

/* Truncated Gaussian: G(x) = integral of exp(-t^2 / 2 s^2) from -A to x,
 * clamped to [-A, A]. */
static inline double as_gcdf(double x, double s, double A)
{
    if (x < -A)
        x = -A;
    if (x > A)
        x = A;
    return s * sqrt(AS_PI / 2) * (erf(x / (s * sqrt(2))) + erf(A / (s * sqrt(2))));
}

/* Gaussian-filtered coverage at pixel (u, v) of the half-plane
 * n . p <= d (n unit), window +-A = +-3 sigma per axis. */
static inline double as_gauss_halfplane(double nx, double ny, double d, double u, double v, double s)
{
    double A = 3 * s;
    if (fabs(ny) > fabs(nx)) { /* integrate the inner integral over the larger component */
        double t = nx;
        nx = ny, ny = t;
        t = u;
        u = v, v = t;
    }
    /* inside iff nx x <= r(y) = d - nx u - ny (v + y) */
    double br[4] = {-A, A, 0, 0};
    int nb = 2;
    if (ny != 0)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double y = (d - nx * (u + sgn * A)) / ny - v; /* kink: r(y) / nx = sgn A */
            if (y > -A && y < A)
                br[nb++] = y;
        }
    for (int i = 0; i < nb; i++) /* sort the few breakpoints */
        for (int j = i + 1; j < nb; j++)
            if (br[j] < br[i]) {
                double t = br[i];
                br[i] = br[j], br[j] = t;
            }
    double total = 0;
    for (int p = 0; p + 1 < nb; p++) {
        double a = br[p], b = br[p + 1], h = (b - a) / 64, acc = 0;
        for (int i = 0; i <= 64; i++) {
            double y = a + h * i;
            double r = d - nx * u - ny * (v + y), x = r / nx;
            double inner = nx > 0 ? as_gcdf(x, s, A) : as_gcdf(A, s, A) - as_gcdf(x, s, A);
            double f = exp(-y * y / (2 * s * s)) * inner;
            acc += f * (i == 0 || i == 64 ? 1 : i % 2 ? 4 : 2);
        }
        total += acc * h / 3;
    }
    double Z = as_gcdf(A, s, A);
    return total / (Z * Z);
}

typedef struct {
    double rms, max;            /* per edge: the least-squares line through the
                                   rows' displacements, at its ends (max) */
    double row_rms, row_max;    /* per row (local, unfitted) */
    long rows, edges;
} as_err;

/* The per-row (per-column for near-horizontal edges) displacements of
 * edge q of square k in image img, away from the corners, into dev
 * (room for as many rows as the image has); returns their count.  *ends
 * gets the first and last row index (for the fitted line). */
static inline long as_edge_rows(const as_scene *s, const double *img, int gauss, double sig, int k, int q,
                                double *dev, long *t0out)
{
    double reach = gauss ? 3 * sig + 1.5 : 1.5; /* pixels an edge affects, each side */
    double mx = 0, my = 0;
    for (int i = 0; i < 4; i++)
        mx += s->c[k][i][0] / 4, my += s->c[k][i][1] / 4;
    const double *a = s->c[k][q], *b = s->c[k][(q + 1) % 4];
    double ex = b[0] - a[0], ey = b[1] - a[1], len = hypot(ex, ey);
    double nx = ey / len, ny = -ex / len;
    double d = nx * a[0] + ny * a[1];
    if (nx * mx + ny * my > d) /* make n point outward: inside is n.p <= d */
        nx = -nx, ny = -ny, d = -d;
    int vertical = fabs(ex) < fabs(ey); /* walk rows, else columns */
    double lo = vertical ? fmin(a[1], b[1]) : fmin(a[0], b[0]);
    double hi = vertical ? fmax(a[1], b[1]) : fmax(a[0], b[0]);
    double margin = reach + 2; /* keep the corners' influence out */
    long m = 0, t0 = (long)ceil(lo + margin), t1 = (long)floor(hi - margin);
    if (t0out)
        *t0out = t0;
    for (long t = t0; t <= t1; t++) {
        /* position of the edge on this row (column) */
        double pos = vertical ? (d - ny * t) / nx : (d - nx * t) / ny;
        long p0 = (long)floor(pos - reach - 1), p1 = (long)ceil(pos + reach + 1);
        double dv = 0;
        for (long p = p0; p <= p1; p++) {
            long u = vertical ? p : t, v = vertical ? t : p;
            if (u < 0 || v < 0 || u >= (long)s->w || v >= (long)s->h)
                continue;
            double ref = gauss ? as_gauss_halfplane(nx, ny, d, (double)u, (double)v, sig)
                               : as_box_cover(s, k, (double)u, (double)v);
            dv += img[(size_t)v * s->w + (size_t)u] - ref;
        }
        dev[m++] = dv;
    }
    return m;
}

/* Edge error of image img (intensity in [0, 1], w x h, row 0 = top) for
 * filter gauss (0: box) with sigma s. */
static inline as_err as_edge_error(const as_scene *s, const double *img, int gauss, double sig)
{
    as_err e = {0, 0, 0, 0, 0, 0};
    double sum2 = 0, esum2 = 0;
    double *dev = malloc(sizeof *dev * (s->w > s->h ? s->w : s->h) + sizeof *dev);
    for (int k = 0; k < s->nsq && dev; k++)
        for (int q = 0; q < 4; q++) {
            long t0, m = as_edge_rows(s, img, gauss, sig, k, q, dev, &t0);
            double st = 0, sd = 0, stt = 0, std_ = 0;
            for (long i = 0; i < m; i++) {
                double x = (double)i;
                sum2 += dev[i] * dev[i];
                if (fabs(dev[i]) > e.row_max)
                    e.row_max = fabs(dev[i]);
                e.rows++;
                st += x, sd += dev[i], stt += x * x, std_ += x * dev[i];
            }
            if (m < 2)
                continue;
            /* the edge as a line detector would place it: fit d = a + b x
             * and take the larger displacement of the two ends */
            double den = m * stt - st * st, sl = den > 0 ? (m * std_ - st * sd) / den : 0;
            double a0 = (sd - sl * st) / m, a1 = a0 + sl * (double)(m - 1);
            double ed = fmax(fabs(a0), fabs(a1));
            esum2 += ed * ed;
            if (ed > e.max)
                e.max = ed;
            e.edges++;
        }
    free(dev);
    e.row_rms = e.rows ? sqrt(sum2 / (double)e.rows) : 0;
    e.rms = e.edges ? sqrt(esum2 / (double)e.edges) : 0;
    return e;
}

/* Per-row RMS edge error of the edges in direction dir (degrees, to
 * 1e-6): all rows of all such edges; *rows gets their number. */
static inline double as_dir_rms(const as_scene *s, const double *img, double dir, long *rows)
{
    double sum2 = 0;
    long n = 0;
    double *dev = malloc(sizeof *dev * (s->w > s->h ? s->w : s->h) + sizeof *dev);
    for (int k = 0; k < s->nsq && dev; k++)
        for (int q = 0; q < 4; q++) {
            double dd = fabs(as_edge_dir(s, k, q) - dir);
            if (fmin(dd, 180 - dd) > 1e-6)
                continue;
            long m = as_edge_rows(s, img, 0, 0, k, q, dev, NULL);
            for (long i = 0; i < m; i++)
                sum2 += dev[i] * dev[i];
            n += m;
        }
    free(dev);
    if (rows)
        *rows = n;
    return n ? sqrt(sum2 / (double)n) : 0;
}

/* ---- llvmpipe's vertex snapping through the fine framebuffer ---------- */

/* A vertical edge swept across the sample column at x0 = 1 - 1/2 + (i +
 * 1/2) / N of pixel 1 in steps of 1/(4096 N) px: the counted samples
 * change where the rasteriser puts the edge.  The largest distance
 * between that and the exact crossing, for the plain pass (N = 1) and
 * the grid's fine framebuffer (fine pixels 1/N px). */
static inline double as_snap_worst(gls_glctx *ctx, uint32_t N)
{
    char err[256];
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, T[3] = {0, 0, 0}, worst = 0;
    gls_camera c = tb_camera(4, 2, 100, 100, 1.5, 0.5, 0, R, T, 0.5, 100);
    gls_aa_plan p;
    gls_aa_opts o = gls_aa_defaults();
    o.samples = (uint64_t)N * N;
    o.pattern = GLS_AA_GRID;
    if (N > 1 && gls_aa_plan_init(&p, &o, err, sizeof err))
        return -1;
    double xs = 0.5 + (N / 2 + 0.5) / N; /* a sample column of pixel 1 */
    for (int k = -40; k <= 40; k++) {
        double x = xs + k / (4096.0 * N);
        tb t;
        tb_init(&t);
        tb_object(&t, "e", 1);
        tb_color(&t, 1, 1, 1, 1);
        tb_rect_z(&t, -1, -1, (x - c.cx) * 5 / c.fx, 1, 5);
        gls_bundle *b = tb_finish(&t);
        gls_scene sc;
        gls_renderer *r = NULL;
        if (gls_scene_flatten(b, &sc, err, sizeof err) || !(r = gls_renderer_create(ctx, b, &sc, err, sizeof err)) ||
            gls_renderer_set_size(r, 4, 2, err, sizeof err))
            return -1;
        long got, want = 0;
        if (N == 1) {
            uint8_t rgba[4 * 2 * 4];
            gls_render_pass(r, &c, 0, 0);
            gls_render_read_rgba(r, rgba);
            got = rgba[4] == 255;
            want = 1 < x;
        } else {
            gls_accum a;
            if (gls_accum_init(&a, 4, 2, 0, 0) || gls_aa_render_fine(r, &c, &p, NULL, &a, NULL, err, sizeof err))
                return -1;
            got = a.sum32[4] / 255;
            for (uint32_t i = 0; i < N; i++)
                want += (0.5 + (i + 0.5) / N < x) * (long)N;
            gls_accum_free(&a);
        }
        if (got != want && fabs(x - xs) > worst)
            worst = fabs(x - xs);
        gls_renderer_destroy(r);
        gls_scene_free(&sc);
        gls_bundle_free(b);
    }
    return worst;
}

/* ---- the analytic per-row error of a sample pattern ------------------ */

static int as_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* RMS over uniformly random edge offsets of the per-row coverage error of
 * a straight edge in direction dir (degrees) for the box filter over the
 * m sample points (x, y) in [0, 1)^2 of a pixel (the pattern repeats from
 * pixel to pixel).  A row of pixels crossed by a steep edge x = c + y cot
 * (dir) counts, per pixel u, the samples with u + x_i - y_i cot < c: with
 * p_i = x_i - y_i cot = P_i + f_i (P_i integer, f_i in [0, 1)) the row's
 * count less the covered area is
 *     E(c) = #{f_i < c} / m - c - (mean P_i + cot / 2),   c in [0, 1),
 * whose mean over c is (1/2 - mean x) - cot (1/2 - mean y): zero for a
 * pattern centred on the pixel.  Its mean square is integrated exactly
 * between the sorted f_i.  Flat edges: the same per column, x and y
 * swapped.  p: room for m doubles. */
static inline double as_pattern_rms(const double *x, const double *y, long m, double dir, double *p)
{
    double t = dir * AS_PI / 180;
    int steep = fabs(sin(t)) >= fabs(cos(t));
    double sl = steep ? cos(t) / sin(t) : sin(t) / cos(t), P = 0;
    for (long i = 0; i < m; i++) {
        double v = steep ? x[i] - sl * y[i] : y[i] - sl * x[i], fl = floor(v);
        P += fl;
        p[i] = v - fl;
    }
    double K = P / (double)m + sl / 2;
    qsort(p, (size_t)m, sizeof *p, as_cmp_double);
    /* E(c) = k/m - K - c on [p_k-1, p_k) (p_-1 = 0, p_m = 1) */
    double sum = 0, prev = 0;
    for (long k = 0; k <= m; k++) {
        double a = prev, b = k < m ? p[k] : 1, f = (double)k / (double)m - K;
        sum += ((f - a) * (f - a) * (f - a) - (f - b) * (f - b) * (f - b)) / 3;
        prev = b;
    }
    return sqrt(sum > 0 ? sum : 0);
}

#endif
