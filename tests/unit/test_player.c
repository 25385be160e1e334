/* Player tests: render bundles built in memory through the runtime and
 * compare with an independent double-precision model of the camera,
 * written here without the runtime's matrix code (camera.c).
 *
 *   test_player                run the tests
 *   test_player --write DIR    also write the scenes and cameras the
 *                              end-to-end tests (tests/e2e/player_*.sh)
 *                              feed to glsplay and to OpenCV
 *
 * A long file on purpose: a list of independent tests, one function each,
 * over the scene builder of player_scene.h and the model below.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "outputs.h"
#include "player.h"
#include "player_scene.h"

static gls_glctx *ctx;

/* ---- independent camera model ------------------------------------- */

/* Rotation matrix from a rotation vector (Rodrigues), row-major. */
static void rodrigues(double rx, double ry, double rz, double R[9])
{
    double th = sqrt(rx * rx + ry * ry + rz * rz);
    double k[3] = {rx / th, ry / th, rz / th};
    double c = cos(th), s = sin(th), v = 1 - c;
    double K[9] = {0, -k[2], k[1], k[2], 0, -k[0], -k[1], k[0], 0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = (i == j) * c + s * K[3 * i + j] + v * k[i] * k[j];
}

/* u, v of world point P; returns Zc.  Straight from the brief's formula. */
static double ref_project(const gls_camera *c, const double P[3], double *u, double *v)
{
    double X = c->R[0] * P[0] + c->R[1] * P[1] + c->R[2] * P[2] + c->T[0];
    double Y = c->R[3] * P[0] + c->R[4] * P[1] + c->R[5] * P[2] + c->T[1];
    double Z = c->R[6] * P[0] + c->R[7] * P[1] + c->R[8] * P[2] + c->T[2];
    *u = (c->fx * X + c->skew * Y) / Z + c->cx;
    *v = c->fy * Y / Z + c->cy;
    return Z;
}

/* World point from a camera-frame point: P = R^T (Pc - T). */
static void ref_to_world(const gls_camera *c, const double Pc[3], double P[3])
{
    for (int j = 0; j < 3; j++)
        P[j] = c->R[j] * (Pc[0] - c->T[0]) + c->R[3 + j] * (Pc[1] - c->T[1]) + c->R[6 + j] * (Pc[2] - c->T[2]);
}

/* Is (x, y) strictly inside the convex polygon q (n corners, either
 * winding)? */
static int inside_convex(const double (*q)[2], int n, double x, double y)
{
    int pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        const double *a = q[i], *b = q[(i + 1) % n];
        double cr = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
        pos += cr > 0;
        neg += cr < 0;
    }
    return pos == n || neg == n;
}

static double polygon_perimeter(const double (*q)[2], int n)
{
    double p = 0;
    for (int i = 0; i < n; i++)
        p += hypot(q[(i + 1) % n][0] - q[i][0], q[(i + 1) % n][1] - q[i][1]);
    return p;
}

/* Compare the pixels of colour rgb with the reference coverage of the
 * projected polygon q: a pixel is lit iff its centre is inside.  Reports
 * mismatched pixels per pixel of perimeter (= mean absolute edge error in
 * pixels, to first order) and the difference of the lit centroids. */
typedef struct {
    double mismatch_per_px, dcx, dcy;
    long lit;
} cover_cmp;

static cover_cmp compare_cover(const uint8_t *rgba, uint32_t W, uint32_t H, const uint8_t rgb[3],
                               const double (*q)[2], int n)
{
    cover_cmp r = {0, 0, 0, 0};
    long mism = 0, nr = 0;
    double sx = 0, sy = 0, rx = 0, ry = 0;
    for (uint32_t v = 0; v < H; v++)
        for (uint32_t u = 0; u < W; u++) {
            const uint8_t *p = rgba + 4 * ((size_t)v * W + u);
            int lit = p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
            int ref = inside_convex(q, n, u, v);
            mism += lit != ref;
            if (lit)
                r.lit++, sx += u, sy += v;
            if (ref)
                nr++, rx += u, ry += v;
        }
    r.mismatch_per_px = mism / polygon_perimeter(q, n);
    if (r.lit && nr) {
        r.dcx = sx / r.lit - rx / nr;
        r.dcy = sy / r.lit - ry / nr;
    } else {
        r.dcx = r.dcy = 1e9;
    }
    return r;
}

/* ---- the projection scene ----------------------------------------- */

static const uint8_t palette[5][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {255, 0, 255}};

static gls_camera proj_camera(void)
{
    double R[9], T[3] = {0.2, -0.1, 0.5};
    rodrigues(0.1, -0.2, 0.05, R);
    return tb_camera(640, 480, 700, 650, 301.3, 257.8, 3.7, R, T, 0.1, 1000);
}

/* Five tilted squares placed in the camera frame, stored in world
 * coordinates; corners[k] receives each square's world corners. */
