/* make bench-aa: what sub-pixel accuracy costs.
 *
 *   aa_bench table W H N...        one line per N, filter and output:
 *                                  "N filter output seconds rms max samples/s"
 *   aa_bench breakdown W H N TILES SERIAL
 *                                  per-sample milliseconds of drawing,
 *                                  read-back and accumulation
 *
 * The scene and the exact answer are bench/aa_scene.h.  Seconds per
 * frame include the sample plan, every pass, the accumulation and the
 * conversion to the output format (not the file encoding). */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "aa_render.h"
#include "aa_scene.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct {
    gls_glctx *ctx;
    gls_scene sc;
    gls_renderer *r;
    as_scene s;
    gls_camera cam;
} bench;

static int setup(bench *b, uint32_t w, uint32_t h)
{
    char err[256];
    b->ctx = gls_glctx_create(GLS_BACKEND_AUTO, err, sizeof err);
    if (!b->ctx) {
        fprintf(stderr, "aa_bench: %s\n", err);
        return -1;
    }
    as_layout(&b->s, w, h, 4, 3, h / 4.0);
    b->cam = as_camera(&b->s, 1, 100);
    gls_bundle *bu = as_bundle(&b->s, &b->cam);
    if (gls_scene_flatten(bu, &b->sc, err, sizeof err) ||
        !(b->r = gls_renderer_create(b->ctx, bu, &b->sc, err, sizeof err)) ||
        gls_renderer_set_size(b->r, w, h, err, sizeof err)) {
        fprintf(stderr, "aa_bench: %s\n", err);
        return -1;
    }
    gls_bundle_free(bu);
    return 0;
}

/* Render with plan options o; fills acc; returns seconds or -1. */
static double render(bench *b, const gls_aa_opts *o, const gls_aa_run_opts *ro, gls_accum *acc, gls_aa_stats *st)
{
    char err[256];
    gls_aa_plan p;
    double t0 = now();
    if (gls_aa_plan_init(&p, o, err, sizeof err) || gls_accum_init(acc, b->s.w, b->s.h, gls_aa_weighted(&p), 0) ||
        gls_aa_render(b->r, &b->cam, &p, ro, acc, st, err, sizeof err)) {
        fprintf(stderr, "aa_bench: %s\n", err);
        return -1;
    }
    return now() - t0;
}

static int table(bench *b, int argc, char **argv)
{
    size_t n = (size_t)b->s.w * b->s.h;
    double *img = malloc(n * sizeof *img);
    uint8_t *rgba = malloc(n * 4);
    uint16_t *rgb16 = malloc(n * 6);
    float *rgbf = malloc(n * 12);
    if (!img || !rgba || !rgb16 || !rgbf)
        return 1;
    printf("# N filter output seconds_per_frame edge_rms_px edge_max_px row_rms_px row_max_px samples_per_s\n");
    {
        /* warm-up: llvmpipe compiles its shaders on the first draw; that
           one-time cost belongs to no row of the table */
        gls_aa_opts o = gls_aa_defaults();
        o.n = 2;
        gls_aa_run_opts ro = {0, 0, NULL, NULL, NULL, NULL};
        gls_accum acc;
        gls_aa_stats st;
        if (render(b, &o, &ro, &acc, &st) < 0)
            return 1;
        gls_accum_free(&acc);
    }
    for (int a = 0; a < argc; a++) {
        uint32_t N = (uint32_t)atoi(argv[a]);
        for (int f = 0; f < 2; f++) {
            gls_aa_opts o = gls_aa_defaults();
            o.n = N;
            o.filter = f ? GLS_AA_GAUSS : GLS_AA_BOX;
            gls_aa_run_opts ro = {0, 0, NULL, NULL, NULL, NULL};
            gls_accum acc;
            gls_aa_stats st;
            double t = render(b, &o, &ro, &acc, &st);
            if (t < 0)
                return 1;
            /* short renders: best of up to 5, so noise from other
               processes does not dominate the figure */
            for (int rep = 1; rep < 5 && t < 0.5; rep++) {
                gls_accum again;
                gls_aa_stats st2;
                double t2 = render(b, &o, &ro, &again, &st2);
                gls_accum_free(&again);
                if (t2 < 0)
                    return 1;
                if (t2 < t)
                    t = t2;
            }
            for (int out = 0; out < 3; out++) {
                double t0 = now();
                if (out == 0)
                    gls_accum_rgba8(&acc, rgba);
                else if (out == 1)
                    gls_accum_rgb16(&acc, rgb16);
                else
                    gls_accum_rgbf(&acc, rgbf);
                double tc = now() - t0;
                for (size_t i = 0; i < n; i++)
                    img[i] = out == 0 ? rgba[4 * i] / 255.0 : out == 1 ? rgb16[3 * i] / 65535.0 : rgbf[3 * i];
                as_err e = as_edge_error(&b->s, img, f, o.sigma);
                printf("%u %s %s %.4f %.6f %.6f %.6f %.6f %.0f\n", N, f ? "gauss" : "box",
                       out == 0 ? "png8" : out == 1 ? "png16" : "pfm", t + tc, e.rms, e.max, e.row_rms, e.row_max,
                       (double)st.samples / st.total_s);
                fflush(stdout);
            }
            gls_accum_free(&acc);
        }
    }
    free(img), free(rgba), free(rgb16), free(rgbf);
    return 0;
}

static int breakdown(bench *b, uint32_t N, uint32_t tiles, int serial)
{
    gls_aa_opts o = gls_aa_defaults();
    o.n = N;
    gls_aa_run_opts ro = {tiles, serial, NULL, NULL, NULL, NULL};
    gls_accum acc;
    gls_aa_stats st;
    if (render(b, &o, &ro, &acc, &st) < 0)
        return 1;
    double k = 1e3 / (double)st.samples;
    printf("N %u mosaic %ux%u %s: per sample %.3f ms = draw %.3f + read-back %.3f + accumulate %.3f ms "
           "(%llu passes)\n",
           N, st.kx, st.ky, serial ? "serial" : "overlapped", st.total_s * k, st.draw_s * k, st.read_s * k,
           st.accum_s * k, (unsigned long long)st.passes);
    gls_accum_free(&acc);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 5) {
        fprintf(stderr, "usage: aa_bench table W H N... | breakdown W H N TILES SERIAL\n");
        return 2;
    }
    bench b;
    memset(&b, 0, sizeof b);
    if (setup(&b, (uint32_t)atoi(argv[2]), (uint32_t)atoi(argv[3])))
        return 1;
    int rc;
    if (strcmp(argv[1], "table") == 0)
        rc = table(&b, argc - 4, argv + 4);
    else if (strcmp(argv[1], "breakdown") == 0 && argc == 7)
        rc = breakdown(&b, (uint32_t)atoi(argv[4]), (uint32_t)atoi(argv[5]), atoi(argv[6]));
    else
        rc = 2;
    gls_renderer_destroy(b.r);
    gls_scene_free(&b.sc);
    gls_glctx_destroy(b.ctx);
    return rc;
}
