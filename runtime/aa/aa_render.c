/* gls_aa_render (aa_render.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "aa_render.h"
#include "progress_line.h"
#include "units.h"

/* Mosaic budget in pixels.  Larger mosaics amortise the clear, the
 * rasteriser start-up and the read-back over more samples, but past a
 * few Mpixel the read-back buffers fall out of cache; measured with make
 * bench-aa (spec/antialiasing.md "Cost"). */
#define MOSAIC_PIXELS (1u << 19)


void gls_aa_mosaic_shape(const gls_renderer *r, uint32_t w, uint32_t h, uint64_t samples, uint32_t tiles,
                         uint32_t *kx, uint32_t *ky)
{
    /* no renderer (--explain without GL): the camera size limit */
    uint32_t maxd = r ? gls_renderer_max_dim(r) : GLS_CAMERA_MAX_DIM;
    uint64_t t = tiles;
    if (!t) {
        t = MOSAIC_PIXELS / ((uint64_t)w * h);
        if (t < 1)
            t = 1;
    }
    if (t > samples)
        t = samples;
    if (t > GLS_ACCUM_MAX_TILES)
        t = GLS_ACCUM_MAX_TILES;
    /* as square as the GL size limit allows: columns first */
    uint32_t cx = (uint32_t)ceil(sqrt((double)t));
    if (cx > maxd / w)
        cx = maxd / w ? maxd / w : 1;
    uint32_t cy = (uint32_t)((t + cx - 1) / cx);
    if (cy > maxd / h)
        cy = maxd / h ? maxd / h : 1;
    *kx = cx;
    *ky = cy;
}

typedef struct {
    uint8_t *buf;
    uint32_t n;                 /* samples in this batch */
    uint64_t *w;                /* their weights */
} batch;

/* Add batch b's rows v0..v1-1 to acc. */
static void accumulate(gls_accum *acc, const batch *b, uint32_t kx, uint32_t w, uint32_t h, uint32_t v0, uint32_t v1)
{
    size_t stride = (size_t)kx * w * 4;
    const uint8_t *tile[GLS_ACCUM_MAX_TILES];
    for (uint32_t t = 0; t < b->n; t++)
        tile[t] = b->buf + stride * h * (t / kx) + (size_t)w * 4 * (t % kx);
    if (v0 == 0 && v1 == h)
        gls_accum_add_tiles(acc, tile, stride, b->n, b->w);
    else
        gls_accum_add_tiles_rows(acc, v0, v1 - v0, tile, stride, b->n, b->w);
}

int gls_aa_render(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_run_opts *ro,
                  gls_accum *acc, gls_aa_stats *st, char *err, size_t errlen)
{
    return gls_aa_render_rows(r, c, p, ro, 0, c->height, acc, st, err, errlen);
}

int gls_aa_render_rows(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_run_opts *ro,
                       uint32_t v0, uint32_t v1, gls_accum *acc, gls_aa_stats *st, char *err, size_t errlen)
{
    uint32_t W = c->width, H = c->height, kx, ky;
    if (v1 > H)
        v1 = H;
    if (v0 >= v1)
        v0 = 0, v1 = H;
    gls_aa_stats s;
    memset(&s, 0, sizeof s);
    gls_aa_mosaic_shape(r, W, H, p->count, ro->tiles, &kx, &ky);
    if (gls_renderer_set_mosaic(r, W, H, kx, ky, err, errlen))
        return -1;
    s.kx = kx, s.ky = ky;
    uint32_t T = kx * ky;
    size_t bytes = (size_t)kx * W * ky * H * 4;
    batch b[2];
    memset(b, 0, sizeof b);
    double *du = malloc(T * sizeof *du), *dv = malloc(T * sizeof *dv);
    int rc = -1;
    for (int i = 0; i < 2; i++) {
        b[i].buf = malloc(bytes);
        b[i].w = malloc(T * sizeof *b[i].w);
    }
    if (!du || !dv || !b[0].buf || !b[1].buf || !b[0].w || !b[1].w) {
        char need[32];
        gls_fmt_bytes(need, sizeof need, 2 * (uint64_t)bytes);
        snprintf(err, errlen, "out of memory for the read-back of %ux%u tiles of %ux%u images (%s)", kx, ky, W, H,
                 need);
        goto out;
    }
    double t0 = gls_now(), last = t0;
    int cur = 0, pending = 0;
    for (uint64_t k = 0; k < p->count;) {
        batch *nb = &b[cur];
        nb->n = 0;
        while (k < p->count && nb->n < T) {
            double ou, ov;
            gls_aa_sample(p, k++, &ou, &ov, &nb->w[nb->n]);
            if (!nb->w[nb->n])
                continue; /* outside a lattice Gaussian's window */
            /* The principal point moves by -offset: the image content
             * moves by -offset, so pixel (u, v) shows the scene at
             * (u + ou, v + ov), the sample's position. */
            du[nb->n] = -ou;
            dv[nb->n] = -ov;
            nb->n++;
        }
        if (!nb->n)
            break;
        double ta = gls_now();
        gls_render_tiles_rows(r, c, nb->n, du, dv, v0, v1 - v0);
        if (ro->serial) {
            gls_render_finish(r);
            double tb = gls_now();
            s.draw_s += tb - ta;
            gls_render_read_mosaic_rows(r, (nb->n + kx - 1) / kx, v0, v1 - v0, nb->buf);
            double tc = gls_now();
            s.read_s += tc - tb;
            accumulate(acc, nb, kx, W, H, v0, v1);
            s.accum_s += gls_now() - tc;
        } else {
            /* rasterise this batch on llvmpipe's threads while this thread
             * adds up the previous one */
            gls_render_flush(r);
            double tb = gls_now();
            s.draw_s += tb - ta;
            if (pending)
                accumulate(acc, &b[cur ^ 1], kx, W, H, v0, v1);
            double tc = gls_now();
            s.accum_s += tc - tb;
            gls_render_read_mosaic_rows(r, (nb->n + kx - 1) / kx, v0, v1 - v0, nb->buf);
            s.read_s += gls_now() - tc;
            pending = 1;
            cur ^= 1;
        }
        s.passes++;
        gls_progress_steps(ro->progress, ro->label, "samples", k, p->count, t0, &last, 0);
        if (ro->on_pass)
            ro->on_pass(ro->ctx, s.passes, (p->count + T - 1) / T, gls_now() - t0);
    }
    if (pending) {
        double tc = gls_now();
        accumulate(acc, &b[cur ^ 1], kx, W, H, v0, v1);
        s.accum_s += gls_now() - tc;
    }
    s.samples = p->count;
    s.total_s = gls_now() - t0;
    if (s.total_s > 2)
        gls_progress_steps(ro->progress, ro->label, "samples", p->count, p->count, t0, &last, 1);
    rc = gls_renderer_set_mosaic(r, W, H, 1, 1, err, errlen);
out:
    for (int i = 0; i < 2; i++)
        free(b[i].buf), free(b[i].w);
    free(du);
    free(dv);
    if (st)
        *st = s;
    return rc;
}
