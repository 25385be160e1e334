/* Exact coverage: the edge segments (exact.h, gls_exact_edges).
 *
 * Per pixel, from the candidates of the walk that makes the areas
 * (exact_visit_cands): every line a visible boundary can lie on there,
 * the candidates' edges and their pairs' equal-depth lines, is clipped to
 * the square; the points where a candidate's edge or two candidates'
 * equal depth cross it cut it into pieces along which nothing changes, so
 * one point of each piece (its middle) decides for all of it which
 * candidate is in front on each side: a candidate covers a side if the
 * point is inside it, or on its edge with its inside on that side; among
 * those the nearer 1/Zc wins, at equal depth (the line is their
 * equal-depth line) the one that grows nearer towards the side, then the
 * lower index, as the areas do.  A piece is a segment where the two ids
 * differ, reported once: by the lowest-index triangle with an edge on it,
 * an equal-depth line only where no edge lies and its own two triangles
 * are the two sides.  All in pixel-local coordinates (exact_int.h). */
#include <math.h>
#include <stdlib.h>
#include "exact_int.h"

#define ON_LINE 1e-9 /* px: a point this near an edge's line is on it */

typedef struct {
    const gls_exact_tri *t;
    const uint16_t *idmap;
    gls_exact_seg_fn fn;
    void *user;
    int w, h;
    double *bp;         /* breakpoints along the line                      */
    size_t capbp;
    double *cz;         /* pixel.cz's room                                 */
    size_t capcz;
} edge_ctx;

typedef struct {
    const exact_prep *p;
    const exact_cand *c;
    size_t nc;
    double i, j;
    double *cz;         /* the candidates' 1/Zc at the pixel centre        */
} pixel;

static double plane_local(const pixel *px, size_t u, double x, double y)
{
    const exact_plane *z = &px->p[px->c[u].tri].z;
    return px->cz[u] + z->a * x + z->b * y;
}

/* edge k of candidate u at local point (x, y): its kept-side value over
 * the gradient's length, a signed distance */
static double edge_dist(const pixel *px, size_t u, int k, double x, double y)
{
    const exact_line *l = &px->p[px->c[u].tri].e[k];
    double f = l->a * (x - (l->ox - px->i)) + l->b * (y - (l->oy - px->j));
    return l->s * f / hypot(l->a, l->b);
}

/* -1 no, else the edge (0..2) that the point lies on, or 3: inside */
static int covers(const pixel *px, size_t u, double x, double y, double nx, double ny)
{
    int on = 3;
    for (int k = 0; k < 3; k++) {
        double d = edge_dist(px, u, k, x, y);
        if (d > ON_LINE)
            continue;
        if (d < -ON_LINE)
            return -1;
        const exact_line *l = &px->p[px->c[u].tri].e[k];
        if (!(l->s * (l->a * nx + l->b * ny) > 0))
            return -1;
        on = k;
    }
    return on;
}

/* the point lies on one of candidate u's edges (the closed triangle's
 * border) */
static int on_edge(const pixel *px, size_t u, double x, double y)
{
    int on = 0;
    for (int k = 0; k < 3; k++) {
        double d = edge_dist(px, u, k, x, y);
        if (d < -ON_LINE)
            return 0;
        on |= d <= ON_LINE;
    }
    return on;
}

/* the candidate in front on the side (nx, ny) of local point (x, y), or
 * (size_t)-1: the background */
static size_t front(const pixel *px, double x, double y, double nx, double ny)
{
    size_t best = (size_t)-1;
    double bz = 0, bd = 0;
    for (size_t u = 0; u < px->nc; u++) {
        if (covers(px, u, x, y, nx, ny) < 0)
            continue;
        const exact_plane *z = &px->p[px->c[u].tri].z;
        double zu = plane_local(px, u, x, y), du = z->a * nx + z->b * ny;
        int nearer;
        if (best == (size_t)-1)
            nearer = 1;
        else if (fabs(zu - bz) > 1e-12 * (fabs(zu) + fabs(bz)))
            nearer = zu > bz;
        else if (du != bd)
            nearer = du > bd;
        else
            nearer = px->c[u].tri < px->c[best].tri;
        if (nearer)
            best = u, bz = zu, bd = du;
    }
    return best;
}

