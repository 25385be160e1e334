/* Optical flow from the ground truth (gt_flow.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gt_flow.h"
#include "vec.h"

int gls_flow_moves_init(gls_flow_moves *m, const gls_scene *s, const uint32_t *moved, size_t nmoved)
{
    memset(m, 0, sizeof *m);
    if (nmoved == 0)
        return 0;
    m->slot = malloc((s->ninst ? s->ninst : 1) * sizeof *m->slot);
    if (!m->slot)
        return -1;
    for (uint32_t i = 0; i < s->ninst; i++) {
        int aff = 0;
        for (size_t k = 0; k < nmoved && !aff; k++)
            aff = moved[k] == i;
        /* parents come first in the table (scene.h), so a parent's slot
         * is known when its children are reached */
        uint32_t p = s->inst[i].parent;
        if (!aff && p != GLS_NONE && m->slot[p] != GLS_NONE)
            aff = 1;
        m->slot[i] = aff ? m->n++ : GLS_NONE;
    }
    m->inv0 = malloc(m->n * sizeof *m->inv0);
    m->w1 = malloc(m->n * sizeof *m->w1);
    if (!m->inv0 || !m->w1) {
        gls_flow_moves_free(m);
        return -1;
    }
    return 0;
}

/* The inverse of the affine map x -> A x + t (A = W's 3x3, t its last
 * column) as 3x4: A^-1 (x - t), A^-1 by cofactors over the determinant.
 * A singular A (an instance flattened to nothing) draws no pixel. */
static void affine_inverse(const double W[16], double inv[12])
{
    const double A[9] = {W[0], W[1], W[2], W[4], W[5], W[6], W[8], W[9], W[10]};
    double d = rm_det(A), k = d != 0 ? 1 / d : 0;
    double B[9] = {(A[4] * A[8] - A[5] * A[7]) * k, (A[2] * A[7] - A[1] * A[8]) * k, (A[1] * A[5] - A[2] * A[4]) * k,
                   (A[5] * A[6] - A[3] * A[8]) * k, (A[0] * A[8] - A[2] * A[6]) * k, (A[2] * A[3] - A[0] * A[5]) * k,
                   (A[3] * A[7] - A[4] * A[6]) * k, (A[1] * A[6] - A[0] * A[7]) * k, (A[0] * A[4] - A[1] * A[3]) * k};
    rv3 t = rm_apply(B, rv(W[3], W[7], W[11]));
    for (int r = 0; r < 3; r++) {
        inv[4 * r] = B[3 * r], inv[4 * r + 1] = B[3 * r + 1], inv[4 * r + 2] = B[3 * r + 2];
    }
    inv[3] = -t.x, inv[7] = -t.y, inv[11] = -t.z;
}

void gls_flow_moves_take(gls_flow_moves *m, const gls_scene *s, int which)
{
    for (uint32_t i = 0; m->n && i < s->ninst; i++) {
        uint32_t k = m->slot[i];
        if (k == GLS_NONE)
            continue;
        if (which == 0)
            affine_inverse(s->inst[i].world, m->inv0[k]);
        else
            memcpy(m->w1[k], s->inst[i].world, sizeof m->w1[k]);
    }
}

void gls_flow_moves_free(gls_flow_moves *m)
{
    free(m->slot);
    free(m->inv0);
    free(m->w1);
    memset(m, 0, sizeof *m);
}

/* y = M x for a 3x4 affine M. */
static void apply34(const double M[12], const double x[3], double y[3])
{
    for (int r = 0; r < 3; r++)
        y[r] = M[4 * r] * x[0] + M[4 * r + 1] * x[1] + M[4 * r + 2] * x[2] + M[4 * r + 3];
}

/* The larger one-sided depth difference along a row or column at pixel i
 * (step: 1 or the width; has_lo/has_hi: whether the neighbour exists;
 * neighbours with no surface left out): the depth's change over a pixel,
 * large enough at a crease (floor meets wall) or a curved surface seen at
 * a grazing angle, where the one-sided differences disagree. */
static double slope(const float *z, size_t i, size_t step, int has_lo, int has_hi)
{
    double best = 0;
    if (has_lo && isfinite(z[i - step]))
        best = fabs((double)z[i] - z[i - step]);
    if (has_hi && isfinite(z[i + step]) && fabs((double)z[i + step] - z[i]) > best)
        best = fabs((double)z[i + step] - z[i]);
    return best;
}

void gls_flow_move_point(const gls_flow_moves *m, uint32_t id, double P[3])
{
    uint32_t k = m->n ? m->slot[id - 1] : GLS_NONE;
    if (k != GLS_NONE) { /* to the instance's frame at t, back at t+1 */
        double Po[3];
        apply34(m->inv0[k], P, Po);
        apply34(m->w1[k], Po, P);
    }
}

uint8_t gls_flow_visibility(const gls_camera *c1, const float *z1, double u1, double v1, double Z, double spread)
{
    uint32_t w = c1->width, h = c1->height;
    /* the nearest pixel: pixel centres are at whole (u, v) */
    double px = floor(u1 + 0.5), py = floor(v1 + 0.5);
    if (!(px >= 0 && px < w && py >= 0 && py < h) || Z < c1->near || Z > c1->far)
        return GLS_FLOW_OUT;
    size_t j = (size_t)py * w + (size_t)px;
    double tol = GLS_FLOW_OCC_REL * Z;
    if (isfinite(z1[j]))
        tol += slope(z1, j, 1, px > 0, px + 1 < w) * (fabs(u1 - px) + spread) +
               slope(z1, j, w, py > 0, py + 1 < h) * (fabs(v1 - py) + spread);
    return isfinite(z1[j]) && Z > z1[j] + tol ? GLS_FLOW_OCCLUDED : GLS_FLOW_VISIBLE;
}

void gls_flow_compute(const gls_camera *c0, const gls_camera *c1, const uint32_t *inst, const float *z,
                      const float *z1, const gls_flow_moves *m, float *uv, uint8_t *mask)
{
    uint32_t w = c0->width, h = c0->height;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            uv[2 * i] = uv[2 * i + 1] = GLS_FLOW_UNKNOWN;
            mask[i] = GLS_FLOW_NONE;
            if (!inst[i] || !isfinite(z[i]))
                continue;
            double Pc[3], P[3], Pc1[3];
            gls_camera_unproject(c0, x, y, z[i], Pc);
            gls_camera_to_world(c0, Pc, P);
            gls_flow_move_point(m, inst[i], P);
            gls_camera_to_cam(c1, P, Pc1);
            double Z = Pc1[2];
            if (!(Z > 0)) { /* behind the camera: no image position */
                mask[i] = GLS_FLOW_OUT;
                continue;
            }
            double u1 = (c1->fx * Pc1[0] + c1->skew * Pc1[1]) / Z + c1->cx;
            double v1 = c1->fy * Pc1[1] / Z + c1->cy;
            uv[2 * i] = (float)(u1 - x);
            uv[2 * i + 1] = (float)(v1 - y);
            mask[i] = gls_flow_visibility(c1, z1, u1, v1, Z, 0);
        }
}