static gls_bundle *proj_scene(const gls_camera *c, double corners[5][4][3])
{
    static const double centre[5][3] = {{-1.1, -0.8, 6}, {1.3, -0.9, 7}, {0, 0.1, 5}, {-1.5, 1.1, 8}, {1.6, 1.2, 9}};
    tb t;
    tb_init(&t);
    tb_object(&t, "scene", 1);
    for (int k = 0; k < 5; k++) {
        /* a 1.1-unit square, rotated in its plane by 7 + 5k degrees (so
         * no edge is pixel-aligned) and tilted about x by 20 degrees */
        double a = (7.0 + 5 * k) * 3.14159265358979323846 / 180, ct = cos(a), st = sin(a);
        double tilt = 20 * 3.14159265358979323846 / 180;
        double q[4][3];
        for (int i = 0; i < 4; i++) {
            double x = (i == 1 || i == 2) ? 0.55 : -0.55, y = i >= 2 ? 0.55 : -0.55;
            double xr = ct * x - st * y, yr = st * x + ct * y;
            double Pc[3] = {centre[k][0] + xr, centre[k][1] + yr * cos(tilt), centre[k][2] + yr * sin(tilt)};
            ref_to_world(c, Pc, q[i]);
            memcpy(corners[k][i], q[i], sizeof q[i]);
        }
        tb_color(&t, palette[k][0] / 255.0, palette[k][1] / 255.0, palette[k][2] / 255.0, 1);
        tb_poly(&t, 4, (const double(*)[3])q);
    }
    return tb_finish(&t);
}

static void check_projection(double du, int expect_ok)
{
    gls_camera c = proj_camera();
    double corners[5][4][3];
    gls_bundle *b = proj_scene(&c, corners);
    uint8_t *rgba = malloc((size_t)c.width * c.height * 4);
    CHECK(tb_render(ctx, b, &c, du, 0, rgba, NULL) == 0);
    double worst_m = 0, worst_c = 0;
    for (int k = 0; k < 5; k++) {
        double q[4][2];
        for (int i = 0; i < 4; i++)
            ref_project(&c, corners[k][i], &q[i][0], &q[i][1]);
        cover_cmp r = compare_cover(rgba, c.width, c.height, palette[k], (const double(*)[2])q, 4);
        CHECK_MSG(r.lit > 1000, "square %d: only %ld pixels lit", k, r.lit);
        double dc = hypot(r.dcx, r.dcy);
        if (r.mismatch_per_px > worst_m)
            worst_m = r.mismatch_per_px;
        if (dc > worst_c)
            worst_c = dc;
    }
    printf("  jitter du=%g: worst mismatched pixels per perimeter pixel %.4f, worst centroid error %.4f px\n", du,
           worst_m, worst_c);
    if (expect_ok) {
        CHECK(worst_m < 0.02);
        CHECK(worst_c < 0.05);
    } else {
        /* the same measurement must see a deliberate 0.25 px shift */
        CHECK(worst_c > 0.2 && worst_c < 0.3);
    }
    free(rgba);
    gls_bundle_free(b);
}

static void test_projection_skew_offcentre(void) { check_projection(0, 1); }
static void test_projection_detects_shift(void) { check_projection(0.25, 0); }

/* ---- depth ---------------------------------------------------------- */

static const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

static void test_depth_fronto_parallel(void)
{
    static const double depths[] = {0.1001, 0.3, 1, 3.3, 10, 77, 1000, 3000, 9000, 9999.5};
    enum { ND = sizeof depths / sizeof depths[0] };
    double T[3] = {0, 0, 0};
    gls_camera c = tb_camera(320, 400, 300, 310, 161.2, 198.7, 0.9, I3, T, 0.1, 10000);
    tb t;
    tb_init(&t);
    tb_object(&t, "scene", 1);
    uint32_t band = c.height / ND;
    for (int k = 0; k < ND; k++) {
        double Z = depths[k];
        /* rows k*band .. (k+1)*band - 1, all columns, with margin */
        double y0 = (k * band - 0.5 - c.cy) * Z / c.fy, y1 = ((k + 1) * band - 0.5 - c.cy) * Z / c.fy;
        double x0 = (-10 - c.cx) * Z / c.fx - 0.01 * Z, x1 = (c.width + 10 - c.cx) * Z / c.fx + 0.01 * Z;
        tb_rect_z(&t, x0, y0, x1, y1, Z);
    }
    /* beyond far and before near: must not appear */
    tb_rect_z(&t, -1e9, -1e9, 1e9, 1e9, 10001);
    tb_rect_z(&t, -1, -1, 1, 1, 0.09);
    gls_bundle *b = tb_finish(&t);
    float *z = malloc((size_t)c.width * c.height * sizeof *z);
    CHECK(tb_render(ctx, b, &c, 0, 0, NULL, z) == 0);
    double worst = 0;
    long bad = 0;
    printf("  worst relative depth error per plane:");
    for (int k = 0; k < ND; k++) {
        double wk = 0;
        for (uint32_t v = k * band + 1; v + 1 < (k + 1) * band; v++)
            for (uint32_t u = 0; u < c.width; u++) {
                double e = fabs(z[(size_t)v * c.width + u] - depths[k]) / depths[k];
                if (!(e <= 1e-5))
                    bad++;
                if (e > wk || e != e)
                    wk = e;
            }
        printf(" %g:%.2g", depths[k], wk);
        if (wk > worst || wk != wk)
            worst = wk;
    }
    printf("\n  worst relative depth error over 0.1..10000: %.3g\n", worst);
    CHECK_MSG(bad == 0, "%ld pixels with relative error >= 1e-5", bad);
    /* rows below the last band see only the plane beyond far: +inf */
    for (uint32_t v = ND * band; v < c.height; v++)
        CHECK(isinf(z[(size_t)v * c.width + 5]));
    free(z);
    gls_bundle_free(b);
}

