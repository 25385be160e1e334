/* Exact coverage of a scene (exact_scene.h): the scene's triangles as
 * image triangles, their colours, and the exact image's conversions. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "exact_scene.h"

const char *gls_exact_scene_unsupported(const gls_scene *s)
{
    if (s->lit)
        return "a lit scene (its lights and normals are shaded by GL)";
    for (uint32_t k = 0; k < s->nchunks; k++)
        if (s->chunks[k].key.texture != GLS_NONE)
            return "a textured object (its texels are sampled by GL)";
    return NULL;
}

static void world_of(const double W[16], const double *p, double q[3])
{
    for (int r = 0; r < 3; r++)
        q[r] = W[4 * r] * p[0] + W[4 * r + 1] * p[1] + W[4 * r + 2] * p[2] + W[4 * r + 3];
}

/* room for need image triangles; 0, or -1 when out of memory */
static int reserve(gls_exact_geom *g, size_t need)
{
    if (need > g->cap) {
        size_t c = g->cap ? 2 * g->cap : 1024;
        if (c < need)
            c = need;
        gls_exact_tri *t = realloc(g->t, c * sizeof *t);
        if (t)
            g->t = t;
        gls_exact_vcol *v = realloc(g->v, c * sizeof *v);
        if (v)
            g->v = v;
        if (!t || !v)
            return -1;
        g->cap = c;
    }
    return 0;
}

static int add_tri(gls_exact_geom *g, const gls_exact_pinhole *cam, const double P[3][3], const float col[3][4],
                   uint32_t id)
{
    if (reserve(g, g->n + 3))
        return -1;
    gls_exact_tri proto;
    memset(&proto, 0, sizeof proto);
    proto.id = id;
    memcpy(proto.rgba, col[0], sizeof proto.rgba);
    int m = gls_exact_project(cam, P, &proto, g->t + g->n);
    gls_exact_vcol vc;
    for (int k = 0; k < 3; k++) {
        /* camera space of the whole triangle, for the colour's interpolation */
        double d[3] = {P[k][0] - cam->C[0], P[k][1] - cam->C[1], P[k][2] - cam->C[2]};
        for (int r = 0; r < 3; r++)
            vc.P[k][r] = cam->R[3 * r] * d[0] + cam->R[3 * r + 1] * d[1] + cam->R[3 * r + 2] * d[2];
        memcpy(vc.rgba[k], col[k], sizeof vc.rgba[k]);
    }
    for (int k = 0; k < m; k++)
        g->v[g->n + k] = vc;
    g->n += (size_t)m;
    return 0;
}

int gls_exact_geom_make(gls_exact_geom *g, const gls_scene *s, const gls_camera *c)
{
    memset(g, 0, sizeof *g);
    gls_exact_pinhole cam;
    memcpy(cam.R, c->R, sizeof cam.R);
    gls_camera_centre(c, cam.C);
    cam.fx = c->fx, cam.fy = c->fy, cam.cx = c->cx, cam.cy = c->cy, cam.skew = c->skew;
    cam.znear = c->near, cam.zfar = c->far;
    g->fx = c->fx, g->fy = c->fy, g->cx = c->cx, g->cy = c->cy, g->skew = c->skew;
    /* the arrays at their size at once (one image triangle a scene
     * triangle, bar the near and far cuts): grown by doubling from small,
     * 100k triangles copied 20 MB and page-faulted it in twice, an eighth
     * of --aa exact's time on make bench-aa's scene */
    size_t total = 0;
    for (uint32_t i = 0; i < s->ninst; i++)
        if (s->inst[i].proto != GLS_NONE) {
            const gls_proto *pr = &s->protos[s->inst[i].proto];
            for (uint32_t ch = pr->first_chunk; ch < pr->first_chunk + pr->nchunks; ch++)
                total += s->chunks[ch].count / 3;
        }
    if (reserve(g, total + 3))
        return -1;
    for (uint32_t i = 0; i < s->ninst; i++) {
        const gls_instance *in = &s->inst[i];
        if (in->proto == GLS_NONE)
            continue;
        const gls_proto *pr = &s->protos[in->proto];
        for (uint32_t ch = pr->first_chunk; ch < pr->first_chunk + pr->nchunks; ch++) {
            const gls_chunk *k = &s->chunks[ch];
            for (uint32_t v = k->first; v + 2 < k->first + k->count; v += 3) {
                double P[3][3];
                float col[3][4];
                for (int q = 0; q < 3; q++) {
                    world_of(in->world, s->exact + 3 * (size_t)(v + q), P[q]);
                    const uint8_t *rgba = s->has_color ? s->verts + (size_t)(v + q) * s->stride + s->color_offset
                                                       : k->key.rgba;
                    for (int e = 0; e < 4; e++)
                        col[q][e] = rgba[e] / 255.0f;
                }
                if (add_tri(g, &cam, P, col, i))
                    return -1;
            }
        }
    }
    return 0;
}

