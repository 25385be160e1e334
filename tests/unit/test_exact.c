/* Exact coverage (runtime/aa/exact.h, spec/antialiasing.md "Exact
 * coverage"): the engine's per-pixel areas against independent
 * computations.  The references here share no code with the engine: a
 * triangle's area in a pixel square by integrating its vertical extent
 * over x (piecewise linear between known breakpoints, so the midpoint rule
 * is exact), and a half-plane's area in a square in closed form.  Long on
 * purpose: a list of independent tests over one small rig. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "exact.h"
#include "halfplane_area.h"
#include "lattice.h"

/* ---- rig ------------------------------------------------------------- */

typedef struct {
    int w, h;
    double *cover;      /* per pixel: sum of areas                         */
    double *by_id;      /* per pixel and id 0..3: area                     */
    size_t most;        /* most fragments in one pixel                     */
} cov;

static void cov_pixel(void *user, int px, int py, const gls_exact_frag *f, size_t n)
{
    cov *c = user;
    size_t p = (size_t)py * c->w + px;
    (void)f;
    for (size_t k = 0; k < n; k++) {
        c->cover[p] += f[k].area;
        c->by_id[p * 4 + (f[k].tri & 3)] += f[k].area;
    }
    if (n > c->most)
        c->most = n;
}

static cov run(const gls_exact_tri *t, size_t n, int w, int h)
{
    cov c = {w, h, calloc((size_t)w * h, sizeof(double)), calloc((size_t)w * h * 4, sizeof(double)), 0};
    CHECK(gls_exact_visit(t, n, w, h, cov_pixel, &c) == 0);
    return c;
}

static void cov_free(cov *c) { free(c->cover), free(c->by_id); }

static gls_exact_tri tri(double x0, double y0, double x1, double y1, double x2, double y2, double iz)
{
    return (gls_exact_tri){{x0, x1, x2}, {y0, y1, y2}, {iz, iz, iz}, 0, {1, 1, 1, 1}, 0};
}

static uint64_t rng = 88172645463325252ull;
static double urand(void) /* [0, 1) */
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* ---- independent references ------------------------------------------ */

/* The vertical extent of triangle (x[3], y[3]) at abscissa u: [lo, hi] */
static int tri_span(const double *x, const double *y, double u, double *lo, double *hi)
{
    int n = 0;
    *lo = INFINITY, *hi = -INFINITY;
    for (int k = 0; k < 3; k++) {
        double ax = x[k], ay = y[k], bx = x[(k + 1) % 3], by = y[(k + 1) % 3];
        if ((u < ax && u < bx) || (u > ax && u > bx) || ax == bx)
            continue;
        double yy = ay + (by - ay) * (u - ax) / (bx - ax);
        *lo = fmin(*lo, yy), *hi = fmax(*hi, yy), n++;
    }
    return n > 0;
}

static int dcmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Area of the triangle in the square [i-.5, i+.5] x [j-.5, j+.5]:
 * integral over x of the clamped vertical extent.  It is linear between
 * the breakpoints (vertices, square sides, edges meeting y = j +- .5), so
 * the midpoint of each interval integrates it exactly. */
static double ref_tri_area(const double *x, const double *y, int i, int j)
{
    double bp[32];
    int nb = 0;
    bp[nb++] = i - 0.5, bp[nb++] = i + 0.5;
    for (int k = 0; k < 3; k++) {
        bp[nb++] = x[k];
        double ax = x[k], ay = y[k], bx = x[(k + 1) % 3], by = y[(k + 1) % 3];
        for (int s = -1; s <= 1; s += 2) {
            double yl = j + 0.5 * s;
            if (ay != by && (yl - ay) * (yl - by) <= 0)
                bp[nb++] = ax + (bx - ax) * (yl - ay) / (by - ay);
        }
    }
    qsort(bp, nb, sizeof *bp, dcmp);
    double a = 0;
    for (int k = 0; k + 1 < nb; k++) {
        double u0 = fmax(bp[k], i - 0.5), u1 = fmin(bp[k + 1], i + 0.5), lo, hi;
        if (u1 <= u0)
            continue;
        if (tri_span(x, y, 0.5 * (u0 + u1), &lo, &hi)) {
            double l = fmin(hi, j + 0.5) - fmax(lo, j - 0.5);
            if (l > 0)
                a += l * (u1 - u0);
        }
    }
    return a;
}

/* Area and centroid of the triangle's part of the square [i-.5, i+.5] x
 * [j-.5, j+.5]: the triangle cut by the square's four sides in turn
 * (Sutherland-Hodgman), then the shoelace formula. */
static double ref_tri_centroid(const double *x, const double *y, int i, int j, double *cx, double *cy)
{
    double px[16], py[16], qx[16], qy[16];
    int n = 3;
    for (int k = 0; k < 3; k++)
        px[k] = x[k], py[k] = y[k];
    for (int side = 0; side < 4 && n; side++) {
        /* kept where d >= 0 */
        int m = 0;
        for (int k = 0; k < n; k++) {
            int l = (k + 1) % n;
            double dk = side == 0 ? px[k] - (i - 0.5) : side == 1 ? (i + 0.5) - px[k]
                      : side == 2 ? py[k] - (j - 0.5) : (j + 0.5) - py[k];
            double dl = side == 0 ? px[l] - (i - 0.5) : side == 1 ? (i + 0.5) - px[l]
                      : side == 2 ? py[l] - (j - 0.5) : (j + 0.5) - py[l];
            if (dk >= 0)
                qx[m] = px[k], qy[m] = py[k], m++;
            if ((dk >= 0) != (dl >= 0)) {
                double t = dk / (dk - dl);
                qx[m] = px[k] + t * (px[l] - px[k]), qy[m] = py[k] + t * (py[l] - py[k]), m++;
            }
        }
        n = m;
        memcpy(px, qx, sizeof px), memcpy(py, qy, sizeof py);
    }
    double a = 0, mx = 0, my = 0;
    for (int k = 0; k < n; k++) {
        int l = (k + 1) % n;
        double c = px[k] * py[l] - px[l] * py[k];
        a += c, mx += (px[k] + px[l]) * c, my += (py[k] + py[l]) * c;
    }
    *cx = a != 0 ? mx / (3 * a) : i, *cy = a != 0 ? my / (3 * a) : j;
    return fabs(a) / 2;
}