/* The near limit of spec/camera.md "Depth range", rendered: with near just
   above the smallest near for far = 1000 every plane up to 0.999 far is
   drawn with its depth; far below the limit (near / 1e6, which the camera
   parser refuses) the far planes' depths are subnormal floats and vanish. */
static void test_depth_near_limit(void)
{
    static const double depths[] = {0.5, 10, 300, 900, 999};
    enum { ND = sizeof depths / sizeof depths[0] };
    double T[3] = {0, 0, 0}, nmin, nmax;
    CHECK(gls_camera_depth_range(1, 1000, &nmin, &nmax) == 0);
    for (int pass = 0; pass < 2; pass++) {
        double n = pass == 0 ? nmin * 1.01 : nmin * 1e-6;
        CHECK(gls_camera_depth_range(n, 1000, &nmin, &nmax) == (pass == 0 ? 0 : -1));
        gls_camera c = tb_camera(50, 50, 40, 40, 24.5, 24.5, 0, I3, T, n, 1000);
        tb t;
        tb_init(&t);
        tb_object(&t, "scene", 1);
        for (int k = 0; k < ND; k++) { /* band k: rows 10k..10k+9 */
            double Z = depths[k], y0 = (10 * k - 0.5 - c.cy) * Z / c.fy, y1 = (10 * k + 9.5 - c.cy) * Z / c.fy;
            tb_rect_z(&t, -Z, y0, Z, y1, Z);
        }
        gls_bundle *b = tb_finish(&t);
        float z[50 * 50];
        CHECK(tb_render(ctx, b, &c, 0, 0, NULL, z) == 0);
        printf("  near %.3g:", n);
        int lost = 0;
        for (int k = 0; k < ND; k++) {
            double e = fabs(z[(10 * k + 5) * 50 + 25] - depths[k]) / depths[k];
            printf(" %g:%.2g", depths[k], e);
            if (pass == 0)
                CHECK_MSG(e < 1e-5, "near %g: plane at %g has depth %g", n, depths[k], z[(10 * k + 5) * 50 + 25]);
            lost += isinf(z[(10 * k + 5) * 50 + 25]);
        }
        printf("%s\n", lost ? " (planes lost)" : "");
        if (pass == 1)
            CHECK_MSG(lost > 0, "below the limit every plane was still drawn: the limit is stricter than needed");
        gls_bundle_free(b);
    }
}

/* A plane through three world points; returns unit normal n and d with
 * n.P = d. */
static void plane_of(const double a[3], const double b[3], const double c[3], double n[3], double *d)
{
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++)
        n[i] /= l;
    *d = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
}

/* A ground-like plane seen at a grazing angle, generic camera pose. */
static gls_camera ground_camera(void)
{
    double R[9], T[3] = {0.3, 1.5, -0.2};
    rodrigues(-0.25, 0.1, 0.02, R);
    return tb_camera(400, 300, 350, 340, 197.5, 151.25, -1.3, R, T, 0.1, 10000);
}

static gls_bundle *ground_scene(double n[3], double *d)
{
    /* a parallelogram, so its four corners are coplanar */
    double q[4][3] = {{-60, 0, -5}, {60, 0.5, -5}, {60, 0.9, 200}, {-60, 0.4, 200}};
    plane_of(q[0], q[1], q[2], n, d);
    tb t;
    tb_init(&t);
    tb_object(&t, "scene", 1);
    tb_color(&t, 0.2, 0.6, 0.4, 1); /* exact in 8 bits: 51 153 102 */
    tb_poly(&t, 4, (const double(*)[3])q);
    return tb_finish(&t);
}

static void test_depth_slanted_plane(void)
{
    gls_camera c = ground_camera();
    double n[3], d;
    gls_bundle *b = ground_scene(n, &d);
    float *z = malloc((size_t)c.width * c.height * sizeof *z);
    CHECK(tb_render(ctx, b, &c, 0, 0, NULL, z) == 0);
    /* reference: ray through the pixel centre meets the plane */
    double worst = 0;
    long count = 0;
    for (uint32_t v = 0; v < c.height; v++)
        for (uint32_t u = 0; u < c.width; u++) {
            float zz = z[(size_t)v * c.width + u];
            if (!isfinite(zz))
                continue;
            double y = (v - c.cy) / c.fy, x = ((u - c.cx) - c.skew * y) / c.fx;
            /* plane in camera frame: n.(R^T (Pc - T)) = d  =>  (R n).Pc = d + (R n).T */
            double m[3];
            for (int i = 0; i < 3; i++)
                m[i] = c.R[3 * i] * n[0] + c.R[3 * i + 1] * n[1] + c.R[3 * i + 2] * n[2];
            double rhs = d + m[0] * c.T[0] + m[1] * c.T[1] + m[2] * c.T[2];
            double Zref = rhs / (m[0] * x + m[1] * y + m[2]);
            double e = fabs(zz - Zref) / Zref;
            if (e > worst)
                worst = e;
            count++;
        }
    printf("  slanted plane: %ld pixels, depth %s, worst relative error %.3g\n", count, "0.5..200", worst);
    CHECK(count > 10000);
    CHECK(worst < 1e-5);
    free(z);
    gls_bundle_free(b);
}

