/* Exact coverage: the pixels (exact.h, gls_exact_visit).
 *
 * The image is done in bands of EXACT_BAND rows, so memory is bounded by a
 * band and the candidates in it.  In a band, each triangle's pixels (its
 * bounding box's) are classified with the conservative edge test: inside
 * (the whole square on the kept side of all three edges), outside (the
 * whole square beyond one), or crossed; the margins are widened by a
 * bound on the rounding, so a doubtful pixel is called crossed, which
 * costs time and never accuracy.  Pass 1 finds, per pixel, the largest
 * least 1/Zc over the square of a triangle covering it whole (the nearest
 * full cover, F); pass 2 keeps as the pixel's candidates the triangles
 * that reach nearer than F somewhere in the square (those entirely behind
 * it are hidden).  A pixel with one candidate that covers it whole shows
 * it with area 1: the uncrossed pixels.  The others are resolved exactly:
 * each candidate clipped to the square, and every other candidate's part
 * of the square where it is nearer (its triangle and the half-plane of its
 * equal-depth line) cut away, candidates taken front to back so that a
 * hidden triangle stops early. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "exact_int.h"

#define EXACT_BAND 16

struct exact_work {
    const exact_prep *prep;
    const gls_exact_tri *tris;
    exact_pieces cur, next;
    exact_pt *buf[3];   /* clip buffers: the piece, its two parts          */
    size_t cap[3];
    gls_exact_frag *frags;
    size_t capf;
    exact_cand_fn cands; /* exact_visit_cands: the candidates, no frags   */
    void *cuser;
};

/* 1 the square of pixel (i, j) is inside, -1 outside, 0 crossed */
static int classify(const exact_prep *p, double i, double j)
{
    int inside = 1;
    for (int k = 0; k < 3; k++) {
        const exact_line *l = &p->e[k];
        double fx = l->a * (i - l->ox), fy = l->b * (j - l->oy), f = l->s * (fx + fy);
        double half = 0.5 * (fabs(l->a) + fabs(l->b));
        double eps = 1e-9 * half + 4e-16 * (fabs(fx) + fabs(fy));
        if (f < -(half + eps))
            return -1;
        if (f < half + eps)
            inside = 0;
    }
    return inside;
}

static void zrange(const exact_plane *z, double i, double j, double *lo, double *hi)
{
    double c = exact_plane_at(z, i, j), d = 0.5 * (fabs(z->a) + fabs(z->b));
    double e = 1e-12 * (fabs(c) + fabs(z->z0) + fabs(z->a * (i - z->x0)) + fabs(z->b * (j - z->y0)) + d);
    *lo = c - d - e, *hi = c + d + e;
}

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t c = *cap ? *cap : 16;
    while (c < need)
        c *= 2;
    void *n = realloc(*p, c * size);
    if (!n)
        return -1;
    *p = n, *cap = c;
    return 0;
}

/* Remove from each piece of w->cur the convex region inside all of the
 * lines l[0..nl) (their kept halves), into w->next; then swap. */
static int subtract(exact_work *w, const exact_line *l, int nl)
{
    /* the common case, a region beyond one of its lines from every piece,
     * changes nothing: no copy */
    size_t k0 = 0;
    for (; k0 < w->cur.np; k0++) {
        const exact_pt *pv = w->cur.v + w->cur.start[k0];
        size_t n = w->cur.start[k0 + 1] - w->cur.start[k0];
        int apart = 0;
        for (int m = 0; m < nl && !apart; m++)
            apart = exact_line_side(pv, n, &l[m]) < 0;
        if (!apart)
            break;
    }
    if (k0 == w->cur.np)
        return 0;
    exact_pieces_clear(&w->next);
    for (size_t k = 0; k < w->cur.np; k++) {
        size_t n = w->cur.start[k + 1] - w->cur.start[k];
        const exact_pt *pv = w->cur.v + w->cur.start[k];
        int cut[4], ncut = 0, apart = 0;
        for (int m = 0; m < nl && !apart; m++) {
            int side = exact_line_side(pv, n, &l[m]);
            apart = side < 0;
            if (side == 0)
                cut[ncut++] = m;
        }
        if (apart || ncut == 0) { /* beyond one line: untouched; inside all: gone */
            if (apart && exact_pieces_add(&w->next, pv, n))
                return -1;
            continue;
        }
        /* a split makes at most 2n + 2 vertices (n + 1 when convex) */
        if (grow((void **)&w->buf[0], &w->cap[0], n, sizeof(exact_pt)))
            return -1;
        int iv = 0, iin = 1, iout = 2;
        memcpy(w->buf[iv], pv, n * sizeof(exact_pt));
        for (int c = 0; c < ncut && n; c++) {
            int m = cut[c];
            if (grow((void **)&w->buf[iin], &w->cap[iin], 2 * n + 2, sizeof(exact_pt)) ||
                grow((void **)&w->buf[iout], &w->cap[iout], 2 * n + 2, sizeof(exact_pt)))
                return -1;
            size_t nin, nout;
            exact_clip(w->buf[iv], n, &l[m], w->buf[iin], &nin, w->buf[iout], &nout);
            if (nout && exact_area(w->buf[iout], nout, NULL, NULL) > 0 &&
                exact_pieces_add(&w->next, w->buf[iout], nout))
                return -1;
            int sw = iv;
            iv = iin, iin = sw, n = nin;
        }
    }
    exact_pieces t = w->cur;
    w->cur = w->next, w->next = t;
    return 0;
}

