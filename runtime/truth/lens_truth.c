/* Ground truth through a lens beyond the frame's own pass (lens_truth.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "distort.h"
#include "gt_pass.h"
#include "lens_truth.h"

/* f's plain fine camera at c's pose. */
static gls_camera fine_at(const gls_distort_frame *f, const gls_camera *c)
{
    gls_camera fc = f->lay.fine;
    memcpy(fc.R, c->R, sizeof fc.R);
    memcpy(fc.T, c->T, sizeof fc.T);
    return fc;
}

int gls_lens_gt_render(gls_renderer *r, const gls_distort_frame *f, const gls_camera *c, uint32_t *ids,
                       float *normals, float *z, char *err, size_t errlen)
{
    gls_camera fc = fine_at(f, c);
    size_t fn = (size_t)fc.width * fc.height, n = (size_t)c->width * c->height;
    uint32_t *fids = ids ? malloc(fn * sizeof *fids) : NULL;
    float *fnrm = normals ? malloc(fn * 3 * sizeof *fnrm) : NULL;
    float *fz = z ? malloc(fn * sizeof *fz) : NULL;
    int rc = -1;
    if ((ids && !fids) || (normals && !fnrm) || (z && !fz)) {
        snprintf(err, errlen, "out of memory for the %ux%u undistorted ground truth", fc.width, fc.height);
        goto out;
    }
    /* the depth is read at the renderer's size (gls_render_read_z) */
    if ((z && gls_renderer_set_size(r, fc.width, fc.height, err, errlen)) ||
        gls_gt_render(r, &fc, fids, fnrm, fz, err, errlen))
        goto out;
    gls_distort_frame_read_truth(f, 0, n, fids, fnrm, fz, ids, normals, z);
    rc = 0;
out:
    free(fids), free(fnrm), free(fz);
    return rc;
}

void gls_flow_compute_lens(const gls_camera *c0, const gls_camera *c1, const gls_distort_frame *f,
                           const uint32_t *inst, const float *z, const float *z1, const gls_flow_moves *m, float *uv,
                           uint8_t *mask)
{
    const double *ray = f->ray;
    /* the point's depth at t and z1 at t+1 were each read at the nearest
     * fine pixel, up to half a fine pixel (1 / (2 mag) image pixels) from
     * the centre: one fine pixel in all */
    double spread = 1 / f->lay.mag;
    size_t n = (size_t)c0->width * c0->height;
    for (size_t i = 0; i < n; i++) {
        uv[2 * i] = uv[2 * i + 1] = GLS_FLOW_UNKNOWN;
        mask[i] = GLS_FLOW_NONE;
        if (!inst[i] || !isfinite(z[i]))
            continue;
        double Pc[3] = {z[i] * ray[2 * i], z[i] * ray[2 * i + 1], z[i]}, P[3], Pc1[3];
        gls_camera_to_world(c0, Pc, P);
        gls_flow_move_point(m, inst[i], P);
        gls_camera_to_cam(c1, P, Pc1);
        double Z = Pc1[2], x = Pc1[0] / Z, y = Pc1[1] / Z;
        /* behind the camera, or where the model folds back: the lens
         * images the point nowhere */
        if (!(Z > 0) || !(x * x + y * y < c1->dist.max_r2)) {
            mask[i] = GLS_FLOW_OUT;
            continue;
        }
        double u1, v1;
        gls_distort_project(c1, Pc1, &u1, &v1);
        uint32_t px = (uint32_t)(i % c0->width), py = (uint32_t)(i / c0->width);
        uv[2 * i] = (float)(u1 - px);
        uv[2 * i + 1] = (float)(v1 - py);
        mask[i] = gls_flow_visibility(c1, z1, u1, v1, Z, spread);
    }
}

/* Point p (camera frame, Zc > 0) through c's lens; at the fold along its
 * direction when at or beyond it (the outermost the lens images there). */
