/* Optical flow with a rolling shutter (gt_flow_rolling.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "distort.h"
#include "distort_exposure.h"
#include "gt_flow_rolling.h"
#include "gt_pass.h"

void gls_flow_rows_free(gls_flow_rows *fr)
{
    free(fr->cam0);
    free(fr->inv0);
    free(fr->cam1);
    free(fr->w1);
    memset(fr, 0, sizeof *fr);
}

static void put_pose(double dst[12], const gls_camera *c)
{
    memcpy(dst, c->R, 9 * sizeof *dst);
    memcpy(dst + 9, c->T, 3 * sizeof *dst);
}

int gls_flow_rows_fill(gls_flow_rows *fr, const gls_camera *c, uint32_t band, double next_dt, gls_flow_moves *m,
                       const gls_scene *s, gls_pose_at_fn pose_at, void *ud, double *bad)
{
    memset(fr, 0, sizeof *fr);
    uint32_t H = c->height, n = m->n, h = band ? band : H;
    size_t rows = H ? H : 1, per = n ? n : 1;
    fr->H = H, fr->n = n;
    fr->cam0 = malloc(rows * sizeof *fr->cam0);
    fr->cam1 = malloc(rows * sizeof *fr->cam1);
    fr->inv0 = malloc(rows * per * sizeof *fr->inv0);
    fr->w1 = malloc(rows * per * sizeof *fr->w1);
    if (!fr->cam0 || !fr->cam1 || !fr->inv0 || !fr->w1) {
        gls_flow_rows_free(fr);
        return -1;
    }
    int rc = 0;
    gls_camera at = *c;
    /* frame t: each band at its middle row's time, as its depth */
    for (uint32_t v0 = 0; v0 < H && rc == 0; v0 += h) {
        uint32_t v1 = v0 + h < H ? v0 + h : H;
        double t = c->line_delay * (v0 + v1 - 1) / 2.0;
        if (pose_at(ud, t, &at)) {
            *bad = t, rc = 1;
            break;
        }
        gls_flow_moves_take(m, s, 0);
        for (uint32_t v = v0; v < v1; v++) {
            put_pose(fr->cam0[v], &at);
            if (n)
                memcpy(fr->inv0 + (size_t)v * n, m->inv0, n * sizeof *m->inv0);
        }
    }
    /* frame t+1: every row's own time */
    for (uint32_t v = 0; v < H && rc == 0; v++) {
        double t = next_dt + c->line_delay * v;
        if (pose_at(ud, t, &at)) {
            *bad = t, rc = 1;
            break;
        }
        gls_flow_moves_take(m, s, 1);
        put_pose(fr->cam1[v], &at);
        if (n)
            memcpy(fr->w1 + (size_t)v * n, m->w1, n * sizeof *m->w1);
    }
    at = *c;
    pose_at(ud, 0, &at);
    if (rc)
        gls_flow_rows_free(fr);
    return rc;
}

/* pose_at shifted by a frame interval: the next frame's bands through
 * gls_distort_truth_bands, which takes times from the frame time */
typedef struct {
    gls_pose_at_fn pose_at;
    void *ud;
    double dt;
} shifted;

static int pose_shifted(void *ud, double t, gls_camera *cam)
{
    shifted *sh = ud;
    return sh->pose_at(sh->ud, sh->dt + t, cam);
}

int gls_flow_rolling_depth(gls_renderer *r, const gls_camera *c, const gls_distort_frame *f, gls_bands bands,
                           double next_dt, gls_pose_at_fn pose_at, void *ud, float *z1, char *err, size_t errlen)
{
    if (f) {
        shifted sh = {pose_at, ud, next_dt};
        int rc = gls_distort_truth_bands(r, c, f, bands, pose_shifted, &sh, NULL, NULL, NULL, NULL, z1, err, errlen);
        gls_camera at = *c;
        pose_at(ud, 0, &at); /* the scene back at frame t */
        return rc;
    }
    /* each band's ground-truth pass scissored to its rows and read
     * straight into them; with the test's choice (gls_bands' whole) the
     * whole image into a scratch buffer, its rows copied */
    size_t n = (size_t)c->width * c->height, W = c->width;
    uint32_t h = bands.rows ? bands.rows : c->height;
    int whole = bands.whole;
    float *zb = whole ? malloc((n ? n : 1) * sizeof *zb) : NULL;
    int rc = 0;
    if (whole && !zb) {
        snprintf(err, errlen, "out of memory for the next frame's depth");
        return -1;
    }
    for (uint32_t v0 = 0; v0 < c->height && rc == 0; v0 += h) {
        uint32_t v1 = v0 + h < c->height ? v0 + h : c->height;
        gls_camera at = *c;
        pose_at(ud, next_dt + c->line_delay * (v0 + v1 - 1) / 2.0, &at);
        if (whole) {
            rc = gls_gt_render(r, &at, NULL, NULL, zb, err, errlen);
            if (rc == 0)
                memcpy(z1 + W * v0, zb + W * v0, W * (v1 - v0) * sizeof *z1);
        } else {
            rc = gls_gt_render_rows(r, &at, v0, v1 - v0, NULL, NULL, z1, err, errlen);
        }
    }
    gls_camera at = *c;
    pose_at(ud, 0, &at);
    free(zb);
    return rc;
}