/* the closed-form area of a half-plane in the pixel square */
#define ref_halfplane gls_halfplane_area

/* ---- tests ------------------------------------------------------------ */

/* Random triangles: every pixel's area against the integrating reference,
 * and the sum against the triangle's area. */
static void test_exact_area_vs_reference(void)
{
    double worst = 0;
    for (int r = 0; r < 200; r++) {
        gls_exact_tri t = tri(urand() * 12 - 2, urand() * 12 - 2, urand() * 12 - 2, urand() * 12 - 2,
                              urand() * 12 - 2, urand() * 12 - 2, 1);
        cov c = run(&t, 1, 8, 8);
        for (int j = 0; j < 8; j++)
            for (int i = 0; i < 8; i++) {
                double e = fabs(c.cover[j * 8 + i] - ref_tri_area(t.x, t.y, i, j));
                worst = fmax(worst, e);
            }
        cov_free(&c);
    }
    printf("  random triangles: worst per-pixel difference %.3g\n", worst);
    CHECK_MSG(worst <= 1e-12, "worst %g", worst);
}

/* A half-plane (a triangle whose other edges lie far outside) at every
 * direction over [0, 180) in 0.05-degree steps, each at a random sub-pixel
 * offset: every pixel against the closed form.  Also the per-row edge
 * error (the row's sum minus the exact sum). */
static void test_exact_halfplane_sweep(void)
{
    double worst = 0, worst_row = 0, worst_deg = 0;
    const int W = 6;
    for (int k = 0; k < 3600; k++) {
        double th = k * 0.05 * M_PI / 180, nx = cos(th), ny = sin(th);
        double px = 2.5 + urand(), py = 2.5 + urand(), L = 1e3;
        /* inside: n . (x - p) > 0; counter-clockwise order is irrelevant */
        gls_exact_tri t = tri(px - L * ny, py + L * nx, px + L * ny, py - L * nx, px + L * nx, py + L * ny, 1);
        cov c = run(&t, 1, W, W);
        for (int j = 0; j < W; j++) {
            double row = 0;
            for (int i = 0; i < W; i++) {
                double ref = ref_halfplane(nx, ny, nx * (i - px) + ny * (j - py));
                double e = fabs(c.cover[j * W + i] - ref);
                row += c.cover[j * W + i] - ref;
                if (e > worst)
                    worst = e, worst_deg = k * 0.05;
            }
            worst_row = fmax(worst_row, fabs(row));
        }
        cov_free(&c);
    }
    printf("  half-plane sweep: worst per-pixel error %.3g (at %.2f deg), worst per-row %.3g px\n", worst, worst_deg,
           worst_row);
    CHECK_MSG(worst <= 1e-9, "worst %g at %g deg", worst, worst_deg);
    CHECK_MSG(worst_row <= 1e-9, "worst row %g", worst_row);
}

/* 1000 triangles around a point: every pixel inside the fan's polygon
 * covered exactly once, flat (coplanar neighbours) and as a cone (every
 * neighbour at another slope). */
static void fan(int cone)
{
    const int N = 1000, W = 48;
    double cx = 24.3, cy = 23.7, R = 20;
    gls_exact_tri *t = malloc(N * sizeof *t);
    for (int k = 0; k < N; k++) {
        double a0 = 2 * M_PI * k / N, a1 = 2 * M_PI * (k + 1) / N;
        t[k] = tri(cx, cy, cx + R * cos(a0), cy + R * sin(a0), cx + R * cos(a1), cy + R * sin(a1), 0.5);
        if (cone)
            t[k].iz[0] = 1;
        t[k].id = (uint32_t)k;
    }
    cov c = run(t, N, W, W);
    double worst = 0, rin = R * cos(M_PI / N) - 1e-9;
    int interior = 0;
    for (int j = 0; j < W; j++)
        for (int i = 0; i < W; i++) {
            double dx = fabs(i - cx) + 0.5, dy = fabs(j - cy) + 0.5;
            if (dx * dx + dy * dy >= rin * rin)
                continue;
            interior++;
            worst = fmax(worst, fabs(c.cover[j * W + i] - 1));
        }
    printf("  fan (%s): %d interior pixels, worst |sum - 1| %.3g, most triangles in a pixel %zu\n",
           cone ? "cone" : "flat", interior, worst, c.most);
    CHECK(interior > 1000);
    CHECK_MSG(worst <= 1e-12, "worst %g", worst);
    cov_free(&c), free(t);
}
static void test_exact_fan(void) { fan(0), fan(1); }

/* A T-junction: one triangle's edge meets two triangles' shared vertex at
 * its midpoint: no crack, no double count. */
static void test_exact_t_junction(void)
{
    double x0 = 1.37, y0 = 1.61, x1 = 14.81, y1 = 12.29;
    double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
    gls_exact_tri t[3] = {tri(x0, y0, x1, y0, x0, y1, 0.5), tri(x1, y0, x1, y1, mx, my, 0.5),
                          tri(x1, y1, x0, y1, mx, my, 0.5)};
    cov c = run(t, 3, 16, 16);
    double worst = 0;
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++)
            if (i - 0.5 >= x0 && i + 0.5 <= x1 && j - 0.5 >= y0 && j + 0.5 <= y1)
                worst = fmax(worst, fabs(c.cover[j * 16 + i] - 1));
    CHECK_MSG(worst <= 1e-12, "worst %g", worst);
    cov_free(&c);
}