static void project_clamped(const gls_camera *c, const double p[3], double *u, double *v)
{
    double x = p[0] / p[2], y = p[1] / p[2], r2 = x * x + y * y, q[3] = {x, y, 1};
    if (!(r2 < c->dist.max_r2)) {
        double s = sqrt(c->dist.max_r2 / r2);
        q[0] = x * s, q[1] = y * s;
    }
    gls_distort_project(c, q, u, v);
}

double gls_lens_box_truncation(const gls_camera *c, const double k[8][3])
{
    double u0 = INFINITY, v0 = INFINITY, u1 = -INFINITY, v1 = -INFINITY;
    for (int a = 0; a < 8; a++)
        for (int bit = 0; bit < 3; bit++) {
            int b = a | (1 << bit);
            if (b == a)
                continue;
            /* the edge a..b, clipped to Zc >= near */
            double ta = 0, tb = 1, za = k[a][2], zb = k[b][2], near = c->near;
            if (za < near && zb < near)
                continue;
            if (za < near)
                ta = (near - za) / (zb - za);
            else if (zb < near)
                tb = (near - za) / (zb - za);
            for (int i = 0; i <= GLS_LENS_BOX_EDGE_STEPS; i++) {
                double t = ta + (tb - ta) * i / GLS_LENS_BOX_EDGE_STEPS, p[3], u, v;
                for (int j = 0; j < 3; j++)
                    p[j] = k[a][j] + t * (k[b][j] - k[a][j]);
                if (p[2] < near)
                    p[2] = near; /* the clip point, rounded */
                project_clamped(c, p, &u, &v);
                u0 = fmin(u0, u), u1 = fmax(u1, u), v0 = fmin(v0, v), v1 = fmax(v1, v);
            }
        }
    return gls_box_truncation_of(c, u0, v0, u1, v1);
}

int gls_boxes_compute_lens(gls_renderer *r, const gls_scene *s, const gls_camera *c, const gls_distort_frame *f,
                           const uint32_t *ids, gls_box **boxes, size_t *n, char *err, size_t errlen)
{
    gls_box *b = NULL;
    size_t k = 0, np = (size_t)c->width * c->height;
    gls_camera fc = fine_at(f, c);
    size_t fn = (size_t)fc.width * fc.height;
    *boxes = NULL, *n = 0;
    if (gls_boxes_base(s, c, ids, &b, &k)) {
        snprintf(err, errlen, "out of memory for the boxes");
        return -1;
    }
    if (k == 0)
        return 0;
    uint8_t *vis = calloc(s->nitems ? s->nitems : 1, 1);
    float *z = malloc(fn * sizeof *z);
    if (!vis || !z) {
        snprintf(err, errlen, "out of memory for the %ux%u undistorted boxes pass", fc.width, fc.height);
        free(b), free(vis), free(z);
        return -1;
    }
    if (gls_renderer_set_size(r, fc.width, fc.height, err, errlen)) {
        free(b), free(vis), free(z);
        return -1;
    }
    gls_render_prepare(r, &fc);
    static const double m[6] = {1, 0, 0.5, 0, 1, 0.5}; /* fine (u, v) -> window (u + 1/2, v + 1/2) */
    const uint32_t sc[4] = {0, 0, fc.width, fc.height};
    for (size_t j = 0; j < k; j++) {
        for (uint32_t i = 0; i < s->nitems; i++)
            vis[i] = s->items[i].inst == b[j].inst;
        b[j].truncated = gls_lens_box_truncation(c, (const double(*)[3])b[j].corners);
        /* drawn alone through the fine camera, counted at the pixel
         * centres' nearest fine pixels, as the instance image is made */
        gls_render_mapped(r, &fc, m, fc.width, fc.height, sc, vis);
        gls_render_read_z(r, z);
        uint64_t alone = 0;
        for (size_t i = 0; i < np; i++)
            alone += isfinite(z[gls_distort_frame_nearest(f, i)]) != 0;
        gls_box_set_alone(&b[j], alone);
    }
    free(vis), free(z);
    *boxes = b, *n = k;
    return 0;
}
