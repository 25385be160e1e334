/* Motion blur, rolling shutter, depth of field through a lens
 * (distort_exposure.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "distort.h"
#include "distort_exposure.h"
#include "gt_pass.h"

/* Fine rows of slack around a band's pre-image: its border is sampled
 * every half image pixel (the curve between two samples bulges far less
 * than a fine row) and the bilinear read takes the row below. */
#define ROW_SLACK 2

typedef struct {
    gls_renderer *r;
    const gls_camera *c;
    const gls_aa_plan *p;
    const gls_distort_frame *df;
    gls_distort_layout lay;  /* the anti-aliased fine image's            */
    uint16_t *rgb16;         /* its rows, the band's                      */
    uint64_t aa_memory;
    const char *name;
} lens_bands;

/* The fine rows r0..r1 of lay that the pre-image of image rows v0..v1-1
 * (grown by the anti-aliasing window) covers. */
static void band_fine_rows(const gls_camera *c, const gls_distort_layout *lay, uint32_t v0, uint32_t v1,
                           uint32_t *r0, uint32_t *r1)
{
    const gls_camera *f = &lay->fine;
    double m = lay->margin, ua = -0.5 - m, ub = c->width - 0.5 + m, va = v0 - 0.5 - m, vb = v1 - 0.5 + m;
    double lo = INFINITY, hi = -INFINITY;
    uint32_t nu = (uint32_t)ceil(2 * (ub - ua)), nv = (uint32_t)ceil(2 * (vb - va));
    for (uint32_t i = 0; i <= nu + nv; i++)
        for (int side = 0; side < 2; side++) {
            /* the top and bottom edges, then the left and right ones */
            double u = i <= nu ? ua + (ub - ua) * i / nu : side ? ub : ua;
            double v = i <= nu ? (side ? vb : va) : va + (vb - va) * (i - nu) / nv, x, y;
            if (gls_distort_pixel_ray(c, u, v, &x, &y) < 0) {
                *r0 = 0, *r1 = f->height - 1; /* checked not to happen: all of it */
                return;
            }
            lo = fmin(lo, f->fy * y + f->cy), hi = fmax(hi, f->fy * y + f->cy);
        }
    double a = floor(lo) - ROW_SLACK, b = ceil(hi) + ROW_SLACK;
    *r0 = a < 0 ? 0 : (uint32_t)a;
    *r1 = b > f->height - 1 ? f->height - 1 : (uint32_t)b;
}

static int lens_band(void *ud, const gls_camera *at, double lx, double ly, uint32_t v0, uint32_t v1, gls_accum *tmp,
                     char *msg, size_t msglen)
{
    lens_bands *lb = ud;
    char err[512];
    uint32_t r0, r1;
    band_fine_rows(lb->c, &lb->lay, v0, v1, &r0, &r1);
    /* drawn: the fine camera at the band's pose, sheared for the lens
     * point (the same shear of the undistorted ray as the pinhole's),
     * cropped to rows r0..r1; read: the unsheared layout cropped alike */
    gls_camera posed = lb->lay.fine, draw;
    memcpy(posed.R, at->R, sizeof posed.R);
    memcpy(posed.T, at->T, sizeof posed.T);
    gls_exposure_lens(&posed, lx, ly, &draw);
    draw.height = r1 - r0 + 1;
    draw.cy -= r0;
    gls_distort_frame view = *lb->df;
    view.lay_aa = lb->lay;
    view.lay_aa.fine.height = draw.height;
    view.lay_aa.fine.cy -= r0;
    view.rgb16 = lb->rgb16;
    if (gls_distort_render_aa(lb->r, &draw, lb->p, lb->aa_memory, lb->rgb16, err, sizeof err)) {
        snprintf(msg, msglen, "glsplay: error: camera %s: %s", lb->name, err);
        return -1;
    }
    if (gls_distort_frame_accum_rows(&view, lb->c, lb->p, v0, v1, tmp)) {
        snprintf(msg, msglen, "glsplay: error: camera %s: out of memory for the lens's sub-frame image", lb->name);
        return -1;
    }
    return 0;
}

int gls_distort_exposure_render(gls_renderer *r, const gls_camera *c, const gls_exposure *e, const gls_aa_plan *p,
                                const gls_distort_frame *df, gls_pose_at_fn pose_at, void *ud, uint32_t band,
                                uint64_t aa_memory, const char *name, gls_accum *acc, char *msg, size_t msglen)
{
    lens_bands lb;
    memset(&lb, 0, sizeof lb);
    lb.r = r, lb.c = c, lb.p = p, lb.df = df, lb.aa_memory = aa_memory, lb.name = name;
    char err[512];
    if (gls_distort_layout_make(c, p, GLS_DISTORT_AA_SCALE, gls_renderer_max_dim(r), &lb.lay, err, sizeof err)) {
        snprintf(msg, msglen, "glsplay: error: camera %s: %s", name, err);
        return -1;
    }
    lb.rgb16 = malloc(3 * (size_t)lb.lay.fine.width * lb.lay.fine.height * sizeof *lb.rgb16);
    if (!lb.rgb16) {
        snprintf(msg, msglen, "glsplay: error: camera %s: out of memory for the %ux%u anti-aliased undistorted image",
                 name, lb.lay.fine.width, lb.lay.fine.height);
        return -1;
    }
    int rc = gls_exposure_render_bands(c, e, p, pose_at, ud, lens_band, &lb, acc, band, msg, msglen);
    free(lb.rgb16);
    return rc;
}