static uint32_t id_of(const edge_ctx *e, const pixel *px, size_t u)
{
    if (u == (size_t)-1)
        return 0;
    uint32_t d = e->t[px->c[u].tri].id;
    return e->idmap ? e->idmap[d] : d;
}

static int add_bp(edge_ctx *e, size_t *n, double s)
{
    if (*n == e->capbp) {
        size_t c = e->capbp ? 2 * e->capbp : 64;
        double *b = realloc(e->bp, c * sizeof *b);
        if (!b)
            return -1;
        e->bp = b, e->capbp = c;
    }
    e->bp[(*n)++] = s;
    return 0;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* where f, affine along the line (f0 at s0, f1 at s1), crosses 0 inside */
static int cross(edge_ctx *e, size_t *n, double s0, double s1, double f0, double f1)
{
    if ((f0 < 0 && f1 > 0) || (f0 > 0 && f1 < 0))
        return add_bp(e, n, s0 + (s1 - s0) * (f0 / (f0 - f1)));
    return 0;
}

/* The line P + s D, s in [s0, s1] within the square, from candidate
 * `own` (edge `k`, or k -1: the equal-depth line of own and `other`) */
static int label(edge_ctx *e, const pixel *px, double Px, double Py, double Dx, double Dy, double s0, double s1,
                 size_t own, int k, size_t other)
{
    size_t n = 0;
    if (add_bp(e, &n, s0) || add_bp(e, &n, s1))
        return -1;
    double ax = Px + s0 * Dx, ay = Py + s0 * Dy, bx = Px + s1 * Dx, by = Py + s1 * Dy;
    for (size_t u = 0; u < px->nc; u++) {
        for (int q = 0; q < 3; q++)
            if (cross(e, &n, s0, s1, edge_dist(px, u, q, ax, ay), edge_dist(px, u, q, bx, by)))
                return -1;
        for (size_t v = u + 1; v < px->nc; v++)
            if (cross(e, &n, s0, s1, plane_local(px, u, ax, ay) - plane_local(px, v, ax, ay),
                      plane_local(px, u, bx, by) - plane_local(px, v, bx, by)))
                return -1;
    }
    qsort(e->bp, n, sizeof *e->bp, cmp_d);
    /* left as seen in the image, y down: (Dy, -Dx) */
    double ln = hypot(Dx, Dy), lx = Dy / ln, ly = -Dx / ln;
    double ra = 0, rb = 0;
    uint32_t rl = 0, rr = 0;
    int run = 0;
    for (size_t q = 0; q + 1 <= n; q++) {
        int keep = 0;
        uint32_t il = 0, ir = 0;
        double sa = q + 1 < n ? e->bp[q] : 0, sb = q + 1 < n ? e->bp[q + 1] : 0;
        if (q + 1 < n && sb > sa) {
            double m = 0.5 * (sa + sb), x = Px + m * Dx, y = Py + m * Dy;
            size_t fl = front(px, x, y, lx, ly), fr = front(px, x, y, -lx, -ly);
            il = id_of(e, px, fl), ir = id_of(e, px, fr);
            keep = il != ir;
            /* reported once: by the lowest-index triangle with an edge
             * here; an equal-depth line only where no edge lies and it
             * parts its own two triangles */
            for (size_t u = 0; u < px->nc && keep; u++)
                if (u != own && (k < 0 || px->c[u].tri < px->c[own].tri) && on_edge(px, u, x, y))
                    keep = 0;
            if (k < 0 && keep)
                keep = (fl == own && fr == other) || (fl == other && fr == own);
        }
        if (run && (!keep || il != rl || ir != rr || q + 1 >= n)) {
            gls_exact_seg g = {Px + ra * Dx + px->i, Py + ra * Dy + px->j, Px + rb * Dx + px->i,
                               Py + rb * Dy + px->j, rl, rr};
            e->fn(e->user, &g);
            run = 0;
        }
        if (keep) {
            if (!run)
                ra = sa, rl = il, rr = ir, run = 1;
            rb = sb;
        }
    }
    return 0;
}

/* clip P + s D, s in [*s0, *s1], to the square [-0.5, 0.5]^2 */
static int clip_square(double Px, double Py, double Dx, double Dy, double *s0, double *s1)
{
    double p[2] = {Px, Py}, d[2] = {Dx, Dy};
    for (int a = 0; a < 2; a++) {
        if (d[a] == 0) {
            if (p[a] < -0.5 || p[a] > 0.5)
                return 0;
            continue;
        }
        double t0 = (-0.5 - p[a]) / d[a], t1 = (0.5 - p[a]) / d[a];
        if (t0 > t1) {
            double s = t0;
            t0 = t1, t1 = s;
        }
        if (t0 > *s0)
            *s0 = t0;
        if (t1 < *s1)
            *s1 = t1;
    }
    return *s1 > *s0;
}

/* a piece on the square's right or lower border is the next pixel's; one
 * on the image's border is no one's */
static int on_border(const edge_ctx *e, const pixel *px, double Px, double Py, double Dx, double Dy)
{
    if (Dx == 0 && (Px == 0.5 || (Px == -0.5 && px->i == 0)))
        return 1;
    if (Dy == 0 && (Py == 0.5 || (Py == -0.5 && px->j == 0)))
        return 1;
    (void)e;
    return 0;
}

static int edge_pixel(void *user, const exact_prep *p, const exact_cand *c, size_t nc, int i, int j)
{
    edge_ctx *e = user;
    if (nc == 0 || (nc == 1 && c[0].inside))
        return 0;
    if (nc > e->capcz) {
        double *z = realloc(e->cz, nc * sizeof *z);
        if (!z)
            return -1;
        e->cz = z, e->capcz = nc;
    }
    pixel px = {p, c, nc, i, j, e->cz};
    for (size_t u = 0; u < nc; u++)
        px.cz[u] = exact_plane_at(&p[c[u].tri].z, i, j);
    for (size_t u = 0; u < nc; u++) {
        const exact_prep *T = &p[c[u].tri];
        for (int k = 0; k < 3 && !c[u].inside; k++) {
            const exact_line *l = &T->e[k];
            double Px = l->ox - i, Py = l->oy - j, Dx = l->b, Dy = -l->a, s0 = 0, s1 = 1;
            if (!clip_square(Px, Py, Dx, Dy, &s0, &s1) || on_border(e, &px, Px, Py, Dx, Dy))
                continue;
            if (label(e, &px, Px, Py, Dx, Dy, s0, s1, u, k, 0))
                return -1;
        }
        for (size_t v = u + 1; v < nc; v++) {
            if (c[u].zmax < c[v].zmin || c[v].zmax < c[u].zmin)
                continue;
            exact_line d = exact_depth_line(&T->z, &p[c[v].tri].z, i, j);
            double g = d.a * d.a + d.b * d.b;
            if (!(g > 0))
                continue;
            /* the line's point nearest the centre, and its direction taken
             * lexicographically first to last */
            double Px = -d.c * d.a / g, Py = -d.c * d.b / g, Dx = -d.b, Dy = d.a, s0 = -INFINITY, s1 = INFINITY;
            if (Dx < 0 || (Dx == 0 && Dy < 0))
                Dx = -Dx, Dy = -Dy;
            if (!clip_square(Px, Py, Dx, Dy, &s0, &s1) || on_border(e, &px, Px, Py, Dx, Dy))
                continue;
            if (label(e, &px, Px, Py, Dx, Dy, s0, s1, u, -1, v))
                return -1;
        }
    }
    return 0;
}

int gls_exact_edges(const gls_exact_tri *t, size_t n, int w, int h, const uint16_t *idmap, gls_exact_seg_fn fn,
                    void *user)
{
    edge_ctx e = {t, idmap, fn, user, w, h, NULL, 0, NULL, 0};
    int rc = exact_visit_cands(t, n, w, h, edge_pixel, &e);
    free(e.bp), free(e.cz);
    return rc;
}