/* Slivers far thinner than a pixel (1e-6 and 1e-12 px) across 20
 * pixels: per pixel against the reference, and the total against the
 * sliver's area, both absolute: areas are summed in pixel-local
 * coordinates, where a pixel's rounding is about 1e-16 of its area
 * whatever the sliver's width. */
static void test_exact_sliver(void)
{
    static const double widths[] = {1e-6, 1e-12};
    for (int k = 0; k < 2; k++) {
        double d = widths[k];
        gls_exact_tri t = tri(0.3, 0.7, 19.1, 7.9, 19.1, 7.9 + d, 1);
        /* a vertical side of height y2 - y1 (exact in double) at x 19.1 */
        double area = 0.5 * (t.y[2] - t.y[1]) * (t.x[1] - t.x[0]);
        cov c = run(&t, 1, 20, 10);
        double sum = 0, worst = 0;
        for (int j = 0; j < 10; j++)
            for (int i = 0; i < 20; i++) {
                sum += c.cover[j * 20 + i];
                worst = fmax(worst, fabs(c.cover[j * 20 + i] - ref_tri_area(t.x, t.y, i, j)));
            }
        printf("  sliver %g px: total %.6g (exact %.6g), worst per-pixel %.3g\n", d, sum, area, worst);
        CHECK_MSG(fabs(sum - area) <= 1e-14, "sum %.17g area %.17g", sum, area);
        CHECK_MSG(worst <= 1e-13, "worst %g", worst);
        cov_free(&c);
    }
}

/* Two quads (two triangles each) passing through each other: each pixel's
 * share of the first is the half-plane where its 1/Zc is larger, exactly;
 * coverage sums to 1. */
static void test_exact_interpenetrating(void)
{
    const int W = 12;
    double worst = 0, worst_sum = 0;
    for (int r = 0; r < 50; r++) {
        /* planes iz = c + a x + b y; their difference's zero line is oblique */
        double a1 = 0.01 * (urand() - 0.5), b1 = 0.01 * (urand() - 0.5), c1 = 0.5;
        double a2 = 0.01 * (urand() - 0.5), b2 = 0.01 * (urand() - 0.5);
        double xs = 3 + 6 * urand(), ys = 3 + 6 * urand();
        double c2 = c1 + (a1 - a2) * xs + (b1 - b2) * ys; /* equal at (xs, ys) */
        double X[4] = {-3, W + 3, W + 3, -3}, Y[4] = {-3, -3, W + 3, W + 3};
        gls_exact_tri t[4];
        for (int q = 0; q < 2; q++) {
            double a = q ? a2 : a1, b = q ? b2 : b1, c = q ? c2 : c1;
            int o[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int h = 0; h < 2; h++) {
                gls_exact_tri *u = &t[2 * q + h];
                *u = tri(X[o[h][0]], Y[o[h][0]], X[o[h][1]], Y[o[h][1]], X[o[h][2]], Y[o[h][2]], 0);
                for (int v = 0; v < 3; v++)
                    u->iz[v] = c + a * u->x[v] + b * u->y[v];
            }
        }
        cov c = run(t, 4, W, W);
        for (int j = 0; j < W; j++)
            for (int i = 0; i < W; i++) {
                size_t p = (size_t)j * W + i;
                double first = c.by_id[p * 4 + 0] + c.by_id[p * 4 + 1];
                double ref = ref_halfplane(a1 - a2, b1 - b2, (a1 - a2) * i + (b1 - b2) * j + c1 - c2);
                worst = fmax(worst, fabs(first - ref));
                worst_sum = fmax(worst_sum, fabs(c.cover[p] - 1));
            }
        cov_free(&c);
    }
    printf("  interpenetrating quads: worst per-pixel %.3g, worst |sum - 1| %.3g\n", worst, worst_sum);
    CHECK_MSG(worst <= 1e-9, "worst %g", worst);
    CHECK_MSG(worst_sum <= 1e-12, "worst sum %g", worst_sum);
}

static const gls_exact_pinhole cam0 = {{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}, 8, 8, 7.5, 7.5, 0, 1, 0};

/* A triangle crossing the near plane, clipped in 3-D: one vertex in front
 * (the cut leaves a triangle, here with dyadic cut points) gives the image
 * of the hand-cut triangle; two in front (a quad) give its projected area,
 * counted once over the two halves. */
static void test_exact_near_plane(void)
{
    gls_exact_tri proto = tri(0, 0, 0, 0, 0, 0, 0), out[3], cut[3];
    double p[3][3] = {{-1, 0.5, -1}, {1, 0.5, -1}, {0, 0.5, 3}};
    double q[3][3] = {{-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0, 0.5, 3}};
    CHECK(gls_exact_project(&cam0, p, &proto, out) == 1);
    CHECK(gls_exact_project(&cam0, q, &proto, cut) == 1);
    cov a = run(out, 1, 16, 16), b = run(cut, 1, 16, 16);
    double worst = 0, sum = 0;
    for (int k = 0; k < 256; k++)
        worst = fmax(worst, fabs(a.cover[k] - b.cover[k])), sum += a.cover[k];
    CHECK_MSG(worst <= 1e-12, "worst %g", worst);
    CHECK(sum > 1);
    cov_free(&a), cov_free(&b);
    /* two vertices in front: (0, 0.5, 1) cut points at Z = 1 from (.., -1) */
    double r[3][3] = {{-1, 0.5, 3}, {1, 0.5, 3}, {0, 0.5, -1}};
    CHECK(gls_exact_project(&cam0, r, &proto, out) == 2);
    /* the cut quad: (-1,.5,3) (1,.5,3) and the points at Z = 1 on the edges
     * to (0,.5,-1): s = 1/2, (.5,.5,1) and (-.5,.5,1) */
    double Q[4][3] = {{-1, 0.5, 3}, {1, 0.5, 3}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}}, u[4], v[4], area = 0;
    for (int k = 0; k < 4; k++)
        u[k] = 8 * Q[k][0] / Q[k][2] + 7.5, v[k] = 8 * Q[k][1] / Q[k][2] + 7.5;
    for (int k = 0; k < 4; k++)
        area += 0.5 * (u[k] * v[(k + 1) % 4] - u[(k + 1) % 4] * v[k]);
    cov c = run(out, 2, 16, 16);
    sum = 0;
    double most = 0;
    for (int k = 0; k < 256; k++)
        sum += c.cover[k], most = fmax(most, c.cover[k]);
    CHECK_MSG(fabs(sum - fabs(area)) <= 1e-12, "sum %.17g area %.17g", sum, fabs(area));
    CHECK(most <= 1 + 1e-12);
    cov_free(&c);
}

