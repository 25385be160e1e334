/* Anti-aliasing tests: the accumulator's exactness at the 4096 x 4096
 * limit (synthetic sample streams), Gaussian weights, constant colours,
 * the jitter's sign, edge error against the exact answer of
 * bench/aa_scene.h, the rasteriser's vertex snapping, and hard geometry
 * (far from the origin, deep depth ranges, near-plane crossings, behind
 * the camera, degenerate and grazing polygons, principal point outside
 * the image).  A list of independent tests, one function each: long on
 * purpose. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "aa_render.h"
#include "check.h"
#include <GL/gl.h>
#include "glcalls.h"
#include "aa_scene.h"

static gls_glctx *ctx;

/* Render bundle b through c with the given AA options into rgbf (w*h*3);
 * optionally also 8- and 16-bit results.  0 on success. */
static int aa_render(const gls_bundle *b, const gls_camera *c, const gls_aa_opts *o, float *rgbf, uint8_t *rgba8,
                     uint16_t *rgb16)
{
    char err[256];
    gls_scene s;
    gls_aa_plan p;
    gls_accum acc;
    if (gls_aa_plan_init(&p, o, err, sizeof err) || gls_scene_flatten(b, &s, err, sizeof err)) {
        printf("  %s\n", err);
        return -1;
    }
    gls_renderer *r = gls_renderer_create(ctx, b, &s, err, sizeof err);
    int rc = -1;
    if (!r || gls_accum_init(&acc, c->width, c->height, gls_aa_weighted(&p), 0)) {
        printf("  renderer: %s\n", err);
        goto out;
    }
    gls_aa_run_opts ro = {0, 0, NULL, NULL, NULL, NULL};
    if (gls_aa_render(r, c, &p, &ro, &acc, NULL, err, sizeof err)) {
        printf("  render: %s\n", err);
        gls_accum_free(&acc);
        goto out;
    }
    if (rgbf)
        gls_accum_rgbf(&acc, rgbf);
    if (rgba8)
        gls_accum_rgba8(&acc, rgba8);
    if (rgb16)
        gls_accum_rgb16(&acc, rgb16);
    gls_accum_free(&acc);
    rc = 0;
out:
    gls_renderer_destroy(r);
    gls_scene_free(&s);
    return rc;
}

/* gls_accum_add_rows (a rolling shutter's band of one sample a pixel) and
 * gls_accum_add_tiles_rows (of jittered passes, several samples a call):
 * the rows asked for are exactly gls_accum_add's sums and mixed pixels,
 * unweighted and weighted, first sample and later; the other rows keep
 * what they held; samples and wsum counted alike. */
static void test_accum_add_rows(void)
{
    enum { W = 7, H = 9, Y0 = 3, ROWS = 4 };
    uint8_t img[2][W * H * 4];
    for (size_t i = 0; i < sizeof img[0]; i++) {
        img[0][i] = (uint8_t)(i * 37 + 11);
        img[1][i] = (uint8_t)(i % 5 ? img[0][i] : i * 53 + 7); /* some pixels differ */
    }
    for (int pass = 0; pass < 4; pass++) {
        int weighted = pass & 1, tiles = pass >= 2; /* tiles: both samples in one call */
        gls_accum whole, rows;
        CHECK(gls_accum_init(&whole, W, H, weighted, 1) == 0);
        CHECK(gls_accum_init(&rows, W, H, weighted, 1) == 0);
        /* the rows outside Y0..Y0+ROWS-1 hold something of their own */
        for (size_t i = 0; i < 4 * (size_t)W * H; i++) {
            if (i >= 4 * (size_t)W * Y0 && i < 4 * (size_t)W * (Y0 + ROWS))
                continue;
            if (weighted)
                rows.sum64[i] = 1000 + i;
            else
                rows.sum32[i] = (uint32_t)(1000 + i);
        }
        uint64_t wk[2];
        for (int k = 0; k < 2; k++) {
            wk[k] = weighted ? 3 + 2 * (uint64_t)k : 1;
            gls_accum_add(&whole, img[k], 4 * W, wk[k]);
            if (!tiles) {
                gls_accum_add_rows(&rows, Y0, ROWS, img[k], 4 * W, wk[k]);
                CHECK(rows.samples == whole.samples && rows.wsum == whole.wsum);
            }
        }
        if (tiles) {
            const uint8_t *tile[2] = {img[0], img[1]};
            gls_accum_add_tiles_rows(&rows, Y0, ROWS, tile, 4 * W, 2, wk);
            CHECK(rows.samples == whole.samples && rows.wsum == whole.wsum);
        }
        int same = 1, kept = 1;
        for (size_t i = 0; i < (size_t)W * H; i++) {
            int in = i >= (size_t)W * Y0 && i < (size_t)W * (Y0 + ROWS);
            for (int ch = 0; ch < 4; ch++) {
                size_t j = 4 * i + ch;
                uint64_t a = weighted ? whole.sum64[j] : whole.sum32[j];
                uint64_t b = weighted ? rows.sum64[j] : rows.sum32[j];
                if (in)
                    same &= a == b;
                else
                    kept &= b == 1000 + j;
            }
            if (in)
                same &= whole.mixed[i] == rows.mixed[i] && whole.first[i] == rows.first[i];
            else
                kept &= rows.mixed[i] == 0;
        }
        CHECK(same);
        CHECK(kept);
        gls_accum_free(&whole);
        gls_accum_free(&rows);
    }
}