void gls_exact_geom_free(gls_exact_geom *g)
{
    free(g->t), free(g->v);
    memset(g, 0, sizeof *g);
}

void gls_exact_geom_shade(void *user, const gls_exact_tri *t, size_t i, double x, double y, float rgba[4])
{
    const gls_exact_geom *g = user;
    const gls_exact_vcol *v = &g->v[i];
    if (!memcmp(v->rgba[0], v->rgba[1], sizeof v->rgba[0]) && !memcmp(v->rgba[0], v->rgba[2], sizeof v->rgba[0])) {
        memcpy(rgba, t->rgba, 4 * sizeof *rgba); /* flat: exact */
        return;
    }
    /* the camera ray through (x, y) meets the triangle's plane at X; its
     * barycentric coordinates there are GL's perspective-correct weights */
    double dy = (y - g->cy) / g->fy, d[3] = {(x - g->cx - g->skew * dy) / g->fx, dy, 1};
    const double *A = v->P[0];
    double e1[3], e2[3], n[3];
    for (int r = 0; r < 3; r++)
        e1[r] = v->P[1][r] - A[r], e2[r] = v->P[2][r] - A[r];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2], n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double nd = n[0] * d[0] + n[1] * d[1] + n[2] * d[2], s = (n[0] * A[0] + n[1] * A[1] + n[2] * A[2]) / nd, w[3];
    double p[3] = {s * d[0] - A[0], s * d[1] - A[1], s * d[2] - A[2]};
    double d00 = 0, d01 = 0, d11 = 0, d20 = 0, d21 = 0;
    for (int r = 0; r < 3; r++)
        d00 += e1[r] * e1[r], d01 += e1[r] * e2[r], d11 += e2[r] * e2[r], d20 += p[r] * e1[r], d21 += p[r] * e2[r];
    double den = d00 * d11 - d01 * d01;
    w[1] = (d11 * d20 - d01 * d21) / den, w[2] = (d00 * d21 - d01 * d20) / den, w[0] = 1 - w[1] - w[2];
    for (int q = 0; q < 4; q++)
        rgba[q] = (float)(w[0] * v->rgba[0][q] + w[1] * v->rgba[1][q] + w[2] * v->rgba[2][q]);
}

static double clamp01(float v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

void gls_exact_rgba8(const float *rgba, size_t n, uint8_t *out)
{
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            out[4 * i + c] = (uint8_t)floor(clamp01(rgba[4 * i + c]) * 255 + 0.5);
        out[4 * i + 3] = 255;
    }
}

void gls_exact_rgb16(const float *rgba, size_t n, uint16_t *out)
{
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            out[3 * i + c] = (uint16_t)floor(clamp01(rgba[4 * i + c]) * 65535 + 0.5);
}

void gls_exact_rgbf(const float *rgba, size_t n, float *out)
{
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            out[3 * i + c] = (float)clamp01(rgba[4 * i + c]);
}