/* ---- points --------------------------------------------------------- */

static double get_f64le(const uint8_t *p)
{
    uint64_t u = 0;
    for (int i = 7; i >= 0; i--)
        u = u << 8 | p[i];
    double d;
    memcpy(&d, &u, 8);
    return d;
}

static void test_points_on_plane(void)
{
    gls_camera c = ground_camera();
    double n[3], d;
    gls_bundle *b = ground_scene(n, &d);
    size_t np = (size_t)c.width * c.height;
    float *z = malloc(np * sizeof *z);
    uint8_t *rgba = malloc(np * 4);
    CHECK(tb_render(ctx, b, &c, 0, 0, rgba, z) == 0);
    gls_buf ply = {0};
    uint64_t count = 0;
    CHECK(gls_encode_ply(&c, z, rgba, &ply, &count) == 0);
    const char *end = strstr((const char *)ply.data, "end_header\n");
    CHECK(end != NULL);
    CHECK(strstr((const char *)ply.data, "property double x") != NULL);
    if (end) {
        const uint8_t *p = (const uint8_t *)end + strlen("end_header\n");
        CHECK((size_t)(ply.data + ply.len - p) == count * 27);
        double C[3], zero[3] = {0, 0, 0};
        ref_to_world(&c, zero, C);
        double worst = 0;
        int colour_ok = 1;
        for (uint64_t i = 0; i < count; i++, p += 27) {
            double P[3] = {get_f64le(p), get_f64le(p + 8), get_f64le(p + 16)};
            double dist = fabs(n[0] * P[0] + n[1] * P[1] + n[2] * P[2] - d);
            double range = sqrt((P[0] - C[0]) * (P[0] - C[0]) + (P[1] - C[1]) * (P[1] - C[1]) +
                                (P[2] - C[2]) * (P[2] - C[2]));
            if (dist / range > worst)
                worst = dist / range;
            colour_ok &= p[24] == 51 && p[25] == 153 && p[26] == 102;
        }
        printf("  %llu points, worst distance to the plane / range %.3g\n", (unsigned long long)count, worst);
        CHECK(count > 10000);
        CHECK(worst < 1e-5);
        CHECK(colour_ok);
    }
    free(ply.data);
    free(z);
    free(rgba);
    gls_bundle_free(b);
}

/* ---- far from the origin ------------------------------------------- */

static gls_bundle *far_scene(const double D[3])
{
    tb t;
    tb_init(&t);
    tb_object(&t, "scene", 1);
    tb_trans(&t, D[0], D[1], D[2]);
    for (int k = 0; k < 6; k++) {
        tb_color(&t, 0.1 + 0.15 * k, 1 - 0.15 * k, 0.5, 1);
        double z = -6.0 - 2.25 * k, o = 0.375 * k;
        double q[4][3] = {{z, -1 + o, -1}, {z + 0.75, 1 + o, -1.25}, {z + 0.5, 1.5 + o, 1}, {z, -0.5 + o, 1.5}};
        tb_poly(&t, 4, (const double(*)[3])q);
    }
    /* and a long ground strip crossing many chunk cells */
    tb_color(&t, 0.6, 0.6, 0.6, 1);
    double g[4][3] = {{-2, -3, -2.5}, {-300, -3, -2.5}, {-300, 3, -2.5}, {-2, 3, -2.5}};
    tb_poly(&t, 4, (const double(*)[3])g);
    return tb_finish(&t);
}

static void far_compare(const double R[9], const double T0[3], int exact)
{
    double D0[3] = {0, 0, 0}, D1[3] = {1e7, -2e7, 3e7}; /* multiples of the cell size */
    double T1[3];
    for (int i = 0; i < 3; i++) /* camera moved with the scene: T1 = T0 - R D */
        T1[i] = T0[i] - (R[3 * i] * D1[0] + R[3 * i + 1] * D1[1] + R[3 * i + 2] * D1[2]);
    gls_camera c0 = tb_camera(320, 240, 280, 290, 160.3, 119.6, 0.7, R, T0, 0.1, 1000);
    gls_camera c1 = c0;
    memcpy(c1.T, T1, sizeof T1);
    gls_bundle *b0 = far_scene(D0), *b1 = far_scene(D1);
    size_t np = (size_t)c0.width * c0.height;
    uint8_t *i0 = malloc(np * 4), *i1 = malloc(np * 4);
    float *z0 = malloc(np * 4), *z1 = malloc(np * 4);
    CHECK(tb_render(ctx, b0, &c0, 0, 0, i0, z0) == 0);
    CHECK(tb_render(ctx, b1, &c1, 0, 0, i1, z1) == 0);
    long lit = 0, diff = 0;
    double worst = 0;
    for (size_t i = 0; i < np; i++) {
        lit += i0[4 * i] != 0;
        diff += memcmp(i0 + 4 * i, i1 + 4 * i, 4) != 0;
        if (isfinite(z0[i]) && isfinite(z1[i])) {
            double e = fabs(z0[i] - z1[i]) / z0[i];
            if (e > worst)
                worst = e;
        } else if (isfinite(z0[i]) != isfinite(z1[i])) {
            worst = INFINITY;
        }
    }
    printf("  %s rotation: %ld lit pixels, %ld differ, worst relative depth difference %.3g\n",
           exact ? "axis-aligned" : "generic", lit, diff, worst);
    CHECK(lit > (long)(np / 4));
    if (exact) {
        CHECK(memcmp(i0, i1, np * 4) == 0);
        CHECK(memcmp(z0, z1, np * 4) == 0);
    } else {
        /* bound: the double rounding of R*(anchor)+T at 1e7 is ~1e-9
         * units; it can flip a float rounding of the chunk translation,
         * which moves vertices by ~1e-6 units (1e-4 px here) */
        CHECK(diff <= lit / 1000);
        CHECK(worst < 1e-6);
    }
    free(i0), free(i1), free(z0), free(z1);
    gls_bundle_free(b0);
    gls_bundle_free(b1);
}

