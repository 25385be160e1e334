/* Exact coverage: the box-filtered colour image (exact.h,
 * gls_exact_image): each pixel the sum of its visible regions' exact areas
 * times their colours, the colour of a region its triangle's at the
 * region's centroid (exact for colour affine in the image) or, for a
 * sampled triangle (textured, lit), the mean of its colour at the
 * pixel's lattice points in the region, and the uncovered rest the
 * background's. */
#include <stdlib.h>
#include <string.h>
#include "exact_int.h"
#include "lattice.h"

typedef struct {
    const gls_exact_tri *t;
    const float *bg;
    gls_exact_shade_fn shade;
    void *user;
    float *rgba;
    const uint16_t *idmap;
    gls_exact_cover *cover;
    int w;
    int oom;            /* a pixel's scratch could not be allocated (set
                           from any worker: atomically)                  */
    double lx[GLS_EXACT_SHADE_M], ly[GLS_EXACT_SHADE_M]; /* the lattice
                           points, pixel-local ([-0.5, 0.5)^2)           */
} image_ctx;

/* Per region of a pixel: its colour. */
typedef struct region {
    float col[4];
    /* its triangle's edge functions and 1/Zc times twice its signed
     * area, affine in the pixel-local point: v[0] + v[1] x + v[2] y */
    double e[3][3], z[3], a;
} region;

/* The regions' edge functions in pixel (px, py): with a = X - x, b = Y - y
 * (X, Y the vertex pixel-local), e_q = a_{q+1} b_{q+2} - a_{q+2} b_{q+1}
 * is affine in (x, y) (the xy terms cancel), and so is sum e_q iz_q. */
static void regions_prep(const image_ctx *c, int px, int py, const gls_exact_frag *f, size_t n, region *r)
{
    for (size_t k = 0; k < n; k++) {
        const gls_exact_tri *t = &c->t[f[k].tri];
        double X[3], Y[3];
        for (int q = 0; q < 3; q++)
            X[q] = t->x[q] - px, Y[q] = t->y[q] - py;
        r[k].a = 0, r[k].z[0] = r[k].z[1] = r[k].z[2] = 0;
        for (int q = 0; q < 3; q++) {
            int u = (q + 1) % 3, v = (q + 2) % 3;
            double *e = r[k].e[q];
            e[0] = X[u] * Y[v] - X[v] * Y[u], e[1] = Y[u] - Y[v], e[2] = X[v] - X[u];
            r[k].a += e[0];
            for (int m = 0; m < 3; m++)
                r[k].z[m] += e[m] * t->iz[q];
        }
    }
}

/* Which of the pixel's regions shows at each of the lattice points
 * ms[0..np): the frag whose triangle contains it and is nearest there
 * (larger 1/Zc, ties the lower triangle index, the walk's rule), into
 * own[p] (n: none, the background), with its 1/Zc and triangle in bz[p],
 * bt[p].  The frags hold every triangle visible in the pixel, so the one
 * in front among them is the one in front among all.  Points on a shared
 * edge go to either side: a set of measure zero.  tz NULL: among all
 * regions; else among those behind the point's (tz[p], tt[p]) in that
 * order, the next surface down once the alpha test has dropped that one
 * (holes_pixel).  A region at a time over all the points, without
 * branches: point by point, the owners were a sixth of the road frame's
 * CPU. */
static void front(const image_ctx *c, const gls_exact_frag *f, size_t n, const region *r, const int *ms, size_t np,
                  const double *tz, const size_t *tt, size_t *own, double *bz, size_t *bt)
{
    double x[GLS_EXACT_SHADE_M], y[GLS_EXACT_SHADE_M];
    for (size_t p = 0; p < np; p++)
        x[p] = c->lx[ms[p]], y[p] = c->ly[ms[p]], own[p] = n, bz[p] = 0, bt[p] = 0;
    for (size_t k = 0; k < n; k++) {
        const region *g = &r[k];
        double a = g->a;
        if (a == 0)
            continue;
        /* the tests' sign: e < 0 outside when a > 0, e > 0 when a < 0;
         * negating every coefficient is exact, so -e is the same value
         * negated */
        double sg = a > 0 ? 1 : -1, E[3][3], Z[3] = {g->z[0], g->z[1], g->z[2]};
        for (int q = 0; q < 3; q++)
            for (int u = 0; u < 3; u++)
                E[q][u] = sg * g->e[q][u];
        size_t tri = f[k].tri;
        for (size_t p = 0; p < np; p++) {
            double e0 = E[0][0] + E[0][1] * x[p] + E[0][2] * y[p], e1 = E[1][0] + E[1][1] * x[p] + E[1][2] * y[p],
                   e2 = E[2][0] + E[2][1] * x[p] + E[2][2] * y[p];
            /* e[q] / a: the point's barycentric weight of vertex q; 1/Zc
             * is affine in the image */
            double z = (Z[0] + Z[1] * x[p] + Z[2] * y[p]) / a;
            int in = !(e0 < 0) & !(e1 < 0) & !(e2 < 0);
            int behind = tz ? (z < tz[p]) | ((z == tz[p]) & (tri > tt[p])) : 1;
            int better = in & behind & ((own[p] == n) | (z > bz[p]) | ((z == bz[p]) & (tri < bt[p])));
            own[p] = better ? k : own[p];
            bz[p] = better ? z : bz[p];
            bt[p] = better ? tri : bt[p];
        }
    }
}