/* ---- accumulator ---------------------------------------------------- */

/* 4096^2 samples of the extreme values, unweighted, 256 per call: every
 * sum must be exactly 2^24 * v and every output exactly v. */
static void test_accum_limit_box(void)
{
    static const uint8_t px[16] = {0, 1, 254, 255, 255, 255, 255, 255, 128, 127, 3, 200, 17, 34, 51, 68};
    gls_accum a;
    CHECK(gls_accum_init(&a, 4, 1, 0, 1) == 0);
    const uint8_t *tiles[GLS_ACCUM_MAX_TILES];
    for (unsigned t = 0; t < GLS_ACCUM_MAX_TILES; t++)
        tiles[t] = px;
    for (uint64_t k = 0; k < GLS_ACCUM_MAX_SAMPLES; k += GLS_ACCUM_MAX_TILES)
        gls_accum_add_tiles(&a, tiles, 16, GLS_ACCUM_MAX_TILES, NULL);
    CHECK(a.samples == 16777216u && a.wsum == 16777216u);
    for (int i = 0; i < 16; i++)
        CHECK_MSG(a.sum32[i] == 16777216u * px[i], "sum %d = %u", i, a.sum32[i]);
    uint8_t o8[16];
    uint16_t o16[12];
    float of[12];
    gls_accum_rgba8(&a, o8);
    gls_accum_rgb16(&a, o16);
    gls_accum_rgbf(&a, of);
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++) {
            CHECK(o8[4 * i + c] == px[4 * i + c]);
            CHECK(o16[3 * i + c] == px[4 * i + c] * 257);
            CHECK(of[3 * i + c] == (float)(px[4 * i + c] / 255.0));
        }
    for (int i = 0; i < 4; i++)
        CHECK(a.mixed[i] == 0);
    gls_accum_free(&a);
}

/* The Gaussian at N = 4096: 16M distinct weights, all added to a pixel
 * of 255 and one of 1: the sums are exactly 255 * wsum and wsum. */
static void test_accum_limit_gauss(void)
{
    char err[128];
    gls_aa_opts o = gls_aa_defaults();
    o.n = 4096;
    o.filter = GLS_AA_GAUSS;
    o.pattern = GLS_AA_GRID; /* the N x N window (the lattice's would be 25 x 4096^2) */
    gls_aa_plan p;
    CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
    CHECK(p.wsum <= (1ull << 52) && p.wsum > (1ull << 52) - p.count);
    static const uint8_t px[8] = {255, 1, 0, 255, 255, 255, 255, 255};
    gls_accum a;
    CHECK(gls_accum_init(&a, 2, 1, 1, 0) == 0);
    const uint8_t *tiles[GLS_ACCUM_MAX_TILES];
    uint64_t w[GLS_ACCUM_MAX_TILES];
    for (unsigned t = 0; t < GLS_ACCUM_MAX_TILES; t++)
        tiles[t] = px;
    for (uint64_t k = 0; k < p.count; k += GLS_ACCUM_MAX_TILES) {
        for (unsigned t = 0; t < GLS_ACCUM_MAX_TILES; t++) {
            double du, dv;
            gls_aa_sample(&p, k + t, &du, &dv, &w[t]);
        }
        gls_accum_add_tiles(&a, tiles, 8, GLS_ACCUM_MAX_TILES, w);
    }
    CHECK(a.wsum == p.wsum);
    CHECK(a.sum64[0] == 255 * p.wsum && a.sum64[1] == p.wsum && a.sum64[2] == 0);
    uint8_t o8[8];
    uint16_t o16[6];
    float of[6];
    gls_accum_rgba8(&a, o8);
    gls_accum_rgb16(&a, o16);
    gls_accum_rgbf(&a, of);
    CHECK(o8[0] == 255 && o8[1] == 1 && o8[2] == 0 && o16[0] == 65535 && o16[1] == 257);
    CHECK(of[0] == 1.0f && of[1] == (float)(1 / 255.0) && of[2] == 0.0f);
    gls_accum_free(&a);
}

