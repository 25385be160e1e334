/* Exact coverage of a scene (exact_scene.h): the scene's triangles as
 * image triangles, their colours, and the exact image's conversions. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "exact_scene.h"
#include "lighting.h"

const char *gls_exact_scene_unsupported(const gls_scene *s)
{
    /* a shadow map is a sampled depth image: its edges are no area the
     * walk knows */
    if (s->lit && s->shadow_res)
        return "shadows (their maps are sampled depth images)";
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
                   uint32_t id, uint32_t v, uint32_t chunk, unsigned flags)
{
    if (reserve(g, g->n + 3))
        return -1;
    gls_exact_tri proto;
    memset(&proto, 0, sizeof proto);
    proto.id = id;
    proto.flags = (uint8_t)flags;
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
    vc.v = v, vc.inst = id, vc.chunk = chunk;
    for (int k = 0; k < 3; k++) {
        const double *a = vc.P[(k + 1) % 3], *b = vc.P[(k + 2) % 3];
        vc.C[k][0] = a[1] * b[2] - a[2] * b[1], vc.C[k][1] = a[2] * b[0] - a[0] * b[2];
        vc.C[k][2] = a[0] * b[1] - a[1] * b[0];
    }
    for (int k = 0; k < m; k++)
        g->v[g->n + k] = vc;
    g->n += (size_t)m;
    return 0;
}

/* GL's normal matrix of instance world W seen by camera R: the inverse
 * transpose of the modelview's 3x3, F R W^-T with F = diag(1, -1, -1)
 * (GL's eye axes); only its direction per vertex matters, the shader
 * normalises after interpolating, but a mirror's sign does. */
static void normal_matrix(const double W[16], const double R[9], double N[9])
{
    double a[9] = {W[0], W[1], W[2], W[4], W[5], W[6], W[8], W[9], W[10]}, ct[9];
    /* cofactors: cof(A)[r][c]; W^-T = cof / det */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            ct[3 * r + c] = a[3 * r1 + c1] * a[3 * r2 + c2] - a[3 * r1 + c2] * a[3 * r2 + c1];
        }
    double det = a[0] * ct[0] + a[1] * ct[1] + a[2] * ct[2];
    if (det == 0)
        det = 1;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0;
            for (int k = 0; k < 3; k++)
                v += R[3 * r + k] * ct[3 * k + c] / det;
            N[3 * r + c] = r ? -v : v;
        }
}

int gls_exact_geom_make(gls_exact_geom *g, const gls_scene *s, const gls_texture *textures, const gls_camera *c)
{
    memset(g, 0, sizeof *g);
    g->s = s, g->tex = textures;
    for (uint32_t k = 0; k < s->nchunks; k++)
        if (s->chunks[k].key.texture != GLS_NONE && !textures)
            return -1;
    if (s->lit) {
        /* the lights as lighting.c hands them to GL: float uniforms */
        g->nl = gls_lights_eye(s, c, g->lpos, g->lcol, g->amb);
        for (uint32_t k = 0; k < 4 * g->nl; k++)
            g->lpos[k] = (float)g->lpos[k], g->lcol[k] = (float)g->lcol[k];
        for (int k = 0; k < 3; k++)
            g->amb[k] = (float)g->amb[k];
        if (!(g->nm = malloc((s->ninst ? s->ninst : 1) * 9 * sizeof *g->nm)))
            return -1;
        for (uint32_t i = 0; i < s->ninst; i++)
            normal_matrix(s->inst[i].world, c->R, g->nm + 9 * (size_t)i);
    }
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
    gls_exact_view vp;
    gls_exact_view_make(&cam, c->width, c->height, &vp);
    size_t total = 0;
    for (uint32_t i = 0; i < s->ninst; i++)
        for (uint32_t ch = gls_exact_view_first(&vp, &cam, s, i); ch != GLS_NONE; ch = gls_exact_view_next(&vp, &cam, s, i, ch))
            total += s->chunks[ch].count / 3;
    if (reserve(g, total + 3))
        return -1;
    for (uint32_t i = 0; i < s->ninst; i++) {
        const gls_instance *in = &s->inst[i];
        for (uint32_t ch = gls_exact_view_first(&vp, &cam, s, i); ch != GLS_NONE; ch = gls_exact_view_next(&vp, &cam, s, i, ch)) {
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
                /* GL's alpha test (render.c, on when the scene has
                 * transparent texels) discards where alpha < 0.5: a
                 * triangle with such a texture, or a vertex alpha under
                 * 0.5, has holes */
                unsigned fl = s->lit || k->key.texture != GLS_NONE ? GLS_EXACT_SAMPLED : 0;
                if ((s->features & GLS_FEAT_ALPHA_TEST) &&
                    ((k->key.texture != GLS_NONE && (textures[k->key.texture].flags & GLS_TEX_ALPHA_HOLES)) ||
                     col[0][3] < 0.5f || col[1][3] < 0.5f || col[2][3] < 0.5f))
                    fl |= GLS_EXACT_HOLES | GLS_EXACT_SAMPLED;
                if (add_tri(g, &cam, P, col, i, v, ch, fl))
                    return -1;
            }
        }
    }
    return 0;
}