int gls_distort_truth_bands(gls_renderer *r, const gls_camera *c, const gls_distort_frame *df, gls_bands bands,
                            gls_pose_at_fn pose_at, void *ud, uint8_t *rgba, float *z, uint32_t *inst, float *normal,
                            float *gt_z, char *err, size_t errlen)
{
    const gls_camera *f0 = &df->lay.fine;
    size_t nf = (size_t)f0->width * f0->height, W = c->width;
    gls_distort_frame view = *df;
    view.rgba = rgba ? malloc(4 * nf) : NULL;
    view.z = z ? malloc(nf * sizeof *view.z) : NULL;
    uint32_t *fids = inst ? malloc(nf * sizeof *fids) : NULL;
    float *fnrm = normal ? malloc(3 * nf * sizeof *fnrm) : NULL;
    float *fgz = gt_z ? malloc(nf * sizeof *fgz) : NULL;
    int rc = -1;
    if ((rgba && !view.rgba) || (z && !view.z) || (inst && !fids) || (normal && !fnrm) || (gt_z && !fgz)) {
        snprintf(err, errlen, "out of memory for the %ux%u undistorted image of a band of rows", f0->width,
                 f0->height);
        goto out;
    }
    /* the test's choice (gls_bands): every band draws and reads the whole
     * fine image */
    int whole = bands.whole;
    uint32_t band = bands.rows;
    /* every pass of a band at the plain fine image's size (gt_pass.h draws
     * at the size set) */
    if (gls_renderer_set_size(r, f0->width, f0->height, err, errlen))
        goto out;
    for (uint32_t v0 = 0; v0 < c->height; v0 += band) {
        uint32_t v1 = v0 + band < c->height ? v0 + band : c->height;
        size_t a = W * v0, b = W * v1;
        /* the fine rows the band's pixels read (their nearest fine
         * pixels): drawn (scissored, so bit for bit the whole pass's
         * rows) and read back, no others */
        uint32_t r0 = 0, r1 = f0->height - 1;
        if (!whole)
            gls_distort_frame_nearest_rows(&view, a, b, &r0, &r1);
        uint32_t rows = r1 - r0 + 1;
        gls_camera at = *c;
        pose_at(ud, c->line_delay * (v0 + v1 - 1) / 2.0, &at);
        memcpy(view.lay.fine.R, at.R, sizeof at.R);
        memcpy(view.lay.fine.T, at.T, sizeof at.T);
        if (rgba || z) {
            gls_render_pass_rows(r, &view.lay.fine, r0, rows);
            if (rgba)
                gls_render_read_rgba_rows(r, r0, rows, view.rgba);
            if (z)
                gls_render_read_z_rows(r, r0, rows, view.z);
            gls_distort_frame_centre_range(&view, a, b, rgba, z);
        }
        if (inst || normal || gt_z) {
            if (gls_gt_render_rows(r, &view.lay.fine, r0, rows, fids, fnrm, fgz, err, errlen))
                goto out;
            /* the band's pixels, the rule of every ground truth through a lens */
            gls_distort_frame_read_truth(&view, a, b, fids, fnrm, fgz, inst, normal, gt_z);
        }
    }
    rc = 0;
out:
    {
        gls_camera at = *c;
        pose_at(ud, 0, &at);
    }
    free(view.rgba);
    free(view.z);
    free(fids);
    free(fnrm);
    free(fgz);
    return rc;
}

void gls_distort_exposure_explain(FILE *out, const gls_camera *c, int moving, const gls_aa_plan *p)
{
    gls_exposure e = gls_exposure_of(c, moving);
    if (!gls_distort_on(c) || !gls_exposure_on(&e))
        return;
    gls_distort_layout la;
    char err[400];
    if (gls_distort_layout_make(c, p, GLS_DISTORT_AA_SCALE, 0, &la, err, sizeof err))
        return; /* gls_distort_explain said why */
    fprintf(out, "  lens with the exposure: each of the %llu sub-frame renders%s draws the anti-aliased undistorted "
                 "image (%ux%u, %llu lattice samples per fine pixel) at its time%s%s, then reads the %llu "
                 "anti-aliasing samples of each pixel through the inverse model as without the exposure\n",
            (unsigned long long)e.samples, e.rolling ? ", for each band of rows," : "", la.fine.width, la.fine.height,
            (unsigned long long)gls_distort_fine_samples(p), e.dof ? " and lens point (sheared before the lens model)"
                                                                   : "",
            e.rolling ? " (only the fine rows the band's pre-image under the model covers)" : "",
            (unsigned long long)p->count);
    if (e.rolling)
        fprintf(out, "  lens with the exposure: ground truth per band of rows: one plain undistorted pass (and one "
                     "ground-truth pass when ids or normals are asked for) at the band's time, drawn and read in "
                     "only the fine rows the band's pixel centres read (nearest fine pixel)\n");
}