static void test_far_from_origin_identical(void)
{
    /* camera looks along world -x; exact entries keep every product exact */
    static const double R[9] = {0, 1, 0, 0, 0, -1, -1, 0, 0};
    double T[3] = {0.25, 0.5, -1};
    far_compare(R, T, 1);
}

static void test_far_from_origin_generic(void)
{
    double R0[9], R[9];
    static const double Rb[9] = {0, 1, 0, 0, 0, -1, -1, 0, 0};
    rodrigues(0.03, -0.05, 0.02, R0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = R0[3 * i] * Rb[j] + R0[3 * i + 1] * Rb[3 + j] + R0[3 * i + 2] * Rb[6 + j];
    double T[3] = {0.25, 0.5, -1};
    far_compare(R, T, 0);
}

/* ---- stereo --------------------------------------------------------- */

static void stereo_cameras(gls_camera *l, gls_camera *r)
{
    double R[9], C[3] = {0.3, 0, 0}, Tl[3] = {0, 0, 0}, Tr[3];
    rodrigues(0.0, -0.04, 0.01, R); /* right camera toed in a little */
    for (int i = 0; i < 3; i++)    /* its centre at C: T = -R C */
        Tr[i] = -(R[3 * i] * C[0] + R[3 * i + 1] * C[1] + R[3 * i + 2] * C[2]);
    *l = tb_camera(480, 360, 500, 500, 239.5, 179.5, 0, I3, Tl, 0.1, 100);
    *r = tb_camera(480, 360, 505, 498, 243.1, 176.2, 0.4, R, Tr, 0.1, 100);
}

static void test_stereo_pair(void)
{
    gls_camera cam[2];
    stereo_cameras(&cam[0], &cam[1]);
    static const double pts[3][3] = {{-0.7, -0.4, 4}, {0.5, 0.3, 6}, {0.1, 0.6, 3}};
    tb t;
    tb_init(&t);
    tb_object(&t, "scene", 1);
    double sq[3][4][3];
    for (int k = 0; k < 3; k++) {
        /* a square around the point, facing the left camera, rotated
         * 11 degrees in its plane so no edge is pixel-aligned */
        double a = 11 * 3.14159265358979323846 / 180, h = 0.2;
        for (int i = 0; i < 4; i++) {
            double x = (i == 1 || i == 2) ? h : -h, y = i >= 2 ? h : -h;
            sq[k][i][0] = pts[k][0] + cos(a) * x - sin(a) * y;
            sq[k][i][1] = pts[k][1] + sin(a) * x + cos(a) * y;
            sq[k][i][2] = pts[k][2];
        }
        tb_color(&t, palette[k][0] / 255.0, palette[k][1] / 255.0, palette[k][2] / 255.0, 1);
        tb_poly(&t, 4, (const double(*)[3])sq[k]);
    }
    gls_bundle *b = tb_finish(&t);
    for (int ci = 0; ci < 2; ci++) {
        const gls_camera *c = &cam[ci];
        uint8_t *rgba = malloc((size_t)c->width * c->height * 4);
        CHECK(tb_render(ctx, b, c, 0, 0, rgba, NULL) == 0);
        for (int k = 0; k < 3; k++) {
            double q[4][2];
            for (int i = 0; i < 4; i++)
                ref_project(c, sq[k][i], &q[i][0], &q[i][1]);
            cover_cmp r = compare_cover(rgba, c->width, c->height, palette[k], (const double(*)[2])q, 4);
            CHECK_MSG(hypot(r.dcx, r.dcy) < 0.05 && r.mismatch_per_px < 0.02,
                      "camera %d square %d: centroid off by (%.4f, %.4f), %.4f mismatches per edge pixel", ci, k,
                      r.dcx, r.dcy, r.mismatch_per_px);
        }
        free(rgba);
    }
    gls_bundle_free(b);
}

/* ---- replay semantics (CPU only) ---------------------------------- */

/* World position of scene vertex i. */
static void scene_vertex(const gls_scene *s, uint32_t i, double P[3], uint8_t rgba[4])
{
    const gls_chunk *ch = NULL;
    for (uint32_t k = 0; k < s->nchunks; k++)
        if (i >= s->chunks[k].first && i < s->chunks[k].first + s->chunks[k].count)
            ch = &s->chunks[k];
    float off[3];
    memcpy(off, s->verts + (size_t)i * s->stride, sizeof off);
    for (int j = 0; j < 3; j++)
        P[j] = ch->anchor[j] + off[j];
    if (s->has_color)
        memcpy(rgba, s->verts + (size_t)i * s->stride + s->color_offset, 4);
    else
        memcpy(rgba, ch->key.rgba, 4);
}

/* Find the triangle whose first vertex is at P; 1 if found. */
static int find_vertex(const gls_scene *s, const double P[3], uint8_t rgba[4])
{
    for (uint32_t i = 0; i < s->nverts; i++) {
        double Q[3];
        scene_vertex(s, i, Q, rgba);
        if (fabs(Q[0] - P[0]) < 1e-6 && fabs(Q[1] - P[1]) < 1e-6 && fabs(Q[2] - P[2]) < 1e-6)
            return 1;
    }
    return 0;
}

static void test_replay_semantics(void)
{
    tb t;
    tb_init(&t);
    uint32_t leaf = tb_object(&t, "a_leaf", 0);
    tb_color(&t, 1, 0, 0, 1);     /* callee changes colour and matrix ... */
    tb_trans(&t, 100, 0, 0);
    tb_rect_z(&t, 0, 0, 1, 1, 0);
    tb_object(&t, "b_top", 1);
    tb_color(&t, 0, 0, 1, 1);
    tb_op0(&t, GLS_OP_PUSH);
    tb_trans(&t, 10, 0, 0);
    tb_scale(&t, 2, 2, 2);
    tb_call(&t, leaf);            /* leaf at 10 + 2*(100 + x) */
    tb_rect_z(&t, 0, 0, 1, 1, 0); /* ... which must not leak: blue, at 10 + 2x */
    tb_op0(&t, GLS_OP_POP);
    tb_rot(&t, 90, 0, 0, 1);      /* x -> y */
    gls_vec4 hw[3] = {{2, 0, 0, 2}, {4, 0, 0, 2}, {2, 2, 0, 2}}; /* w = 2: (1,0,0) (2,0,0) (1,1,0) */
    tb_prim4(&t, GLS_PRIM_TFAN, 3, hw, NULL, NULL);
    tb_rot(&t, 0, 0, 0, 0);       /* zero axis: no rotation */
    gls_vec4 qs[6] = {{0, 0, 5, 1}, {0, 1, 5, 1}, {1, 0, 5, 1}, {1, 1, 5, 1}, {2, 0, 5, 1}, {2, 1, 5, 1}};
    tb_prim4(&t, GLS_PRIM_QSTRIP, 6, qs, NULL, NULL);
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_flatten(b, &s, err, sizeof err) == 0);
    /* 2 rects (2 tris each) + 1 fan tri + 2 quads (4 tris) */
    CHECK(s.nverts == 3 * (2 + 2 + 1 + 4));
    uint8_t c[4];
    double p_leaf[3] = {10 + 2 * 100, 0, 0}, p_after[3] = {10, 0, 0};
    CHECK(find_vertex(&s, p_leaf, c) && c[0] == 255 && c[2] == 0);
    CHECK(find_vertex(&s, p_after, c) && c[0] == 0 && c[2] == 255);
    double p_w[3] = {0, 1, 0}, p_w2[3] = {0, 2, 0}, p_w3[3] = {-1, 1, 0}; /* rotated 90 about z */
    CHECK(find_vertex(&s, p_w, c) && find_vertex(&s, p_w2, c) && find_vertex(&s, p_w3, c));
    /* quad strip 0-1-3-2: (0,0)(0,1)(1,1)(1,0) -> rotated (0,0)(-1,0)(-1,1)(0,1) */
    double p_q[3] = {-1, 1, 5}, p_q2[3] = {-1, 2, 5};
    CHECK(find_vertex(&s, p_q, c) && find_vertex(&s, p_q2, c));
    gls_scene_free(&s);
    /* a library bundle cannot be played */
    b->top = GLS_NONE;
    CHECK(gls_scene_flatten(b, &s, err, sizeof err) == -1);
    CHECK(strstr(err, "library") != NULL);
    gls_bundle_free(b);
}