void gls_exact_geom_free(gls_exact_geom *g)
{
    free(g->t), free(g->v), free(g->nm);
    memset(g, 0, sizeof *g);
}

/* GL's perspective-correct weights of v's vertices over the image: the
 * barycentric coordinates of the point where the camera ray d through
 * (x, y) meets the triangle's plane, each the volume det(d, P[k+1],
 * P[k+2]) = d . C[k] over their sum.  d = ((x - cx - skew dy) / fx, dy,
 * 1) with dy = (y - cy) / fy is affine in (x, y), so each d . C[k] is
 * too: A[k] (x - cx) + B[k] (y - cy) + E[k], set up once for a
 * triangle's points; a point then costs six multiply-adds and one
 * division. */
typedef struct {
    double A[3], B[3], E[3];
} persp;

static void persp_make(const gls_exact_geom *g, const gls_exact_vcol *v, persp *q)
{
    for (int k = 0; k < 3; k++) {
        q->A[k] = v->C[k][0] / g->fx;
        q->B[k] = v->C[k][1] / g->fy - v->C[k][0] * g->skew / (g->fx * g->fy);
        q->E[k] = v->C[k][2];
    }
}

static void persp_weights(const gls_exact_geom *g, const persp *q, double x, double y, double w[3])
{
    double X = x - g->cx, Y = y - g->cy, sum = 0;
    for (int k = 0; k < 3; k++)
        w[k] = q->A[k] * X + q->B[k] * Y + q->E[k], sum += w[k];
    double inv = 1 / sum;
    for (int k = 0; k < 3; k++)
        w[k] *= inv;
}

/* k / 255 for each 8-bit value k, as GL reads an RGBA8 texel */
static const double unit8[256] = {
#define U4(k) (k) / 255.0, (k + 1) / 255.0, (k + 2) / 255.0, (k + 3) / 255.0
#define U16(k) U4(k), U4(k + 4), U4(k + 8), U4(k + 12)
#define U64(k) U16(k), U16(k + 16), U16(k + 32), U16(k + 48)
    U64(0.0), U64(64.0), U64(128.0), U64(192.0)
#undef U64
#undef U16
#undef U4
};

/* The texture's base level at texel-grid point (u, v) = (s W - 1/2,
 * t H - 1/2) as GL samples it with GL_LINEAR and GL_REPEAT (render.c):
 * texel centres at (i + 1/2) / W, t = 0 the image's bottom row (render.c
 * uploads bottom row first), 8-bit texels / 255.
 * The sampled reference's samples see the texture magnified, so GL takes
 * the base level there; a one-sample pass minifying it takes a mipmap. */