/* The shader at one point */
static void shade1(const image_ctx *c, size_t tri, double x, double y, float v[4])
{
    float o[1][4];
    c->shade(c->user, &c->t[tri], tri, &x, &y, 1, o);
    for (int q = 0; q < 4; q++)
        v[q] = o[0][q];
}

/* The shader at lattice points ms[0..cnt) of triangle tri, in one call,
 * into v[ms[p]] (the flat colour without a shader) */
static void shade_group(const image_ctx *c, int px, int py, size_t tri, const int *ms, size_t cnt, float (*v)[4])
{
    const gls_exact_tri *t = &c->t[tri];
    if (!cnt)
        return;
    if (c->shade) {
        double x[GLS_EXACT_SHADE_M], y[GLS_EXACT_SHADE_M];
        float o[GLS_EXACT_SHADE_M][4];
        for (size_t p = 0; p < cnt; p++)
            x[p] = px + c->lx[ms[p]], y[p] = py + c->ly[ms[p]];
        c->shade(c->user, t, tri, x, y, cnt, o);
        for (size_t p = 0; p < cnt; p++)
            memcpy(v[ms[p]], o[p], sizeof v[0]);
    } else
        for (size_t p = 0; p < cnt; p++)
            memcpy(v[ms[p]], t->rgba, sizeof v[0]);
}

/* The shader at the lattice points m that region k owns (own[m] == k),
 * into v[m]; their count. */
static size_t shade_owned(const image_ctx *c, int px, int py, const gls_exact_frag *f, size_t k, const size_t *own,
                          float (*v)[4])
{
    int at[GLS_EXACT_SHADE_M];
    size_t cnt = 0;
    for (int m = 0; m < GLS_EXACT_SHADE_M; m++)
        if (own[m] == k)
            at[cnt++] = m;
    shade_group(c, px, py, f[k].tri, at, cnt, v);
    return cnt;
}

/* The colours of the pixel's sampled regions (f[k] with a sampled
 * triangle): the mean of the shader at the lattice points each region
 * owns, into r[k].col, summed in lattice order; the centroid's where it
 * owns none. */
static void sampled_colours(const image_ctx *c, int px, int py, const gls_exact_frag *f, size_t n, region *r)
{
    int full = n == 1 && f[0].area == 1.0;
    size_t own[GLS_EXACT_SHADE_M];
    float v[GLS_EXACT_SHADE_M][4];
    if (!full)
        regions_prep(c, px, py, f, n, r);
    if (full)
        for (int m = 0; m < GLS_EXACT_SHADE_M; m++)
            own[m] = 0;
    else {
        int ms[GLS_EXACT_SHADE_M];
        double bz[GLS_EXACT_SHADE_M];
        size_t bt[GLS_EXACT_SHADE_M];
        for (int m = 0; m < GLS_EXACT_SHADE_M; m++)
            ms[m] = m;
        front(c, f, n, r, ms, GLS_EXACT_SHADE_M, NULL, NULL, own, bz, bt);
    }
    for (size_t k = 0; k < n; k++) {
        if (!(c->t[f[k].tri].flags & GLS_EXACT_SAMPLED))
            continue;
        size_t cnt = shade_owned(c, px, py, f, k, own, v);
        if (!cnt) {
            shade1(c, f[k].tri, f[k].cx, f[k].cy, r[k].col);
            continue;
        }
        double sum[4] = {0, 0, 0, 0};
        for (int m = 0; m < GLS_EXACT_SHADE_M; m++)
            if (own[m] == k)
                for (int q = 0; q < 4; q++)
                    sum[q] += v[m][q];
        for (int q = 0; q < 4; q++)
            r[k].col[q] = (float)(sum[q] / (double)cnt);
    }
}