/* y = M x for a 3x4 affine M. */
static void apply34(const double M[12], const double x[3], double y[3])
{
    for (int r = 0; r < 3; r++)
        y[r] = M[4 * r] * x[0] + M[4 * r + 1] * x[1] + M[4 * r + 2] * x[2] + M[4 * r + 3];
}

/* The point (world P, or Po in its instance's frame when k is a moving
 * instance) in frame t+1's camera at row r's time: pixel (u, v) and Zc,
 * projected by the lens model when f (distorted rows: the row whose time
 * sees it).  0; -1 when the lens images it nowhere (behind the camera or
 * at or beyond the model's fold). */
static int at_row(const gls_camera *c, const gls_distort_frame *f, const gls_flow_rows *fr, uint32_t k,
                  const double P[3], uint32_t r, double out[3])
{
    double X[3], Pc[3];
    if (k != GLS_NONE)
        apply34(fr->w1[(size_t)r * fr->n + k], P, X);
    else
        memcpy(X, P, sizeof X);
    gls_camera at = *c;
    memcpy(at.R, fr->cam1[r], sizeof at.R);
    memcpy(at.T, fr->cam1[r] + 9, sizeof at.T);
    gls_camera_to_cam(&at, X, Pc);
    out[2] = Pc[2];
    if (f) {
        double x = Pc[0] / Pc[2], y = Pc[1] / Pc[2];
        if (!(Pc[2] > 0) || !(x * x + y * y < c->dist.max_r2))
            return -1;
        gls_distort_project(c, Pc, &out[0], &out[1]);
        return 0;
    }
    out[0] = (c->fx * Pc[0] + c->skew * Pc[1]) / Pc[2] + c->cx;
    out[1] = c->fy * Pc[1] / Pc[2] + c->cy;
    return 0;
}

/* u, v, Zc at the (clamped) continuous row y: linear between rows.  -1
 * as at_row at either row. */
static int at_time(const gls_camera *c, const gls_distort_frame *f, const gls_flow_rows *fr, uint32_t k,
                   const double P[3], double y, double out[3])
{
    double top = (double)(fr->H - 1), yc = y < 0 ? 0 : y > top ? top : y;
    uint32_t r = (uint32_t)floor(yc);
    double a = yc - r, p[3], q[3];
    if (at_row(c, f, fr, k, P, r, p))
        return -1;
    if (a == 0 || r + 1 >= fr->H) {
        memcpy(out, p, sizeof p);
        return 0;
    }
    if (at_row(c, f, fr, k, P, r + 1, q))
        return -1;
    for (int i = 0; i < 3; i++)
        out[i] = p[i] + a * (q[i] - p[i]);
    return 0;
}

void gls_flow_compute_rolling(const gls_camera *c, const gls_distort_frame *f, const gls_flow_rows *fr,
                              const gls_flow_moves *m, const uint32_t *inst, const float *z, const float *z1,
                              float *uv, uint8_t *mask)
{
    uint32_t w = c->width, h = c->height;
    /* through a lens z and z1 were each read at the nearest fine pixel, up
     * to half a fine pixel from the centre (lens_truth.h) */
    double spread = f ? 1 / f->lay.mag : 0;
    gls_camera c0 = *c;
    for (uint32_t y = 0; y < h; y++) {
        memcpy(c0.R, fr->cam0[y], sizeof c0.R);
        memcpy(c0.T, fr->cam0[y] + 9, sizeof c0.T);
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            uv[2 * i] = uv[2 * i + 1] = GLS_FLOW_UNKNOWN;
            mask[i] = GLS_FLOW_NONE;
            if (!inst[i] || !isfinite(z[i]))
                continue;
            double Pc[3], P[3];
            if (f) { /* the pixel centre's exact ray through the lens */
                Pc[0] = z[i] * f->ray[2 * i], Pc[1] = z[i] * f->ray[2 * i + 1], Pc[2] = z[i];
            } else {
                gls_camera_unproject(&c0, x, y, z[i], Pc);
            }
            gls_camera_to_world(&c0, Pc, P);
            uint32_t k = m->n ? m->slot[inst[i] - 1] : GLS_NONE;
            if (k != GLS_NONE) { /* to the instance's frame at its row's time */
                double Po[3];
                apply34(fr->inv0[(size_t)y * fr->n + k], P, Po);
                memcpy(P, Po, sizeof P);
            }
            /* the fixed point v' = y(v'), from row 0's time */
            double p[3], v = 0;
            int ok = 0;
            for (int it = 0; it < GLS_FLOW_RS_ITER; it++) {
                if (at_time(c, f, fr, k, P, v, p) || !(p[2] > 0))
                    break;
                double step = fabs(p[1] - v);
                v = p[1];
                if (step <= GLS_FLOW_RS_TOL) {
                    ok = 1;
                    break;
                }
            }
            if (!ok) { /* behind the camera, past the lens's fold, or no row sees it: no image position */
                mask[i] = GLS_FLOW_OUT;
                continue;
            }
            if (at_time(c, f, fr, k, P, v, p)) {
                mask[i] = GLS_FLOW_OUT;
                continue;
            }
            uv[2 * i] = (float)(p[0] - x);
            uv[2 * i + 1] = (float)(v - y);
            mask[i] = gls_flow_visibility(c, z1, p[0], v, p[2], spread);
        }
    }
}