/* Gaussian weights sum to one to double precision for every window
 * size, both patterns, several sigmas; the integer weights sum to the
 * plan's wsum and the samples stay inside the window. */
static void test_gauss_weights_sum(void)
{
    char err[128];
    static const uint32_t ns[] = {1, 2, 3, 4, 5, 7, 8, 16, 31, 64, 100, 128, 256, 512};
    for (int pat = 0; pat < 2; pat++)
        for (int si = 0; si < 3; si++)
            for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++) {
                gls_aa_opts o = gls_aa_defaults();
                o.n = ns[i];
                o.filter = GLS_AA_GAUSS;
                o.sigma = si == 0 ? 0.5 : si == 1 ? 0.3 : 1.7;
                o.pattern = pat ? GLS_AA_STRATIFIED : GLS_AA_GRID;
                o.seed = 12345;
                gls_aa_plan p;
                CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
                double s = 0, c = 0;
                uint64_t ws = 0;
                double lim = GLS_AA_GAUSS_SPAN * o.sigma;
                int outside = 0;
                for (uint64_t k = 0; k < p.count; k++) {
                    double y = gls_aa_weight_exact(&p, k) - c, t = s + y;
                    c = (t - s) - y;
                    s = t;
                    double du, dv;
                    uint64_t w;
                    gls_aa_sample(&p, k, &du, &dv, &w);
                    ws += w;
                    outside += fabs(du) > lim || fabs(dv) > lim;
                }
                CHECK_MSG(fabs(s - 1) <= 4 * 0x1.0p-53, "N %u sigma %g: sum - 1 = %g", o.n, o.sigma, s - 1);
                CHECK(ws == p.wsum);
                CHECK(outside == 0);
            }
}

/* --subpixel: the smallest N whose step is at most the accuracy. */
static void test_subpixel_rule(void)
{
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_GRID, 0.5, 1.0 / 256) == 256);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_GRID, 0.5, 0.1) == 10);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_GRID, 0.5, 0.3) == 4);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_GRID, 0.5, 1) == 1);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_GAUSS, GLS_AA_GRID, 0.5, 1.0 / 256) == 768);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_GRID, 0.5, 1.0 / 4096) == 4096);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_GRID, 0.5, 1.0 / 5000) == 0);
    /* the lattice's samples are per pixel area whatever the filter */
    CHECK(gls_aa_n_for_accuracy(GLS_AA_GAUSS, GLS_AA_LATTICE, 0.5, 1.0 / 256) == 256);
    CHECK(gls_aa_n_for_accuracy(GLS_AA_BOX, GLS_AA_LATTICE, 0.5, 1.0 / 16) == 16);
}

/* ---- rendering ------------------------------------------------------ */

/* A scene of one colour everywhere stays exactly that colour at every N,
 * filter and pattern, in every output. */
static void test_constant_colour(void)
{
    gls_bundle *b = tb_wall();
    gls_camera c = tb_front_camera(24, 16);
    size_t n = 24 * 16;
    float *f = malloc(n * 12);
    uint8_t *p8 = malloc(n * 4);
    uint16_t *p16 = malloc(n * 6);
    static const uint32_t ns[] = {1, 2, 3, 4, 7, 8, 16, 33};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++)
        for (int fl = 0; fl < 2; fl++)
            for (int pat = 0; pat < 2; pat++) {
                gls_aa_opts o = gls_aa_defaults();
                o.n = ns[i];
                o.filter = fl ? GLS_AA_GAUSS : GLS_AA_BOX;
                o.pattern = pat ? GLS_AA_STRATIFIED : GLS_AA_GRID;
                o.seed = 7;
                CHECK(aa_render(b, &c, &o, f, p8, p16) == 0);
                int bad = 0;
                for (size_t k = 0; k < n; k++) {
                    static const int want[3] = {77, 154, 231};
                    for (int ch = 0; ch < 3; ch++)
                        bad += p8[4 * k + ch] != want[ch] || p16[3 * k + ch] != want[ch] * 257 ||
                               f[3 * k + ch] != (float)(want[ch] / 255.0);
                }
                CHECK_MSG(bad == 0, "N %u filter %d pattern %d: %d values off", o.n, fl, pat, bad);
            }
    free(f), free(p8), free(p16);
    gls_bundle_free(b);
}