/* The pixel's areas summed per id (a pixel shows few ids: a list, on
 * the stack up to 32, else allocated), the K largest into out.  Out of
 * memory leaves the pixel's slots empty. */
static void pixel_cover(const image_ctx *c, const gls_exact_frag *f, size_t n, gls_exact_cover *out)
{
    double stack_a[32], *sa = stack_a, area[GLS_EXACT_COVER_K];
    uint32_t stack_i[32], *si = stack_i, id[GLS_EXACT_COVER_K];
    size_t ns = 0;
    int m = 0;
    for (int k = 0; k < GLS_EXACT_COVER_K; k++)
        out[k] = (gls_exact_cover){0, 0};
    if (n > 32 && (!(sa = malloc(n * sizeof *sa)) || !(si = malloc(n * sizeof *si)))) {
        if (sa != stack_a)
            free(sa);
        return;
    }
    for (size_t k = 0; k < n; k++) {
        uint32_t d = c->t[f[k].tri].id;
        if (c->idmap)
            d = c->idmap[d];
        if (!d)
            continue;
        size_t q = 0;
        while (q < ns && si[q] != d)
            q++;
        if (q == ns)
            si[ns] = d, sa[ns++] = 0;
        sa[q] += f[k].area;
    }
    /* insertion into the K largest, largest first, ties by the smaller id */
    for (size_t q = 0; q < ns; q++) {
        int at = m;
        while (at > 0 && (sa[q] > area[at - 1] || (sa[q] == area[at - 1] && si[q] < id[at - 1])))
            at--;
        if (at >= GLS_EXACT_COVER_K)
            continue;
        if (m < GLS_EXACT_COVER_K)
            m++;
        for (int r = m - 1; r > at; r--)
            area[r] = area[r - 1], id[r] = id[r - 1];
        area[at] = sa[q], id[at] = si[q];
    }
    for (int k = 0; k < m; k++)
        out[k] = (gls_exact_cover){id[k], (float)area[k]};
    if (sa != stack_a)
        free(sa), free(si);
}

/* A pixel an alpha-tested triangle shows in (GLS_EXACT_HOLES):
 * the mean over the lattice points of the nearest surface there whose
 * alpha passes (GL's alpha test: at least 0.5), or the background.  Layer
 * by layer: the points' nearest surfaces, shaded a region's points in one
 * call; then, for the points whose alpha failed, the next surface behind
 * each, and so on. */
static void holes_pixel(const image_ctx *c, int px, int py, const gls_exact_frag *f, size_t n, region *r,
                        double acc[4])
{
    int ms[GLS_EXACT_SHADE_M];
    size_t own[GLS_EXACT_SHADE_M], bt[GLS_EXACT_SHADE_M], tt[GLS_EXACT_SHADE_M];
    double bz[GLS_EXACT_SHADE_M], tz[GLS_EXACT_SHADE_M];
    float v[GLS_EXACT_SHADE_M][4];
    regions_prep(c, px, py, f, n, r);
    for (int m = 0; m < GLS_EXACT_SHADE_M; m++)
        ms[m] = m;
    size_t np = GLS_EXACT_SHADE_M;
    front(c, f, n, r, ms, np, NULL, NULL, own, bz, bt);
    for (;;) {
        /* the points ms[0..np) at their surfaces own[], a region's in
         * one call (each region's points picked out in turn) */
        unsigned char done[GLS_EXACT_SHADE_M] = {0};
        for (size_t p = 0; p < np; p++) {
            if (done[p])
                continue;
            int grp[GLS_EXACT_SHADE_M];
            size_t cnt = 0;
            for (size_t q = p; q < np; q++)
                if (!done[q] && own[q] == own[p])
                    grp[cnt++] = ms[q], done[q] = 1;
            if (own[p] == n)
                for (size_t q = 0; q < cnt; q++)
                    memcpy(v[grp[q]], c->bg, sizeof v[0]);
            else
                shade_group(c, px, py, f[own[p]].tri, grp, cnt, v);
        }
        /* those the alpha test drops go on behind their surface */
        size_t keep = 0;
        for (size_t p = 0; p < np; p++)
            if (own[p] < n && (c->t[f[own[p]].tri].flags & GLS_EXACT_HOLES) && v[ms[p]][3] < 0.5f)
                ms[keep] = ms[p], tz[keep] = bz[p], tt[keep] = bt[p], keep++;
        if (!keep)
            break;
        np = keep;
        front(c, f, n, r, ms, np, tz, tt, own, bz, bt);
    }
    for (int m = 0; m < GLS_EXACT_SHADE_M; m++)
        for (int q = 0; q < 4; q++)
            acc[q] += v[m][q] / GLS_EXACT_SHADE_M;
}