/* ---- determinism and texture modes ---------------------------------- */

static void test_deterministic_png(void)
{
    gls_camera c = proj_camera();
    double corners[5][4][3];
    gls_bundle *b = proj_scene(&c, corners);
    size_t n = (size_t)c.width * c.height * 4;
    uint8_t *a = malloc(n), *a2 = malloc(n);
    CHECK(tb_render(ctx, b, &c, 0, 0, a, NULL) == 0);
    CHECK(tb_render(ctx, b, &c, 0, 0, a2, NULL) == 0);
    CHECK(memcmp(a, a2, n) == 0);
    gls_buf p1 = {0}, p2 = {0};
    CHECK(gls_encode_png(a, c.width, c.height, &p1) == 0);
    CHECK(gls_encode_png(a2, c.width, c.height, &p2) == 0);
    CHECK(p1.len == p2.len && memcmp(p1.data, p2.data, p1.len) == 0);
    CHECK(p1.len > 8 && memcmp(p1.data, "\x89PNG", 4) == 0);
    free(p1.data), free(p2.data), free(a), free(a2);
    gls_bundle_free(b);
}

static void test_texture_modes(void)
{
    /* 8x8 texture of 4x4 quadrants: top red, green; bottom blue, hole
     * (alpha 0).  Quadrants, not single texels: llvmpipe's texture
     * filter blurs magnified textures by about a texel, so the checks
     * sample quadrant centres, two texels from any colour change. */
    static const uint8_t quad[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {0, 0, 0, 0}};
    uint8_t tex[8 * 8 * 4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++)
            memcpy(tex + 4 * (8 * y + x), quad[2 * (y / 4) + x / 4], 4);
    tb t;
    tb_init(&t);
    uint32_t ti = tb_texture(&t, "checker", 8, 8, tex);
    tb_object(&t, "scene", 1);
    tb_u1(&t, GLS_OP_TEXTURE, ti);
    gls_vec4 p[4] = {{-1, -1, 5, 1}, {1, -1, 5, 1}, {1, 1, 5, 1}, {-1, 1, 5, 1}};
    gls_st st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_REPLACE);
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    /* modulate with half grey, to the right */
    tb_color(&t, 0.5, 0.5, 0.5, 1);
    tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_MODULATE);
    tb_trans(&t, 2.5, 0, 0);
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    gls_bundle *b = tb_finish(&t);
    CHECK(b->features & GLS_FEAT_ALPHA_TEST);
    double T[3] = {-1.25, 0, 0};
    gls_camera c = tb_camera(200, 100, 200, 200, 99.5, 49.5, 0, I3, T, 0.1, 100);
    uint8_t *rgba = malloc((size_t)c.width * c.height * 4);
    CHECK(tb_render(ctx, b, &c, 0, 0, rgba, NULL) == 0);
    /* Sample at texel centres.  World (-0.5, -0.5) is texcoord (0.25,
     * 0.25), a quarter up from the texture image's BOTTOM edge (t = 0 is
     * the bottom row, spec/language.md): the blue quadrant.  The camera's
     * y points down, so world y = -0.5 is in the upper half of the image:
     * the texture appears upside down to this camera, as it should. */
    #define PIX(X, Y) (rgba + 4 * ((size_t)(lrint(c.cy + c.fy * (Y) / 5)) * c.width + (size_t)lrint(c.cx + c.fx * ((X) + T[0]) / 5)))
    const uint8_t *q = PIX(-0.5, -0.5);
    CHECK(q[0] == 0 && q[1] == 0 && q[2] == 255);
    q = PIX(0.5, -0.5); /* the hole: background */
    CHECK(q[0] == 0 && q[1] == 0 && q[2] == 0);
    q = PIX(-0.5, 0.5);
    CHECK(q[0] == 255 && q[1] == 0 && q[2] == 0);
    q = PIX(0.5, 0.5);
    CHECK(q[0] == 0 && q[1] == 255 && q[2] == 0);
    q = PIX(2.0, 0.5); /* modulated red: 128 or 127 */
    CHECK(q[0] >= 126 && q[0] <= 129 && q[1] == 0 && q[2] == 0);
    #undef PIX
    free(rgba);
    gls_bundle_free(b);
}