/* The jitter's sign: pixel (u, v) samples the scene at (u + du, v + dv).
 * A white half-plane x < 10.2 px (left of column 10's centre + 0.2); with
 * a stratified (asymmetric) pattern pixel 10's value must be exactly the
 * fraction of sample offsets with 10 + du < 10.2.  The opposite sign
 * counts 10 - du < 10.2 instead, a different number for this seed. */
static void test_jitter_sign(void)
{
    gls_camera c = tb_front_camera(20, 4);
    double z = 5, xe = (10.2 - c.cx) * z / c.fx;
    tb t;
    tb_init(&t);
    tb_object(&t, "half", 1);
    tb_color(&t, 1, 1, 1, 1);
    tb_rect_z(&t, -100, -100, xe, 100, z);
    gls_bundle *b = tb_finish(&t);
    gls_aa_opts o = gls_aa_defaults();
    o.n = 4;
    o.pattern = GLS_AA_STRATIFIED;
    char err[64];
    gls_aa_plan p;
    int in = 0, in_wrong = 0, close = 1;
    /* the first seed whose samples tell the signs apart and keep clear of
     * the edge by more than the snapping (deterministic) */
    for (o.seed = 1; o.seed < 1000 && (close || in == in_wrong); o.seed++) {
        CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
        in = in_wrong = close = 0;
        for (uint64_t k = 0; k < p.count; k++) {
            double du, dv;
            uint64_t w;
            gls_aa_sample(&p, k, &du, &dv, &w);
            in += 10 + du < 10.2;
            in_wrong += 10 - du < 10.2;
            close += fabs(10 + du - 10.2) < 1.0 / 128; /* within snapping reach */
        }
    }
    o.seed--;
    CHECK(close == 0 && in != in_wrong);
    uint8_t p8[20 * 4 * 4];
    uint16_t p16[20 * 4 * 3];
    CHECK(aa_render(b, &c, &o, NULL, p8, p16) == 0);
    unsigned want = (unsigned)((in * 65535 * 2 + 16) / 32);
    CHECK_MSG(p16[3 * (20 + 10)] == want, "pixel 10: %u, expected %u (%d of 16 samples), wrong sign gives %d",
              p16[3 * (20 + 10)], want, in, in_wrong);
    CHECK(p8[4 * (20 + 9)] == 255 && p8[4 * (20 + 11)] == 0);
    gls_bundle_free(b);
}

/* Edge error against the exact answer: falls with N for both filters and
 * patterns; at N = 16 with 16-bit output the box filter's RMS edge error
 * is at most 1/256 px.  (The Gaussian's window is 6 sigma = 3 px wide, so
 * its step at N = 16 is 3/16 px: it needs about 3x the N of the box for
 * the same step; make bench-aa shows the whole curve.) */
static void test_edge_error_falls(void)
{
    as_scene s;
    as_layout(&s, 192, 144, 3, 2, 40);
    gls_camera c = as_camera(&s, 1, 100);
    gls_bundle *b = as_bundle(&s, &c);
    size_t n = (size_t)s.w * s.h;
    uint16_t *p16 = malloc(n * 6);
    double *img = malloc(n * sizeof *img);
    static const uint32_t ns[] = {1, 4, 16};
    for (int fl = 0; fl < 2; fl++)
        for (int pat = 0; pat < 2; pat++) {
            double prev = 1e9, prow = 1e9;
            for (size_t i = 0; i < 3; i++) {
                gls_aa_opts o = gls_aa_defaults();
                o.n = ns[i];
                o.filter = fl ? GLS_AA_GAUSS : GLS_AA_BOX;
                o.pattern = pat ? GLS_AA_STRATIFIED : GLS_AA_GRID;
                CHECK(aa_render(b, &c, &o, NULL, NULL, p16) == 0);
                for (size_t k = 0; k < n; k++)
                    img[k] = p16[3 * k] / 65535.0;
                as_err e = as_edge_error(&s, img, fl, o.sigma);
                printf("  %-5s %-10s N %2u: edge rms %.5f max %.5f, row rms %.5f max %.5f px (%ld edges)\n",
                       fl ? "gauss" : "box", pat ? "stratified" : "grid", o.n, e.rms, e.max, e.row_rms, e.row_max,
                       e.edges);
                CHECK(e.edges >= 20);
                CHECK_MSG(e.rms < prev && e.row_rms < prow, "N %u: error did not fall", o.n);
                prev = e.rms, prow = e.row_rms;
                if (o.n == 16 && !fl)
                    CHECK_MSG(e.rms <= 1.0 / 256, "box N 16: edge rms %g > 1/256", e.rms);
            }
        }
    free(p16), free(img);
    gls_bundle_free(b);
}