/* The far plane, as GL clips: a triangle from Zc 1 to 3 with far 2 keeps
 * the quad in front of Zc = 2 (dyadic cut points), its projected area
 * counted once over the pieces. */
static void test_exact_far_plane(void)
{
    gls_exact_pinhole cam = cam0;
    cam.znear = 0.5, cam.zfar = 2;
    gls_exact_tri proto = tri(0, 0, 0, 0, 0, 0, 0), out[3];
    double p[3][3] = {{-1, 0.5, 1}, {1, 0.5, 1}, {0, 0.5, 3}};
    int m = gls_exact_project(&cam, p, &proto, out);
    CHECK(m == 2);
    double Q[4][3] = {{-1, 0.5, 1}, {1, 0.5, 1}, {0.5, 0.5, 2}, {-0.5, 0.5, 2}}, u[4], v[4], area = 0;
    for (int k = 0; k < 4; k++)
        u[k] = 8 * Q[k][0] / Q[k][2] + 7.5, v[k] = 8 * Q[k][1] / Q[k][2] + 7.5;
    for (int k = 0; k < 4; k++)
        area += 0.5 * (u[k] * v[(k + 1) % 4] - u[(k + 1) % 4] * v[k]);
    cov c = run(out, (size_t)m, 16, 16);
    double sum = 0;
    for (int k = 0; k < 256; k++)
        sum += c.cover[k];
    CHECK_MSG(fabs(sum - fabs(area)) <= 1e-12, "sum %.17g area %.17g", sum, fabs(area));
    /* entirely beyond the far plane: nothing */
    double q[3][3] = {{-1, 0.5, 3}, {1, 0.5, 3}, {0, 0.5, 4}};
    CHECK(gls_exact_project(&cam, q, &proto, out) == 0);
    cov_free(&c);
}

/* The same scene 1e7 units from the origin (vertices and camera moved
 * together; coordinates dyadic, so the move is exact): the same image. */
static void test_exact_far_offset(void)
{
    const double off[3] = {1e7, -1e7, 1e7};
    double worst = 0;
    static double first[256];
    for (int pass = 0; pass < 2; pass++) {
        gls_exact_pinhole cam = cam0;
        cam.R[0] = 0.8, cam.R[2] = 0.6, cam.R[6] = -0.6, cam.R[8] = 0.8; /* turned about y */
        gls_exact_tri t[36];
        size_t n = 0;
        double s = pass ? 1 : 0;
        rng = 12345; /* the same triangles both times */
        for (int k = 0; k < 3; k++)
            cam.C[k] = s * off[k];
        for (int r = 0; r < 12; r++) {
            double p[3][3];
            for (int v = 0; v < 3; v++)
                for (int k = 0; k < 3; k++) /* multiples of 2^-16 in front of the camera */
                    p[v][k] = s * off[k] + ldexp(floor((k == 2 ? 4 : 0) * 65536 + (urand() - 0.5) * 6 * 65536), -16);
            gls_exact_tri proto = tri(0, 0, 0, 0, 0, 0, 0);
            proto.id = (uint32_t)r;
            n += (size_t)gls_exact_project(&cam, p, &proto, t + n);
        }
        cov c = run(t, n, 16, 16);
        for (int k = 0; k < 256; k++) {
            if (pass)
                worst = fmax(worst, fabs(c.cover[k] - first[k]));
            else
                first[k] = c.cover[k];
        }
        if (!pass) {
            double sum = 0;
            for (int k = 0; k < 256; k++)
                sum += c.cover[k];
            CHECK(sum > 10);
        }
        cov_free(&c);
    }
    CHECK_MSG(worst == 0, "worst %g", worst);
}

/* Flat colours: the image is the area-weighted mix, background the rest. */
static void test_exact_image_flat(void)
{
    gls_exact_tri t = tri(0.5, 0.5, 3.5, 0.5, 0.5, 3.5, 1);
    float rgba[4 * 4 * 4], bg[4] = {0, 0, 0, 1};
    t.rgba[0] = 1, t.rgba[1] = 0.5f, t.rgba[2] = 0, t.rgba[3] = 1;
    CHECK(gls_exact_image(&t, 1, 4, 4, bg, NULL, NULL, rgba) == 0);
    /* pixel (1, 1): fully inside; pixel (2, 2): exactly half (diagonal) */
    CHECK_NEAR(rgba[(1 * 4 + 1) * 4 + 0], 1, 0);
    CHECK_NEAR(rgba[(2 * 4 + 2) * 4 + 0], 0.5, 1e-7);
    CHECK_NEAR(rgba[(2 * 4 + 2) * 4 + 1], 0.25, 1e-7);
    CHECK_NEAR(rgba[(2 * 4 + 2) * 4 + 3], 1, 1e-7);
    CHECK_NEAR(rgba[0], 0, 0);
}

/* A sampled triangle's shader for the tests below: red the point's x
 * within its pixel (0..1) squared; id 1 (alpha-tested): 0.25 with the
 * alpha *user, id 2: 1, opaque. */