static void image_pixel(void *user, int px, int py, const gls_exact_frag *f, size_t n)
{
    image_ctx *c = user;
    double acc[4] = {0, 0, 0, 0}, cover = 0;
    size_t at = (size_t)py * (size_t)c->w + (size_t)px;
    if (c->cover)
        pixel_cover(c, f, n, c->cover + at * GLS_EXACT_COVER_K);
    if (!c->rgba)
        return;
    /* unresolved frags (area NaN): an alpha-tested pixel's, or a dense
     * one's (gls_exact_render's dense): point-sampled */
    int holes = n && f[0].area != f[0].area, any = 0;
    for (size_t k = 0; k < n; k++)
        holes |= (c->t[f[k].tri].flags & GLS_EXACT_HOLES) != 0, any |= (c->t[f[k].tri].flags & GLS_EXACT_SAMPLED) != 0;
    /* per region scratch: on the stack for up to 64 regions, else
     * allocated (a far hillside's slivers put hundreds in a pixel) */
    region stack_r[64], *r = stack_r;
    if ((holes || (any && c->shade)) && n > 64 && !(r = malloc(n * sizeof *r))) {
        __atomic_store_n(&c->oom, 1, __ATOMIC_RELAXED);
        return;
    }
    if (holes) {
        double h[4] = {0, 0, 0, 0};
        holes_pixel(c, px, py, f, n, r, h);
        for (int q = 0; q < 4; q++)
            c->rgba[at * 4 + q] = (float)h[q];
        if (r != stack_r)
            free(r);
        return;
    }
    if (any && c->shade)
        sampled_colours(c, px, py, f, n, r);
    for (size_t k = 0; k < n; k++) {
        float col[4];
        const gls_exact_tri *t = &c->t[f[k].tri];
        if (c->shade && (t->flags & GLS_EXACT_SAMPLED))
            for (int q = 0; q < 4; q++)
                col[q] = r[k].col[q];
        else if (c->shade)
            shade1(c, f[k].tri, f[k].cx, f[k].cy, col);
        else
            for (int q = 0; q < 4; q++)
                col[q] = t->rgba[q];
        for (int q = 0; q < 4; q++)
            acc[q] += f[k].area * col[q];
        cover += f[k].area;
    }
    /* rounding can put the sum of areas a few ulps over 1 */
    double rest = cover < 1 ? 1 - cover : 0;
    float *o = c->rgba + at * 4;
    for (int q = 0; q < 4; q++)
        o[q] = (float)(acc[q] + rest * c->bg[q]);
    if (r != stack_r)
        free(r);
}

int gls_exact_image(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                    void *user, float *rgba)
{
    return gls_exact_render(t, n, w, h, bg, shade, user, NULL, rgba, NULL, 0);
}

int gls_exact_render(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                     void *user, const uint16_t *idmap, float *rgba, gls_exact_cover *cover, size_t dense)
{
    image_ctx c = {t, bg, shade, user, rgba, idmap, cover, w, 0, {0}, {0}};
    /* the lattice the sampled path uses at that count (lattice.c) */
    gls_lattice l;
    if (gls_lattice_choose(GLS_EXACT_SHADE_M, &l))
        return -1;
    for (int m = 0; m < GLS_EXACT_SHADE_M; m++) {
        int64_t x, y;
        gls_lattice_point(&l, (uint64_t)m, &x, &y);
        c.lx[m] = (double)x / (double)l.q - 0.5, c.ly[m] = (double)y / (double)l.q - 0.5;
    }
    /* each pixel's value depends on its frags only and is written to its
     * own place: the workers compute it (the shading is most of the work
     * on textured scenes) */
    return exact_visit_dense(t, n, w, h, image_pixel, &c, cover ? 0 : dense) || c.oom ? -1 : 0;
}