/* llvmpipe snaps vertices to 1/2^GL_SUBPIXEL_BITS of a pixel (8 bits
 * here).  Sweep a vertical edge across pixel 1's centre in 1/4096-px
 * steps with one plain pass each: where the pixel turns on is the edge's
 * snapped position; its distance from the exact crossing is at most half
 * a snap step, 1/512 px, below the 1/256 bound.  (The anti-aliased edge
 * error above includes this: it is the floor the grid pattern reaches at
 * large N, where the offsets are multiples of the snap step and every
 * sample snaps a vertex the same way.) */
static void test_snapping_bias(void)
{
    GLint bits = 0;
    glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
    /* bench/aa_scene.h: 81 positions of the edge, 1/4096 px apart */
    double worst = as_snap_worst(ctx, 1);
    printf("  GL_SUBPIXEL_BITS %d: largest edge displacement by snapping %.6f px (bound %.6f)\n", bits, worst,
           bits > 0 ? 0.5 / (1 << bits) : 0.0);
    CHECK_MSG(worst >= 0 && worst <= 1.0 / 512 + 1e-9, "snapping moved the edge by %g px", worst);
}

/* Hard cases: no NaN, no crash, values in [0, 1]; where the answer is
 * known (far from the origin, deep depth range, principal point outside
 * the image) the edge error stays within the simple case's bound. */
static double scene_edge_rms(as_scene *s, const gls_camera *c, int gauss, float *f, double *img)
{
    gls_bundle *b = as_bundle(s, c);
    gls_aa_opts o = gls_aa_defaults();
    o.n = 16;
    o.filter = gauss ? GLS_AA_GAUSS : GLS_AA_BOX;
    double r = 1e9;
    if (aa_render(b, c, &o, f, NULL, NULL) == 0) {
        for (size_t k = 0; k < (size_t)s->w * s->h; k++)
            img[k] = f[3 * k];
        r = as_edge_error(s, img, gauss, o.sigma).rms;
    }
    gls_bundle_free(b);
    return r;
}

static int finite_unit(const float *f, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!(f[i] >= 0 && f[i] <= 1))
            return 0;
    return 1;
}

static void test_hard_cases(void)
{
    uint32_t W = 128, H = 96;
    size_t n = (size_t)W * H;
    float *f = malloc(n * 12);
    double *img = malloc(n * sizeof *img);
    for (int g = 0; g < 2; g++) {
        as_scene s;
        as_layout(&s, W, H, 2, 2, 30);
        gls_camera c = as_camera(&s, 1, 100);
        double base = scene_edge_rms(&s, &c, g, f, img);
        CHECK(finite_unit(f, n * 3));
        /* far from the origin */
        as_scene far = s;
        far.origin[0] = 1e7, far.origin[1] = -1e7, far.origin[2] = 1e7;
        gls_camera cf = as_camera(&far, 1, 100);
        double e = scene_edge_rms(&far, &cf, g, f, img);
        CHECK(finite_unit(f, n * 3));
        CHECK_MSG(e <= base + 1e-3, "far: %g vs %g", e, base);
        /* near and far 1e5 apart */
        gls_camera cd = as_camera(&s, 0.5, 1e5 + 0.5);
        e = scene_edge_rms(&s, &cd, g, f, img);
        CHECK(finite_unit(f, n * 3));
        CHECK_MSG(e <= base + 1e-3, "depth range: %g vs %g", e, base);
        /* principal point outside the image: shift cx, cy and the squares */
        as_scene off = s;
        gls_camera co = as_camera(&off, 1, 100);
        co.cx = -300.25, co.cy = 400.5;
        e = scene_edge_rms(&off, &co, g, f, img);
        CHECK(finite_unit(f, n * 3));
        CHECK_MSG(e <= base + 1e-3, "principal point outside: %g vs %g", e, base);
        printf("  %s N 16 edge rms: simple %.5f, far %.5f\n", g ? "gauss" : "box", base, e);

        /* polygons crossing the near plane, behind the camera, degenerate,
         * grazing: only sanity (no NaN, no crash, values in range) */
        tb t;
        tb_init(&t);
        tb_object(&t, "bad", 1);
        tb_color(&t, 1, 0.5, 0.25, 1);
        double cross[3][3] = {{-1, -1, -3}, {1, -1, 5}, {0, 1, 5}};    /* through z = near */
        double behind[3][3] = {{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}}; /* all behind */
        double zero[3][3] = {{0, 0, 5}, {1, 1, 5}, {2, 2, 5}};         /* collinear */
        double point[3][3] = {{0.1, 0.1, 5}, {0.1, 0.1, 5}, {0.1, 0.1, 5}};
        double graze[4][3] = {{-2, 0.3, 1.1}, {2, 0.3, 1.1}, {2, 0.3 + 1e-9, 90}, {-2, 0.3 + 1e-9, 90}};
        tb_poly(&t, 3, (const double(*)[3])cross);
        tb_poly(&t, 3, (const double(*)[3])behind);
        tb_poly(&t, 3, (const double(*)[3])zero);
        tb_poly(&t, 3, (const double(*)[3])point);
        tb_poly(&t, 4, (const double(*)[3])graze);
        gls_bundle *b = tb_finish(&t);
        gls_aa_opts o = gls_aa_defaults();
        o.n = 8;
        o.filter = g ? GLS_AA_GAUSS : GLS_AA_BOX;
        o.pattern = GLS_AA_STRATIFIED;
        CHECK(aa_render(b, &c, &o, f, NULL, NULL) == 0);
        CHECK(finite_unit(f, n * 3));
        co = c;
        co.cx = 1e4, co.cy = -1e4;
        CHECK(aa_render(b, &co, &o, f, NULL, NULL) == 0);
        CHECK(finite_unit(f, n * 3));
        gls_bundle_free(b);
    }
    free(f), free(img);
}