static void shade_test(void *user, const gls_exact_tri *t, size_t i, const double *x, const double *y, size_t n,
                       float (*rgba)[4])
{
    (void)i, (void)y;
    for (size_t p = 0; p < n; p++) {
        double u = x[p] - floor(x[p] + 0.5) + 0.5;
        rgba[p][0] = t->id == 1 ? 0.25f : t->id == 2 ? 1.0f : (float)(u * u);
        rgba[p][1] = rgba[p][2] = 0;
        rgba[p][3] = t->id == 1 ? *(const float *)user : 1;
    }
}

/* A sampled region's colour is the mean of the shader at the pixel's
 * lattice points inside it (exact.h GLS_EXACT_SAMPLED): u^2 over the
 * pixel's 64 points is 1/3 - 1/(12 * 64^2), where the centroid gives
 * 1/4; half the pixel (the diagonal) averages its own points. */
static void test_exact_image_sampled(void)
{
    gls_exact_tri t = tri(0.5, 0.5, 3.5, 0.5, 0.5, 3.5, 1);
    t.flags = GLS_EXACT_SAMPLED;
    float rgba[4 * 4 * 4], bg[4] = {0, 0, 0, 1}, alpha = 1;
    CHECK(gls_exact_image(&t, 1, 4, 4, bg, shade_test, &alpha, rgba) == 0);
    CHECK_NEAR(rgba[(1 * 4 + 1) * 4 + 0], 1.0 / 3 - 1.0 / (12 * 64 * 64), 1e-6);
    /* pixel (2, 2), half of it (above-left of the diagonal x + y = 4):
     * area 1/2 times the mean of u^2 over the points there, which lie
     * to the left, so under the whole pixel's mean */
    double v = rgba[(2 * 4 + 2) * 4 + 0];
    CHECK_MSG(v > 0.5 * 0.1 && v < 0.5 * (1.0 / 3), "half pixel %g", v);
}

/* n triangles fanning about pixel (1, 1)'s centre, radius 3 px, the
 * first edge at angle off, each a wedge of 2 pi / n */
static void fan_about_centre(gls_exact_tri *t, int n, double off)
{
    for (int k = 0; k < n; k++) {
        double a0 = off + 2 * M_PI * k / n, a1 = off + 2 * M_PI * (k + 1) / n;
        t[k] = tri(1, 1, 1 + 3 * cos(a0), 1 + 3 * sin(a0), 1 + 3 * cos(a1), 1 + 3 * sin(a1), 1);
    }
}

/* The pixel-local position (x, y) of the pixel's lattice point m (of
 * GLS_EXACT_SHADE_M, as the sampled path places them) and the wedge it
 * falls in of a fan of n about the pixel's centre turned by off. */
static int lattice_wedge(int m, double off, int n, double *x, double *y)
{
    gls_lattice l;
    int64_t qx, qy;
    CHECK(gls_lattice_choose(GLS_EXACT_SHADE_M, &l) == 0);
    gls_lattice_point(&l, (uint64_t)m, &qx, &qy);
    *x = (double)qx / (double)l.q - 0.5, *y = (double)qy / (double)l.q - 0.5;
    double a = atan2(*y, *x) - off;
    a = a < 0 ? a + 2 * M_PI : a;
    int k = (int)(a / (2 * M_PI / n));
    return k >= n ? n - 1 : k;
}

/* A pixel of 300 sampled regions (a fan about its centre) under a shader
 * that varies with the position (u^2): each region's colour is the mean
 * at the lattice points in its own wedge, or its centroid's where it has
 * none.  Worked out here from the wedges' angles, the lattice and an
 * independent clip.  With a region's index kept in a byte (the bug of
 * 2026-11-29, 255 meaning "255 or beyond"), region 255 took the points of
 * every region after it; a flat shader per triangle does not show that. */
static void test_exact_image_sampled_many_regions(void)
{
    enum { N = 300 };
    static gls_exact_tri t[N];
    const double off = 0.001; /* no lattice point on a wedge's edge */
    fan_about_centre(t, N, off);
    for (int k = 0; k < N; k++)
        t[k].id = 3, t[k].flags = GLS_EXACT_SAMPLED;
    float rgba[3 * 3 * 4], bg[4] = {0, 0, 0, 1}, alpha = 1;
    CHECK(gls_exact_image(t, N, 3, 3, bg, shade_test, &alpha, rgba) == 0);
    /* the lattice points' wedges */
    double sum[N] = {0};
    int cnt[N] = {0};
    for (int m = 0; m < GLS_EXACT_SHADE_M; m++) {
        double x, y;
        int k = lattice_wedge(m, off, N, &x, &y);
        sum[k] += (x + 0.5) * (x + 0.5), cnt[k]++;
    }
    double want = 0, area = 0;
    int with_points = 0;
    for (int k = 0; k < N; k++) {
        double cx, cy, ar = ref_tri_centroid(t[k].x, t[k].y, 1, 1, &cx, &cy);
        double u = cx - 1 + 0.5, col = cnt[k] ? sum[k] / cnt[k] : u * u;
        want += ar * col, area += ar, with_points += cnt[k] > 0;
    }
    CHECK_NEAR(area, 1, 1e-12);
    CHECK_MSG(with_points > 40, "%d wedges hold lattice points", with_points);
    CHECK_NEAR(rgba[(1 * 3 + 1) * 4 + 0], want, 1e-6);
}

/* A dense pixel (gls_exact_render's dense, --aa auto's bound): a fan of
 * 300 flat triangles about pixel (1, 1)'s centre, alternately red and
 * green.  With dense 0 (and with dense 300, not exceeded) the pixel is
 * exact: red is the red wedges' area (worked out here from the wedges),
 * 0.5.  With dense 256 it is point-sampled: red is the share of the 64
 * lattice points in a red wedge (from the points' angles), which the
 * lattice makes other than 0.5; the pixels with fewer triangles stay
 * exact, the same bytes. */