/* The visible part of candidate c[t] in pixel (i, j), against the others
 * (sorted front to back by their nearest 1/Zc): its area and centroid. */
static int visible(exact_work *w, const exact_cand *c, size_t nc, size_t t, double i, double j, gls_exact_frag *f)
{
    static const exact_pt square[4] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    const exact_prep *T = &w->prep[c[t].tri];
    exact_pieces_clear(&w->cur);
    if (exact_pieces_add(&w->cur, square, 4))
        return -1;
    exact_line l[4];
    if (!c[t].inside) {
        for (int k = 0; k < 3; k++)
            l[k] = exact_line_local(&T->e[k], i, j), l[k].s = -l[k].s;
        /* the square minus the outside of each edge: what is inside all */
        for (int k = 0; k < 3 && w->cur.np; k++)
            if (subtract(w, &l[k], 1))
                return -1;
    }
    for (size_t u = 0; u < nc && w->cur.np; u++) {
        if (u == t || (w->tris[c[u].tri].flags & GLS_EXACT_HOLES))
            continue; /* an alpha-tested one hides nothing (exact.h) */
        if (c[u].zmax < c[t].zmin)
            break; /* this one and all after it are behind everywhere */
        const exact_prep *U = &w->prep[c[u].tri];
        /* boxes apart (within the square): U hides nothing of T */
        if (U->xmin >= T->xmax || U->xmax <= T->xmin || U->ymin >= T->ymax || U->ymax <= T->ymin)
            continue;
        int nl = 0;
        if (!c[u].inside)
            for (int k = 0; k < 3; k++)
                l[nl++] = exact_line_local(&U->e[k], i, j);
        if (!(c[u].zmin > c[t].zmax)) { /* not in front everywhere: cut at equal depth */
            exact_line d = exact_depth_line(&U->z, &T->z, i, j);
            if (d.a == 0 && d.b == 0 && d.c == 0) { /* coplanar: the lower index is in front */
                if (c[u].tri > c[t].tri)
                    continue;
            } else
                l[nl++] = d;
        }
        if (nl == 0) {
            exact_pieces_clear(&w->cur);
            break;
        }
        if (subtract(w, l, nl))
            return -1;
    }
    double a = 0, mx = 0, my = 0;
    for (size_t k = 0; k < w->cur.np; k++) {
        double px, py;
        a += exact_area(w->cur.v + w->cur.start[k], w->cur.start[k + 1] - w->cur.start[k], &px, &py);
        mx += px, my += py;
    }
    *f = (gls_exact_frag){c[t].tri, a, i + (a > 0 ? mx / a : 0), j + (a > 0 ? my / a : 0)};
    return 0;
}

static int cand_order(const void *pa, const void *pb)
{
    const exact_cand *a = pa, *b = pb;
    if (a->zmax != b->zmax)
        return a->zmax > b->zmax ? -1 : 1;
    return a->tri < b->tri ? -1 : a->tri > b->tri;
}

/* One pixel's fragments from its candidates c[0..nc) (reordered) */
static int resolve(exact_work *w, exact_cand *c, size_t nc, int i, int j, size_t *nf)
{
    *nf = 0;
    if (nc == 1 && c[0].inside) {
        w->frags[0] = (gls_exact_frag){c[0].tri, 1.0, i, j};
        *nf = 1;
        return 0;
    }
    qsort(c, nc, sizeof *c, cand_order);
    for (size_t t = 0; t < nc; t++) {
        gls_exact_frag f;
        if (visible(w, c, nc, t, i, j, &f))
            return -1;
        if (f.area > 0)
            w->frags[(*nf)++] = f;
    }
    return 0;
}