/* Mosaic passes give the same image as one sample per pass, and two
 * stratified runs with one seed give identical images. */
static void test_mosaic_same_as_single(void)
{
    as_scene s;
    as_layout(&s, 64, 48, 2, 1, 20);
    gls_camera c = as_camera(&s, 1, 100);
    gls_bundle *b = as_bundle(&s, &c);
    char err[128];
    gls_scene sc;
    CHECK(gls_scene_flatten(b, &sc, err, sizeof err) == 0);
    gls_renderer *r = gls_renderer_create(ctx, b, &sc, err, sizeof err);
    CHECK(r != NULL);
    gls_aa_opts o = gls_aa_defaults();
    o.n = 7;
    o.filter = GLS_AA_GAUSS;
    o.pattern = GLS_AA_STRATIFIED;
    o.seed = 99;
    gls_aa_plan p;
    CHECK(gls_aa_plan_init(&p, &o, err, sizeof err) == 0);
    uint16_t out[3][64 * 48 * 3];
    static const uint32_t tiles[3] = {1, 5, 16};
    for (int i = 0; i < 3 && r; i++) {
        gls_accum a;
        CHECK(gls_accum_init(&a, 64, 48, 1, 0) == 0);
        gls_aa_run_opts ro = {tiles[i], i == 2, NULL, NULL, NULL, NULL};
        gls_aa_stats st;
        CHECK(gls_aa_render(r, &c, &p, &ro, &a, &st, err, sizeof err) == 0);
        CHECK(st.samples == 49 && st.kx * st.ky >= tiles[i] && st.passes == (49 + st.kx * st.ky - 1) / (st.kx * st.ky));
        gls_accum_rgb16(&a, out[i]);
        gls_accum_free(&a);
    }
    CHECK(memcmp(out[0], out[1], sizeof out[0]) == 0);
    CHECK(memcmp(out[0], out[2], sizeof out[0]) == 0);
    gls_renderer_destroy(r);
    gls_scene_free(&sc);
    gls_bundle_free(b);
}

int main(void)
{
    ctx = tb_glctx(GLS_BACKEND_AUTO, "test_aa");
    RUN(test_accum_add_rows);
    RUN(test_accum_limit_box);
    RUN(test_accum_limit_gauss);
    RUN(test_gauss_weights_sum);
    RUN(test_subpixel_rule);
    RUN(test_constant_colour);
    RUN(test_jitter_sign);
    RUN(test_edge_error_falls);
    RUN(test_snapping_bias);
    RUN(test_hard_cases);
    RUN(test_mosaic_same_as_single);
    gls_glctx_destroy(ctx);
    CHECK_EXIT();
}