static void texel_uv(const gls_texture *tx, double u, double v, double out[4])
{
    int64_t W = tx->width, H = tx->height, i0, j0;
    double a, b;
    if (fabs(u) < 0x1p52 && fabs(v) < 0x1p52) {
        /* the common case, in integers: floor by truncation and a step
         * down, GL_REPEAT by the remainder (a mask for a power of two);
         * the same values as the general case below */
        int64_t iu = (int64_t)u, iv = (int64_t)v;
        iu -= (double)iu > u, iv -= (double)iv > v;
        a = u - (double)iu, b = v - (double)iv;
        i0 = (W & (W - 1)) == 0 ? iu & (W - 1) : (iu % W + W) % W;
        j0 = (H & (H - 1)) == 0 ? iv & (H - 1) : (iv % H + H) % H;
    } else {
        double fu = floor(u), fv = floor(v);
        a = u - fu, b = v - fv;
        /* GL_REPEAT: the texel index modulo the size */
        i0 = (int64_t)(fu - W * floor(fu / W)), j0 = (int64_t)(fv - H * floor(fv / H));
    }
    i0 = i0 < 0 ? 0 : i0 >= W ? W - 1 : i0, j0 = j0 < 0 ? 0 : j0 >= H ? H - 1 : j0;
    int64_t i1 = i0 + 1 == W ? 0 : i0 + 1, j1 = j0 + 1 == H ? 0 : j0 + 1;
    const uint8_t *r0 = tx->rgba + (size_t)(H - 1 - j0) * (size_t)W * 4, *r1 = tx->rgba + (size_t)(H - 1 - j1) * (size_t)W * 4;
    const uint8_t *p00 = r0 + 4 * i0, *p10 = r0 + 4 * i1, *p01 = r1 + 4 * i0, *p11 = r1 + 4 * i1;
    double w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b, w11 = a * b;
    /* texel / 255 from a table: no conversion or division a texel (9% of
     * the demo's CPU under --aa exact) */
    for (int q = 0; q < 4; q++)
        out[q] = w00 * unit8[p00[q]] + w10 * unit8[p10[q]] + w01 * unit8[p01[q]] + w11 * unit8[p11[q]];
}

/* texel_uv at texture coordinates (s, t) */
static void texel(const gls_texture *tx, double s, double t, double out[4])
{
    texel_uv(tx, s * tx->width - 0.5, t * tx->height - 0.5, out);
}

static const float *vattr(const gls_scene *s, uint32_t v, size_t off)
{
    return (const float *)(const void *)(s->verts + (size_t)v * s->stride + off);
}

/* lighting.c's fragment shader in double at the point with weights w:
 * albedo in, colour out (rgb; alpha is albedo's) */