static void test_exact_image_dense(void)
{
    enum { N = 300 };
    static gls_exact_tri t[N];
    const double off = 0.001; /* no lattice point on a wedge's edge */
    fan_about_centre(t, N, off);
    for (int k = 0; k < N; k++)
        t[k].rgba[0] = k % 2 ? 0.0f : 1.0f, t[k].rgba[1] = k % 2 ? 1.0f : 0.0f, t[k].rgba[2] = 0;
    float ex[3 * 3 * 4], at[3 * 3 * 4], dn[3 * 3 * 4], bg[4] = {0, 0, 0, 1};
    CHECK(gls_exact_render(t, N, 3, 3, bg, NULL, NULL, NULL, ex, NULL, 0) == 0);
    CHECK(gls_exact_render(t, N, 3, 3, bg, NULL, NULL, NULL, at, NULL, N) == 0);
    CHECK(gls_exact_render(t, N, 3, 3, bg, NULL, NULL, NULL, dn, NULL, GLS_EXACT_AUTO_DENSE) == 0);
    int red = 0;
    for (int m = 0; m < GLS_EXACT_SHADE_M; m++) {
        double x, y;
        red += lattice_wedge(m, off, N, &x, &y) % 2 == 0;
    }
    double sampled = (double)red / GLS_EXACT_SHADE_M;
    CHECK_NEAR(ex[(1 * 3 + 1) * 4 + 0], 0.5, 1e-9);
    CHECK(memcmp(ex, at, sizeof ex) == 0);
    CHECK_MSG(fabs(sampled - 0.5) > 1e-3, "the lattice gives %g, as the exact area", sampled);
    CHECK_NEAR(dn[(1 * 3 + 1) * 4 + 0], sampled, 1e-6);
    CHECK_NEAR(dn[(1 * 3 + 1) * 4 + 1], 1 - sampled, 1e-6);
    /* the others see a quarter of the fan at most (about 75 triangles) */
    for (int px = 0; px < 9; px++)
        if (px != 4)
            CHECK_MSG(memcmp(dn + 4 * px, ex + 4 * px, sizeof(float) * 4) == 0, "pixel %d", px);
}

/* An alpha-tested triangle (GLS_EXACT_HOLES) hides nothing in the walk:
 * in front of 100 thin triangles fanning through the pixel (more than
 * the 64 regions of the scratch on the stack), the pixel is its colour
 * where its alpha passes and the fan's where it does not, never the sum
 * of the overlapping areas. */
static void test_exact_image_holes_many(void)
{
    gls_exact_tri t[101];
    t[0] = tri(-2, -2, 6, -2, -2, 6, 1);
    t[0].id = 1, t[0].flags = GLS_EXACT_HOLES | GLS_EXACT_SAMPLED;
    for (int k = 0; k < 100; k++) {
        double a0 = 2 * M_PI * k / 100, a1 = 2 * M_PI * (k + 1) / 100;
        t[1 + k] = tri(1, 1, 1 + 3 * cos(a0), 1 + 3 * sin(a0), 1 + 3 * cos(a1), 1 + 3 * sin(a1), 0.5);
        t[1 + k].id = 2;
    }
    float rgba[3 * 3 * 4], bg[4] = {0, 0, 0, 1}, alpha = 1;
    CHECK(gls_exact_image(t, 101, 3, 3, bg, shade_test, &alpha, rgba) == 0);
    CHECK_NEAR(rgba[(1 * 3 + 1) * 4 + 0], 0.25, 1e-6);
    alpha = 0; /* dropped everywhere: the fan */
    CHECK(gls_exact_image(t, 101, 3, 3, bg, shade_test, &alpha, rgba) == 0);
    CHECK_NEAR(rgba[(1 * 3 + 1) * 4 + 0], 1, 1e-6);
}

/* An alpha-tested triangle sorted after a full cover (its nearest point
 * farther than the cover's) still shows where it is in front: the walk
 * must not stop at the full cover (it did after the early stop of
 * 1fe206d met the alpha test: the pixel read 1, the cover alone).  A
 * tilted cover, 1/Zc from 1 at the pixel's left edge to 0.8 at its right,
 * and an alpha-tested one at 0.9: in front on the right half (x > 0), so
 * 32 of the 64 lattice points (x = (2i + 1) / 128 - 1/2) show it. */
static void test_exact_image_holes_behind_cover(void)
{
    gls_exact_tri t[2];
    t[0] = tri(-1.5, -1.5, 3, -1.5, -1.5, 3, 0);
    for (int k = 0; k < 3; k++)
        t[0].iz[k] = 1 - 0.2 * (t[0].x[k] + 0.5);
    t[0].id = 2;
    t[1] = tri(-2, -2, 6, -2, -2, 6, 0.9);
    t[1].id = 1, t[1].flags = GLS_EXACT_HOLES | GLS_EXACT_SAMPLED;
    float rgba[4], bg[4] = {0, 0, 0, 1}, alpha = 1;
    CHECK(gls_exact_image(t, 2, 1, 1, bg, shade_test, &alpha, rgba) == 0);
    CHECK_NEAR(rgba[0], (32 * 0.25 + 32 * 1.0) / 64, 1e-6);
}

/* An alpha-tested triangle hidden everywhere in a pixel (behind an
 * opaque one that does not cover the pixel whole, so it stays a
 * candidate) leaves the pixel exact: its area, not the share of lattice
 * points (40 of 64 lie left of the edge, 0.625, where the area is
 * 0.623).  The walk hands the candidates out unresolved only where an
 * alpha-tested one has a visible part. */