/* Render b through c with anisotropic filtering n (0: the renderer's
 * default, untouched). */
static int render_aniso(const gls_bundle *b, const gls_camera *c, uint32_t n, uint8_t *rgba)
{
    char err[256];
    gls_scene s;
    if (gls_scene_flatten(b, &s, err, sizeof err))
        return -1;
    gls_renderer *r = gls_renderer_create(ctx, b, &s, err, sizeof err);
    int rc = -1;
    if (r && !gls_renderer_set_size(r, c->width, c->height, err, sizeof err) &&
        (n == 0 || !gls_renderer_set_anisotropy(r, n, err, sizeof err))) {
        gls_render_pass(r, c, 0, 0);
        gls_render_read_rgba(r, rgba);
        rc = 0;
    }
    gls_renderer_destroy(r);
    gls_scene_free(&s);
    return rc;
}

static void test_anisotropy_off_by_default(void)
{
    /* a ground plane of fine stripes across the view, seen at a grazing
     * angle: isotropic mipmapping blurs them where anisotropic filtering
     * keeps them, so the two images differ */
    uint8_t tex[64 * 64 * 4];
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            uint8_t v = (x / 2) % 2 ? 255 : 0;
            uint8_t px[4] = {v, v, v, 255};
            memcpy(tex + 4 * (64 * y + x), px, 4);
        }
    tb t;
    tb_init(&t);
    uint32_t ti = tb_texture(&t, "stripes", 64, 64, tex);
    tb_object(&t, "scene", 1);
    tb_u1(&t, GLS_OP_TEXTURE, ti);
    tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_REPLACE);
    gls_vec4 p[4] = {{-4, 1, 1, 1}, {4, 1, 1, 1}, {4, 1, 60, 1}, {-4, 1, 60, 1}};
    gls_st st[4] = {{0, 0}, {8, 0}, {8, 60}, {0, 60}};
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    gls_bundle *b = tb_finish(&t);
    double T[3] = {0, 0, 0};
    gls_camera c = tb_camera(96, 64, 80, 80, 47.5, 31.5, 0, I3, T, 0.1, 100);
    size_t n = (size_t)c.width * c.height * 4;
    uint8_t *def = malloc(n), *one = malloc(n), *a16 = malloc(n);
    CHECK(render_aniso(b, &c, 0, def) == 0);
    CHECK(render_aniso(b, &c, 1, one) == 0);
    CHECK(render_aniso(b, &c, 16, a16) == 0);
    CHECK(memcmp(def, one, n) == 0);  /* the default is off */
    CHECK(memcmp(def, a16, n) != 0);  /* and 16 x is on */
    free(def), free(one), free(a16);
    gls_bundle_free(b);
}