static void light(const gls_exact_geom *g, const gls_exact_vcol *v, const double w[3], const double al[4], double c[3])
{
    const gls_scene *s = g->s;
    const double *M = g->nm + 9 * (size_t)v->inst;
    double eye[3] = {0, 0, 0}, n[3] = {0, 0, 0}, sp[4] = {0, 0, 0, 0};
    for (int k = 0; k < 3; k++) {
        const float *N = vattr(s, v->v + (uint32_t)k, s->normal_offset), *S = vattr(s, v->v + (uint32_t)k, s->specular_offset);
        double P[3] = {v->P[k][0], -v->P[k][1], -v->P[k][2]}; /* GL's eye axes */
        double m[3], lm = 0, l0 = (double)N[0] * N[0] + (double)N[1] * N[1] + (double)N[2] * N[2];
        for (int r = 0; r < 3; r++)
            m[r] = M[3 * r] * N[0] + M[3 * r + 1] * N[1] + M[3 * r + 2] * N[2], lm += m[r] * m[r];
        /* each vertex's normal by the normal matrix kept at its length,
         * as lighting.c's vertex shader and render.c's normals_to_world
         * (items near the camera) carry it */
        double sc = lm > 0 ? sqrt(l0 / lm) : 1;
        for (int r = 0; r < 3; r++) {
            eye[r] += w[k] * P[r];
            n[r] += w[k] * m[r] * sc;
        }
        for (int q = 0; q < 4; q++)
            sp[q] += w[k] * S[q];
    }
    /* a flat normal is the provoking (last) vertex's, of length 2 */
    const float *N2 = vattr(s, v->v + 2, s->normal_offset);
    int flat = (double)N2[0] * N2[0] + (double)N2[1] * N2[1] + (double)N2[2] * N2[2] > 2.0;
    double le = sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    double V[3] = {-eye[0] / le, -eye[1] / le, -eye[2] / le};
    double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int r = 0; r < 3; r++)
        n[r] = ln > 0 ? n[r] / ln : V[r];
    if (flat && n[0] * V[0] + n[1] * V[1] + n[2] * V[2] < 0)
        for (int r = 0; r < 3; r++)
            n[r] = -n[r];
    for (int r = 0; r < 3; r++)
        c[r] = g->amb[r] * al[r];
    int shiny = sp[0] + sp[1] + sp[2] > 0;
    for (uint32_t i = 0; i < g->nl; i++) {
        const double *pos = g->lpos + 4 * i, *col = g->lcol + 4 * i;
        double L[3] = {pos[0], pos[1], pos[2]}, att = 1;
        if (pos[3] != 0) {
            double d[3] = {pos[0] - eye[0], pos[1] - eye[1], pos[2] - eye[2]};
            double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            for (int r = 0; r < 3; r++)
                L[r] = d[r] / sqrt(d2);
            att = 1.0 / (1.0 + col[3] * d2);
        }
        double nl = n[0] * L[0] + n[1] * L[1] + n[2] * L[2];
        if (nl <= 0)
            continue;
        double rv = 0;
        if (shiny) { /* reflect(-L, n) = 2 (n.L) n - L */
            for (int r = 0; r < 3; r++)
                rv += (2 * nl * n[r] - L[r]) * V[r];
            rv = rv > 0 ? pow(rv, sp[3]) : 0;
        }
        for (int r = 0; r < 3; r++)
            c[r] += col[r] * att * (nl * al[r] + (shiny ? sp[r] * rv : 0));
    }
}

/* An unlit textured triangle's points (most of a textured scene's
 * shading): the weights' numerators n_k = A_k X + B_k Y + E_k are affine
 * in the point, and so are their sums against the texture coordinates in
 * texel units (u = s W - 1/2 = sum n_k (W s_k - 1/2) / sum n_k) and
 * against the vertex colours: a point costs three affine forms (seven
 * with modulate's colour), one division and the texel's fetch.  The
 * points' u and v first, a batch at a time, then their texels.  (Keeping
 * the last point's cell of four texels, to fetch them once for the points
 * in one cell, measured no faster on the road frame.) */