static void test_exact_image_holes_hidden(void)
{
    gls_exact_tri t[3];
    t[0] = tri(-5, -5, 1.123, -5, 1.123, 10, 1), t[1] = tri(-5, -5, 1.123, 10, -5, 10, 1);
    t[0].id = t[1].id = 2;
    t[2] = tri(0.6, 0.6, 1.0, 0.6, 0.6, 1.4, 0.5);
    t[2].id = 1, t[2].flags = GLS_EXACT_HOLES | GLS_EXACT_SAMPLED;
    float rgba[3 * 3 * 4], bg[4] = {0, 0, 0, 1}, alpha = 1;
    CHECK(gls_exact_image(t, 3, 3, 3, bg, shade_test, &alpha, rgba) == 0);
    CHECK_NEAR(rgba[(1 * 3 + 1) * 4 + 0], 0.623, 1e-7); /* float output */
    /* brought in front, it shows: the pixel is sampled (its points) */
    for (int k = 0; k < 3; k++)
        t[2].iz[k] = 2;
    CHECK(gls_exact_image(t, 3, 3, 3, bg, shade_test, &alpha, rgba) == 0);
    CHECK_MSG(fabs(rgba[(1 * 3 + 1) * 4 + 0] - 0.623) > 1e-3, "in front: %g", rgba[(1 * 3 + 1) * 4 + 0]);
}

/* Coverage: areas summed per id (two triangles of one id), the K largest
 * largest first (ties: the smaller id), ids mapped, 0 not counted. */
static void test_exact_coverage(void)
{
    /* a pixel-sized square of id 7 (two triangles) in pixel (1, 1), its
     * left half under a nearer rectangle of id 2 (two triangles) */
    gls_exact_tri t[9];
    t[0] = tri(0.5, 0.5, 1.5, 0.5, 1.5, 1.5, 0.5), t[1] = tri(0.5, 0.5, 1.5, 1.5, 0.5, 1.5, 0.5);
    t[0].id = t[1].id = 7;
    t[2] = tri(0.5, 0.5, 1.0, 0.5, 1.0, 1.5, 1), t[3] = tri(0.5, 0.5, 1.0, 1.5, 0.5, 1.5, 1);
    t[2].id = t[3].id = 2;
    /* pixel (2, 1): five nested right triangles 0.1 .. 0.5 wide, the
     * smaller nearer: each shows 0.05 of the pixel; ids 10..14 */
    for (int k = 0; k < 5; k++)
        t[4 + k] = tri(1.5, 0.5, 1.5, 1.5, 1.5 + 0.1 * (k + 1), 0.5, 6 - k), t[4 + k].id = (uint32_t)(10 + k);
    gls_exact_cover cov[3 * 3 * GLS_EXACT_COVER_K];
    float bg[4] = {0, 0, 0, 0};
    CHECK(gls_exact_render(t, 9, 3, 3, bg, NULL, NULL, NULL, NULL, cov, 0) == 0);
    const gls_exact_cover *p = cov + (1 * 3 + 1) * GLS_EXACT_COVER_K;
    CHECK(p[0].id == 2 && p[1].id == 7 && p[2].id == 0);
    CHECK_NEAR(p[0].area, 0.5, 1e-7);
    CHECK_NEAR(p[1].area, 0.5, 1e-7);
    p = cov + (1 * 3 + 2) * GLS_EXACT_COVER_K;
    /* five ids of equal area up to rounding: four of them, each once */
    unsigned seen = 0;
    for (int k = 0; k < GLS_EXACT_COVER_K; k++) {
        CHECK_MSG(p[k].id >= 10 && p[k].id <= 14 && !(seen & (1u << (p[k].id - 10))), "slot %d: id %u", k, p[k].id);
        seen |= p[k].id >= 10 && p[k].id <= 14 ? 1u << (p[k].id - 10) : 0;
        CHECK_NEAR(p[k].area, 0.05, 1e-7);
    }
    /* an id map: 7 -> 0 (not counted), 2 -> 9 */
    uint16_t map[15] = {0};
    map[2] = 9;
    CHECK(gls_exact_render(t, 9, 3, 3, bg, NULL, NULL, map, NULL, cov, 0) == 0);
    p = cov + (1 * 3 + 1) * GLS_EXACT_COVER_K;
    CHECK(p[0].id == 9 && p[1].id == 0);
}

/* The same frags, bit for bit and in the same order, for any number of
 * worker threads (exact.h gls_exact_visit_threads): 300 random tilted
 * triangles passing through each other over 37 x 101 pixels (seven bands,
 * the last short), hashed per pixel in visiting order. */
typedef struct {
    uint64_t hash;
    int last;           /* the last pixel visited, in row-major order      */
    int ordered;
    int w;
} frag_hash;

static void hash_pixel(void *user, int px, int py, const gls_exact_frag *f, size_t n)
{
    frag_hash *hs = user;
    int at = py * hs->w + px;
    hs->ordered &= at == hs->last + 1;
    hs->last = at;
    for (size_t k = 0; k < n; k++) {
        uint64_t v[4];
        memcpy(&v[0], &f[k].area, 8), memcpy(&v[1], &f[k].cx, 8), memcpy(&v[2], &f[k].cy, 8);
        v[3] = f[k].tri;
        for (int q = 0; q < 4; q++)
            hs->hash = (hs->hash ^ v[q]) * 1099511628211ull;
    }
    hs->hash = (hs->hash ^ (uint64_t)n) * 1099511628211ull;
}

/* n random triangles of up to 12 px over a w x h image, at random
 * depths (passing through each other), id k the k-th */
static void random_tris(gls_exact_tri *t, int n, int w, int h)
{
    for (int k = 0; k < n; k++) {
        double x = urand() * w, y = urand() * h, s = 1 + urand() * 12;
        t[k] = tri(x, y, x + s * (urand() - 0.5), y + s * (urand() - 0.5), x + s * (urand() - 0.5),
                   y + s * (urand() - 0.5), 1);
        for (int q = 0; q < 3; q++)
            t[k].iz[q] = 0.5 + urand();
        t[k].id = (uint32_t)k;
    }
}