static void test_output_names(void)
{
    char buf[64];
    CHECK(gls_output_path(buf, sizeof buf, "out", "left", "image", 0, "png") == 0);
    CHECK_STR(buf, "out/left/image_000000.png");
    CHECK(gls_output_path(buf, sizeof buf, "o", "c", "depth", 999999, "pfm") == 0);
    CHECK_STR(buf, "o/c/depth_999999.pfm");
    CHECK(gls_output_path(buf, sizeof buf, "o", "c", "points", 1234567, "ply") == 0);
    CHECK_STR(buf, "o/c/points_1234567.ply");
    CHECK(gls_output_path(buf, 10, "out", "left", "image", 0, "png") == -1);
}

/* ---- scenes for the end-to-end tests ------------------------------ */

static int write_scenes(const char *dir)
{
    char path[1024];
    gls_camera c = proj_camera();
    double corners[5][4][3];
    gls_bundle *b = proj_scene(&c, corners);
    snprintf(path, sizeof path, "%s/proj.glsb", dir);
    if (tb_write(b, path))
        return -1;
    snprintf(path, sizeof path, "%s/proj.cam", dir);
    if (tb_write_camera(&c, path))
        return -1;
    /* the corners, for OpenCV: one line per square, 4 x (x y z) */
    snprintf(path, sizeof path, "%s/proj_corners.txt", dir);
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    for (int k = 0; k < 5; k++) {
        fprintf(f, "%d %d %d", palette[k][0], palette[k][1], palette[k][2]);
        for (int i = 0; i < 4; i++)
            fprintf(f, " %.17g %.17g %.17g", corners[k][i][0], corners[k][i][1], corners[k][i][2]);
        fprintf(f, "\n");
    }
    fclose(f);
    gls_bundle_free(b);

    /* orientation: red square top-left, green bottom-right, at depth 4 */
    tb t;
    tb_init(&t);
    tb_object(&t, "scene", 1);
    tb_color(&t, 1, 0, 0, 1);
    tb_rect_z(&t, -1.9, -1.4, -0.6, -0.4, 4);
    tb_color(&t, 0, 1, 0, 1);
    tb_rect_z(&t, 0.9, 0.5, 1.8, 1.3, 4);
    tb_color(&t, 0, 0, 1, 1); /* a blue ground-like plane: for the PLY check */
    double g[4][3] = {{-3, 1.35, 2}, {3, 1.35, 2}, {3, 1.6, 12}, {-3, 1.6, 12}};
    tb_poly(&t, 4, (const double(*)[3])g);
    b = tb_finish(&t);
    snprintf(path, sizeof path, "%s/orient.glsb", dir);
    if (tb_write(b, path))
        return -1;
    double T[3] = {0, 0, 0};
    gls_camera co = tb_camera(160, 120, 100, 100, 79.5, 59.5, 0, I3, T, 0.1, 100);
    snprintf(path, sizeof path, "%s/orient.cam", dir);
    if (tb_write_camera(&co, path))
        return -1;
    /* a library bundle */
    b->top = GLS_NONE;
    snprintf(path, sizeof path, "%s/library.glsb", dir);
    if (tb_write(b, path))
        return -1;
    gls_bundle_free(b);

    /* stereo cameras for the same orient scene */
    gls_camera l, r;
    stereo_cameras(&l, &r);
    snprintf(path, sizeof path, "%s/left.cam", dir);
    if (tb_write_camera(&l, path))
        return -1;
    snprintf(path, sizeof path, "%s/right.cam", dir);
    return tb_write_camera(&r, path);
}

/* usage: test_player [--backend B] [--write DIR]; the backend is auto
 * unless given (tests/e2e/backends.sh runs the tests through each). */
int main(int argc, char **argv)
{
    gls_backend backend = GLS_BACKEND_AUTO;
    if (argc >= 3 && strcmp(argv[1], "--backend") == 0) {
        if (gls_backend_parse(argv[2], &backend)) {
            printf("FAIL test_player: unknown backend %s\n", argv[2]);
            return 1;
        }
        argc -= 2, argv += 2;
    }
    ctx = tb_glctx(backend, "test_player");
    if (argc == 3 && strcmp(argv[1], "--write") == 0) {
        int r = write_scenes(argv[2]);
        gls_glctx_destroy(ctx);
        if (r)
            printf("FAIL write_scenes: cannot write to %s\n", argv[2]);
        return r ? 1 : 0;
    }
    RUN(test_projection_skew_offcentre);
    RUN(test_projection_detects_shift);
    RUN(test_depth_fronto_parallel);
    RUN(test_depth_slanted_plane);
    RUN(test_depth_near_limit);
    RUN(test_points_on_plane);
    RUN(test_far_from_origin_identical);
    RUN(test_far_from_origin_generic);
    RUN(test_stereo_pair);
    RUN(test_replay_semantics);
    RUN(test_deterministic_png);
    RUN(test_texture_modes);
    RUN(test_anisotropy_off_by_default);
    RUN(test_output_names);
    gls_glctx_destroy(ctx);
    CHECK_EXIT();
}