#define SHADE_BATCH 64
static void shade_textured(const gls_exact_geom *g, const gls_exact_vcol *v, const persp *pw, const gls_texture *tex,
                           const float T[3][2], int replace, const double *x, const double *y, size_t n,
                           float (*rgba)[4])
{
    /* rows: the weights' sum, u's and v's numerators, then modulate's
     * r, g, b, a numerators */
    double F[7][3] = {{0}};
    int nf = replace ? 3 : 7;
    for (int k = 0; k < 3; k++) {
        double ab[3] = {pw->A[k], pw->B[k], pw->E[k]};
        double cu = (double)T[k][0] * tex->width - 0.5, cv = (double)T[k][1] * tex->height - 0.5;
        for (int m = 0; m < 3; m++) {
            F[0][m] += ab[m], F[1][m] += cu * ab[m], F[2][m] += cv * ab[m];
            for (int q = 0; q < nf - 3; q++)
                F[3 + q][m] += (double)v->rgba[k][q] * ab[m];
        }
    }
    for (size_t p0 = 0; p0 < n; p0 += SHADE_BATCH) {
        size_t nb = n - p0 < SHADE_BATCH ? n - p0 : SHADE_BATCH;
        double u[SHADE_BATCH], w[SHADE_BATCH], r[SHADE_BATCH];
        for (size_t p = 0; p < nb; p++) {
            double X = x[p0 + p] - g->cx, Y = y[p0 + p] - g->cy;
            r[p] = 1 / (F[0][0] * X + F[0][1] * Y + F[0][2]);
            u[p] = (F[1][0] * X + F[1][1] * Y + F[1][2]) * r[p];
            w[p] = (F[2][0] * X + F[2][1] * Y + F[2][2]) * r[p];
        }
        for (size_t p = 0; p < nb; p++) {
            double tc[4];
            texel_uv(tex, u[p], w[p], tc);
            if (!replace) {
                double X = x[p0 + p] - g->cx, Y = y[p0 + p] - g->cy;
                for (int q = 0; q < 4; q++)
                    tc[q] *= (F[3 + q][0] * X + F[3 + q][1] * Y + F[3 + q][2]) * r[p];
            }
            /* the 8-bit framebuffer clamps every sample */
            for (int q = 0; q < 4; q++)
                rgba[p0 + p][q] = (float)(tc[q] < 0 ? 0 : tc[q] > 1 ? 1 : tc[q]);
        }
    }
}

void gls_exact_geom_shade(void *user, const gls_exact_tri *t, size_t i, const double *x, const double *y, size_t n,
                          float (*rgba)[4])
{
    const gls_exact_geom *g = user;
    const gls_exact_vcol *v = &g->v[i];
    if (!(t->flags & GLS_EXACT_SAMPLED) && !memcmp(v->rgba[0], v->rgba[1], sizeof v->rgba[0]) &&
        !memcmp(v->rgba[0], v->rgba[2], sizeof v->rgba[0])) {
        for (size_t p = 0; p < n; p++)
            memcpy(rgba[p], t->rgba, 4 * sizeof *rgba[p]); /* flat: exact */
        return;
    }
    /* what the points share, looked up once: the texture, its mode and
     * the vertices' texture coordinates */
    const gls_drawkey *k = &g->s->chunks[v->chunk].key;
    const gls_texture *tex = k->texture != GLS_NONE ? &g->tex[k->texture] : NULL;
    float T[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    if (tex && g->s->has_texcoord) /* else GL's current texture coordinate, (0, 0) */
        for (int e = 0; e < 3; e++) {
            const float *te = vattr(g->s, v->v + (uint32_t)e, g->s->texcoord_offset);
            T[e][0] = te[0], T[e][1] = te[1];
        }
    int replace = k->mode == GLS_MODE_REPLACE;
    persp pw;
    persp_make(g, v, &pw);
    if (tex && !g->s->lit) {
        shade_textured(g, v, &pw, tex, T, replace, x, y, n, rgba);
        return;
    }
    for (size_t p = 0; p < n; p++) {
        double w[3], col[4] = {0, 0, 0, 0}, out[4];
        persp_weights(g, &pw, x[p], y[p], w);
        if (!(tex && replace)) /* replace: the texel alone */
            for (int q = 0; q < 4; q++)
                col[q] = w[0] * v->rgba[0][q] + w[1] * v->rgba[1][q] + w[2] * v->rgba[2][q];
        if (tex) {
            double st[2] = {0, 0}, tc[4];
            for (int e = 0; e < 3; e++)
                st[0] += w[e] * T[e][0], st[1] += w[e] * T[e][1];
            texel(tex, st[0], st[1], tc);
            for (int q = 0; q < 4; q++)
                col[q] = replace ? tc[q] : tc[q] * col[q];
        }
        memcpy(out, col, sizeof out);
        if (g->s->lit)
            light(g, v, w, col, out);
        /* the 8-bit framebuffer clamps every sample */
        for (int q = 0; q < 4; q++)
            rgba[p][q] = (float)(out[q] < 0 ? 0 : out[q] > 1 ? 1 : out[q]);
    }
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