/* Passes 1 and 2 of one band (rows j0..j1) over the triangles */
static int band_cands(const exact_prep *p, const unsigned char *ok, size_t n, int w, int j0, int j1, double *fmin,
                      exact_cand **c, size_t *nc, size_t *capc)
{
    for (size_t k = 0; k < (size_t)w * (size_t)(j1 - j0 + 1); k++)
        fmin[k] = -INFINITY;
    for (int pass = 1; pass <= 2; pass++)
        for (size_t t = 0; t < n; t++) {
            if (!ok[t] || p[t].j1 < j0 || p[t].j0 > j1)
                continue;
            /* narrower than a pixel: covers none whole, nothing for pass 1;
             * an alpha-tested one (ok 2) covers nothing for certain */
            if (pass == 1 && (ok[t] == 2 || p[t].xmax - p[t].xmin < 1 || p[t].ymax - p[t].ymin < 1))
                continue;
            int ja = p[t].j0 > j0 ? p[t].j0 : j0, jb = p[t].j1 < j1 ? p[t].j1 : j1;
            for (int j = ja; j <= jb; j++)
                for (int i = p[t].i0; i <= p[t].i1; i++) {
                    int in = classify(&p[t], i, j);
                    if (in < 0 || (pass == 1 && !in))
                        continue;
                    size_t px = (size_t)(j - j0) * w + i;
                    double lo, hi;
                    zrange(&p[t].z, i, j, &lo, &hi);
                    if (pass == 1) {
                        if (lo > fmin[px])
                            fmin[px] = lo;
                    } else if (hi >= fmin[px]) {
                        if (grow((void **)c, capc, *nc + 1, sizeof **c))
                            return -1;
                        (*c)[(*nc)++] = (exact_cand){t, px, in, lo, hi};
                    }
                }
        }
    return 0;
}

static int run_bands(exact_work *wk, const unsigned char *ok, size_t n, int w, int h, gls_exact_pixel_fn fn,
                     void *user)
{
    size_t bandpx = (size_t)w * EXACT_BAND, nc = 0, capc = 0, caps = 0;
    double *fmin = malloc(bandpx * sizeof *fmin);
    size_t *start = malloc((bandpx + 1) * sizeof *start);
    exact_cand *c = NULL, *sorted = NULL;
    int rc = fmin && start ? 0 : -1;
    for (int j0 = 0; j0 < h && rc == 0; j0 += EXACT_BAND) {
        int j1 = j0 + EXACT_BAND - 1 < h - 1 ? j0 + EXACT_BAND - 1 : h - 1;
        nc = 0;
        if ((rc = band_cands(wk->prep, ok, n, w, j0, j1, fmin, &c, &nc, &capc)) != 0)
            break;
        /* counting sort of the candidates by pixel (buffers kept from band
         * to band: no page faults for each) */
        if (grow((void **)&sorted, &caps, nc + 1, sizeof *sorted) ||
            grow((void **)&wk->frags, &wk->capf, nc + 1, sizeof *wk->frags)) {
            rc = -1;
            break;
        }
        memset(start, 0, (bandpx + 1) * sizeof *start);
        for (size_t k = 0; k < nc; k++)
            start[c[k].pix + 1]++;
        for (size_t k = 0; k < bandpx; k++)
            start[k + 1] += start[k];
        for (size_t k = 0; k < nc; k++)
            sorted[start[c[k].pix]++] = c[k];
        for (size_t k = bandpx; k > 0; k--)
            start[k] = start[k - 1];
        start[0] = 0;
        for (int j = j0; j <= j1 && rc == 0; j++)
            for (int i = 0; i < w; i++) {
                size_t px = (size_t)(j - j0) * w + i, nf;
                if (wk->cands) {
                    if ((rc = wk->cands(wk->cuser, wk->prep, sorted + start[px], start[px + 1] - start[px], i, j)))
                        break;
                    continue;
                }
                if ((rc = resolve(wk, sorted + start[px], start[px + 1] - start[px], i, j, &nf)) != 0)
                    break;
                fn(user, i, j, wk->frags, nf);
            }
    }
    free(fmin), free(start), free(c), free(sorted);
    return rc;
}

static int visit(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user,
                 exact_cand_fn cands)
{
    if (w <= 0 || h <= 0)
        return 0;
    exact_prep *p = malloc((n ? n : 1) * sizeof *p);
    unsigned char *ok = malloc(n ? n : 1);
    exact_work wk = {0};
    int rc = -1;
    if (p && ok) {
        for (size_t k = 0; k < n; k++)
            ok[k] = (unsigned char)(exact_prep_tri(&t[k], w, h, &p[k]) ? (t[k].flags & GLS_EXACT_HOLES ? 2 : 1) : 0);
        wk.prep = p, wk.tris = t, wk.cands = cands, wk.cuser = user;
        rc = run_bands(&wk, ok, n, w, h, fn, user);
    }
    exact_pieces_free(&wk.cur), exact_pieces_free(&wk.next);
    free(wk.buf[0]), free(wk.buf[1]), free(wk.buf[2]), free(wk.frags), free(p), free(ok);
    return rc;
}

int gls_exact_visit(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user)
{
    return visit(t, n, w, h, fn, user, NULL);
}

int exact_visit_cands(const gls_exact_tri *t, size_t n, int w, int h, exact_cand_fn fn, void *user)
{
    return visit(t, n, w, h, NULL, user, fn);
}