static void test_exact_threads(void)
{
    enum { N = 300, W = 37, H = 101 };
    static gls_exact_tri t[N];
    random_tris(t, N, W, H);
    uint64_t first = 0;
    for (unsigned th = 0; th <= 9; th++) {
        frag_hash hs = {14695981039346656037ull, -1, 1, W};
        CHECK(gls_exact_visit_threads(t, N, W, H, hash_pixel, &hs, th) == 0);
        CHECK_MSG(hs.ordered && hs.last == W * H - 1, "threads %u: pixels out of order", th);
        if (th == 0)
            first = hs.hash;
        CHECK_MSG(hs.hash == first, "threads %u: frags differ from the automatic count's", th);
    }
}

/* gls_exact_visit_any_thread (the image's way: each pixel's value from
 * its own frags, computed on the workers): every pixel handed out exactly
 * once, with the frags the ordered walk hands it.  Per pixel, a hash of
 * its frags and a count of calls (each pixel written by the one thread
 * that has its band). */
typedef struct {
    uint64_t *hash;
    int *calls;
    int w;
} pixel_hashes;

static void hash_each_pixel(void *user, int px, int py, const gls_exact_frag *f, size_t n)
{
    pixel_hashes *ph = user;
    frag_hash one = {14695981039346656037ull, -1, 1, ph->w};
    hash_pixel(&one, px, py, f, n);
    ph->hash[py * ph->w + px] = one.hash;
    ph->calls[py * ph->w + px]++;
}

static void test_exact_any_thread(void)
{
    enum { N = 300, W = 37, H = 101 };
    static gls_exact_tri t[N];
    static uint64_t h0[W * H], h1[W * H];
    static int c0[W * H], c1[W * H];
    random_tris(t, N, W, H);
    pixel_hashes a = {h0, c0, W}, b = {h1, c1, W};
    CHECK(gls_exact_visit(t, N, W, H, hash_each_pixel, &a) == 0);
    CHECK(gls_exact_visit_any_thread(t, N, W, H, hash_each_pixel, &b) == 0);
    int once = 1, same = 1;
    for (int k = 0; k < W * H; k++)
        once &= c0[k] == 1 && c1[k] == 1, same &= h0[k] == h1[k];
    CHECK_MSG(once, "a pixel handed out other than once");
    CHECK_MSG(same, "a pixel's frags differ from the ordered walk's");
}

/* Canonical orientation of shared edges (exact_int.h): two triangles on
 * either side of one long edge, which they traverse in opposite
 * directions, their far vertices L px away, so that every pixel of the
 * 32 x 32 image is covered by the two exactly once.  Each edge's line is
 * then a difference of products of size L^2: taken from its own first
 * vertex, each triangle would round it differently and leave a crack or an
 * overlap of about L^2 2^-53 / L px along the edge.  With the canonical
 * line both cut each pixel at the same points.  60 random edges a length,
 * L from 1e3 to 1e7: worst |sum - 1| over every pixel. */
static double shared_edge_worst(double L, int reps, int *checked)
{
    const int W = 32;
    double worst = 0;
    for (int r = 0; r < reps; r++) {
        double th = M_PI * urand(), ux = cos(th), uy = sin(th), nx = -uy, ny = ux;
        double cx = W / 2 + urand() - 0.5, cy = W / 2 + urand() - 0.5;
        double a = L * (0.5 + urand()), b = L * (0.5 + urand()); /* the edge's two ends */
        double px = cx - a * ux, py = cy - a * uy, qx = cx + b * ux, qy = cy + b * uy;
        double sx = (px + qx) / 2 + 2 * L * nx, sy = (py + qy) / 2 + 2 * L * ny; /* one side */
        double tx = (px + qx) / 2 - 2 * L * nx, ty = (py + qy) / 2 - 2 * L * ny; /* the other */
        gls_exact_tri t[2] = {tri(px, py, qx, qy, sx, sy, 1), tri(qx, qy, px, py, tx, ty, 1)};
        t[1].id = 1;
        cov c = run(t, 2, W, W);
        for (int k = 0; k < W * W; k++)
            worst = fmax(worst, fabs(c.cover[k] - 1));
        *checked += W * W;
        cov_free(&c);
    }
    return worst;
}

static void test_exact_shared_edge_long(void)
{
    double worst = 0;
    int checked = 0;
    for (double L = 1e3; L <= 1e7; L *= 10) {
        double w = shared_edge_worst(L, 60, &checked);
        printf("  shared edge, ends %.0e px away: worst |sum - 1| %.3g\n", L, w);
        worst = fmax(worst, w);
    }
    CHECK(checked == 5 * 60 * 32 * 32);
    CHECK_MSG(worst <= 1e-14, "worst %g", worst);
}

int main(void)
{
    RUN(test_exact_area_vs_reference);
    RUN(test_exact_halfplane_sweep);
    RUN(test_exact_fan);
    RUN(test_exact_shared_edge_long);
    RUN(test_exact_t_junction);
    RUN(test_exact_sliver);
    RUN(test_exact_interpenetrating);
    RUN(test_exact_near_plane);
    RUN(test_exact_far_plane);
    RUN(test_exact_far_offset);
    RUN(test_exact_image_flat);
    RUN(test_exact_image_sampled);
    RUN(test_exact_image_sampled_many_regions);
    RUN(test_exact_image_holes_many);
    RUN(test_exact_image_holes_behind_cover);
    RUN(test_exact_image_dense);
    RUN(test_exact_image_holes_hidden);
    RUN(test_exact_coverage);
    RUN(test_exact_threads);
    RUN(test_exact_any_thread);
    CHECK_EXIT();
}
