/* Exact coverage: the convex polygon arithmetic (exact_int.h): a triangle
 * made ready (orientation, canonical edge lines, depth plane, pixel
 * bounds), lines moved to a pixel's local coordinates, the split of a
 * convex polygon by a line, and its area and centroid. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "exact_int.h"

static int lex_less(double ax, double ay, double bx, double by)
{
    return ax < bx || (ax == bx && ay < by);
}

static int clamp_px(double v, int n)
{
    if (v < 0)
        return 0;
    if (v > n - 1)
        return n - 1;
    return (int)v;
}

int exact_prep_tri(const gls_exact_tri *t, int w, int h, exact_prep *p)
{
    int o[3] = {0, 1, 2};
    for (int k = 0; k < 3; k++)
        if (!isfinite(t->x[k]) || !isfinite(t->y[k]) || !isfinite(t->iz[k]))
            return 0;
    double cr = (t->x[1] - t->x[0]) * (t->y[2] - t->y[0]) - (t->y[1] - t->y[0]) * (t->x[2] - t->x[0]);
    if (!(cr != 0))
        return 0;
    if (cr < 0)
        o[1] = 2, o[2] = 1;
    double iz[3];
    for (int k = 0; k < 3; k++)
        p->x[k] = t->x[o[k]], p->y[k] = t->y[o[k]], iz[k] = t->iz[o[k]];
    /* depth plane through the three vertices */
    double e1x = p->x[1] - p->x[0], e1y = p->y[1] - p->y[0], e2x = p->x[2] - p->x[0], e2y = p->y[2] - p->y[0];
    double d1 = iz[1] - iz[0], d2 = iz[2] - iz[0], det = e1x * e2y - e1y * e2x;
    p->z = (exact_plane){(d1 * e2y - d2 * e1y) / det, (e1x * d2 - e2x * d1) / det, p->x[0], p->y[0], iz[0]};
    for (int k = 0; k < 3; k++) {
        int a = k, b = (k + 1) % 3;
        double s = 1;
        if (lex_less(p->x[b], p->y[b], p->x[a], p->y[a]))
            a = b, b = k, s = -1;
        /* f(X) = cross(B - A, X - A): positive left of A -> B */
        p->e[k] = (exact_line){p->y[a] - p->y[b], p->x[b] - p->x[a], 0, p->x[a], p->y[a], s};
    }
    double xmin = fmin(p->x[0], fmin(p->x[1], p->x[2])), xmax = fmax(p->x[0], fmax(p->x[1], p->x[2]));
    double ymin = fmin(p->y[0], fmin(p->y[1], p->y[2])), ymax = fmax(p->y[0], fmax(p->y[1], p->y[2]));
    p->xmin = xmin, p->xmax = xmax, p->ymin = ymin, p->ymax = ymax;
    if (xmax + 0.5 < 0 || ymax + 0.5 < 0 || xmin - 0.5 > w - 1 || ymin - 0.5 > h - 1)
        return 0;
    p->i0 = clamp_px(ceil(xmin - 0.5), w), p->i1 = clamp_px(floor(xmax + 0.5), w);
    p->j0 = clamp_px(ceil(ymin - 0.5), h), p->j1 = clamp_px(floor(ymax + 0.5), h);
    return 1;
}

/* The half of pixel (i, j) where front's 1/Zc exceeds back's (front is
 * nearer), in local coordinates: both planes' constant terms taken at the
 * pixel centre, so the difference keeps its precision. */
exact_line exact_depth_line(const exact_plane *front, const exact_plane *back, double i, double j)
{
    double cf = exact_plane_at(front, i, j), cb = exact_plane_at(back, i, j);
    return (exact_line){front->a - back->a, front->b - back->b, cf - cb, 0, 0, 1};
}

void exact_pieces_clear(exact_pieces *p)
{
    p->nv = 0, p->np = 0;
}

void exact_pieces_free(exact_pieces *p)
{
    free(p->v), free(p->start);
    memset(p, 0, sizeof *p);
}

int exact_pieces_add(exact_pieces *p, const exact_pt *v, size_t n)
{
    if (p->nv + n > p->capv) {
        size_t c = p->capv ? p->capv : 64;
        while (c < p->nv + n)
            c *= 2;
        exact_pt *nv = realloc(p->v, c * sizeof *nv);
        if (!nv)
            return -1;
        p->v = nv, p->capv = c;
    }
    if (p->np + 2 > p->capp) {
        size_t c = p->capp ? p->capp * 2 : 16;
        size_t *ns = realloc(p->start, c * sizeof *ns);
        if (!ns)
            return -1;
        p->start = ns, p->capp = c;
    }
    if (p->np == 0)
        p->start[0] = 0;
    memcpy(p->v + p->nv, v, n * sizeof *v);
    p->nv += n;
    p->start[++p->np] = p->nv;
    return 0;
}

/* Where segment pq meets l, computed from its endpoints in lexicographic
 * order, so the same segment gives the same point from either side. */
static exact_pt crossing(exact_pt p, double fp, exact_pt q, double fq)
{
    if (lex_less(q.x, q.y, p.x, p.y)) {
        exact_pt t = p;
        double ft = fp;
        p = q, fp = fq, q = t, fq = ft;
    }
    double u = fp / (fp - fq);
    return (exact_pt){p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)};
}

void exact_clip(const exact_pt *v, size_t n, const exact_line *l, exact_pt *in, size_t *nin, exact_pt *out,
                size_t *nout)
{
    size_t ni = 0, no = 0;
    for (size_t k = 0; k < n; k++) {
        exact_pt p = v[k], q = v[(k + 1) % n];
        double fp = exact_line_f(l, p), fq = exact_line_f(l, q), sp = l->s * fp, sq = l->s * fq;
        if (sp >= 0)
            in[ni++] = p;
        if (sp <= 0)
            out[no++] = p;
        if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
            exact_pt x = crossing(p, fp, q, fq);
            in[ni++] = x, out[no++] = x;
        }
    }
    *nin = ni >= 3 ? ni : 0, *nout = no >= 3 ? no : 0;
}

/* Shoelace area (positive counter-clockwise) and, when mx is given, the
 * area-weighted centroid's sums (x area, y area) for the caller to add up. */
double exact_area(const exact_pt *v, size_t n, double *mx, double *my)
{
    double a = 0, sx = 0, sy = 0;
    for (size_t k = 0; k < n; k++) {
        exact_pt p = v[k], q = v[(k + 1) % n];
        double c = p.x * q.y - q.x * p.y;
        a += c, sx += (p.x + q.x) * c, sy += (p.y + q.y) * c;
    }
    if (mx)
        *mx = sx / 6, *my = sy / 6;
    return a / 2;
}
