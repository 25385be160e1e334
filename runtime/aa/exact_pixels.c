/* Exact coverage: the pixels (exact.h, gls_exact_visit).
 *
 * The image is done in bands of EXACT_BAND rows (exact_bands.c puts them
 * on worker threads, two bands a thread at a time), so memory is bounded
 * by those bands and the triangles' pixels in them.  In a band, each triangle's pixels (its
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

/* a pixel whose visible parts add up to this is full: what is left of
 * the square is below the areas' rounding (a few 1e-16 a piece) */
#define EXACT_FULL (1 - 1e-14)
/* from this many candidates in a pixel, each one's part of the square is
 * clipped for its box (resolve) */
#define EXACT_CLIP_BOXES 8

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
 * lines l[0..nl) (their kept halves), into w->next; then swap.  1 when
 * the pieces changed, 0 when not, -1 when out of memory. */
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
    return 1;
}

/* The part of T's triangle in the square of pixel (i, j), pixel-local,
 * into poly (8 vertices): the square cut by the outside of each edge, as
 * subtract would cut it.  Its vertex count, 0 when it has no area. */
static size_t tri_in_square(const exact_prep *T, int inside, double i, double j, exact_pt poly[2][8], int *at)
{
    static const exact_pt square[4] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    exact_pt rest[8];
    size_t n = 4;
    *at = 0;
    memcpy(poly[0], square, sizeof square);
    for (int k = 0; k < 3 && n && !inside; k++) {
        exact_line o = exact_line_local(&T->e[k], i, j);
        o.s = -o.s;
        int side = exact_line_side(poly[*at], n, &o);
        if (side < 0)
            continue; /* wholly inside this edge */
        size_t nin, nout = 0;
        if (side == 0)
            exact_clip(poly[*at], n, &o, rest, &nin, poly[1 - *at], &nout);
        if (nout && exact_area(poly[1 - *at], nout, NULL, NULL) > 0)
            *at = 1 - *at, n = nout;
        else
            n = 0;
    }
    return n;
}

/* the box of n vertices (x0, x1, y0, y1); x0 > x1 for none */
static void box_of(const exact_pt *v, size_t n, double b[4])
{
    b[0] = b[2] = INFINITY, b[1] = b[3] = -INFINITY;
    for (size_t k = 0; k < n; k++) {
        b[0] = v[k].x < b[0] ? v[k].x : b[0], b[1] = v[k].x > b[1] ? v[k].x : b[1];
        b[2] = v[k].y < b[2] ? v[k].y : b[2], b[3] = v[k].y > b[3] ? v[k].y : b[3];
    }
}

/* 1 when T and U have an edge with the same two endpoints (so the same
 * canonical line, bit for bit) and keep its two opposite sides: their
 * interiors are disjoint.  Cutting U away from T would find every piece
 * of T beyond that line and change nothing; a mesh's neighbours are most
 * of a crossed pixel's candidate pairs. */
static int share_edge_apart(const exact_prep *T, const exact_prep *U)
{
    for (int k = 0; k < 3; k++)
        for (int m = 0; m < 3; m++) {
            const exact_line *a = &T->e[k], *b = &U->e[m];
            if (a->ox == b->ox && a->oy == b->oy && a->a == b->a && a->b == b->b && a->s != b->s)
                return 1;
        }
    return 0;
}

/* The visible part of candidate c[t] in pixel (i, j), against the others
 * (sorted front to back by their nearest 1/Zc): its area and centroid.
 * w->box holds each candidate's box in the square (resolve). */
static int visible(exact_work *w, const exact_cand *c, size_t nc, size_t t, double i, double j, gls_exact_frag *f)
{
    const exact_prep *T = &w->prep[c[t].tri];
    exact_pieces_clear(&w->cur);
    exact_line l[4];
    /* the square minus the outside of each edge: what is inside all.  One
     * convex piece, clipped on the stack (4 + 3 vertices at most); the
     * same steps, the same bits, as subtract with each edge's outside
     * would take */
    exact_pt poly[2][8];
    int at;
    size_t n = tri_in_square(T, c[t].inside, i, j, poly, &at);
    if (n && exact_pieces_add(&w->cur, poly[at], n))
        return -1;
    /* the box of what is left of T: another candidate whose part of the
     * square lies beyond it (or touches it along a line) cuts nothing
     * away.  The triangles' own boxes say little in a pixel of far
     * slivers, each spanning pixels; their parts in the square are
     * often stacked apart (make bench-aa's road frame) */
    int many = nc >= EXACT_CLIP_BOXES;
    double cb[4];
    if (many)
        box_of(poly[at], n, cb);
    for (size_t u = 0; u < nc && w->cur.np; u++) {
        if (u == t || (w->tris[c[u].tri].flags & GLS_EXACT_HOLES))
            continue; /* an alpha-tested one hides nothing (exact.h) */
        if (c[u].zmax < c[t].zmin)
            break; /* this one and all after it are behind everywhere */
        const exact_prep *U = &w->prep[c[u].tri];
        /* parts of the square apart (with a few candidates, the whole
         * triangles' boxes), or on the two sides of an edge they share (a
         * mesh's neighbours): U hides nothing of T */
        const double *ub = many ? w->box[u] : NULL;
        if ((many ? ub[0] >= cb[1] || ub[1] <= cb[0] || ub[2] >= cb[3] || ub[3] <= cb[2]
                  : U->xmin >= T->xmax || U->xmax <= T->xmin || U->ymin >= T->ymax || U->ymax <= T->ymin) ||
            share_edge_apart(T, U))
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
        int changed = subtract(w, l, nl);
        if (changed < 0)
            return -1;
        if (changed && many) /* what is left of T: its box anew */
            box_of(w->cur.v, w->cur.nv, cb);
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
static int resolve(exact_work *w, exact_cand *c, size_t nc, int i, int j, gls_exact_frag *out, size_t *nf)
{
    *nf = 0;
    if (nc == 1 && c[0].inside) {
        out[0] = (gls_exact_frag){c[0].tri, 1.0, i, j};
        *nf = 1;
        return 0;
    }
    /* a dense pixel (gls_exact_render's dense): its exact cuts would cost
     * the square of its candidates; its candidates go out unresolved, as
     * an alpha-tested pixel's do below, and the colour is point-sampled */
    if (w->dense && nc > w->dense) {
        for (size_t k = 0; k < nc; k++)
            out[k] = (gls_exact_frag){c[k].tri, NAN, i, j};
        *nf = nc;
        return 0;
    }
    qsort(c, nc, sizeof *c, cand_order);
    /* with many candidates, each one's box of its part of the square,
     * clipped (a few: the triangles' own boxes, as cheap as the cuts they
     * would save; make bench-aa's terrain was 6% slower clipping them) */
    if (nc >= EXACT_CLIP_BOXES) {
        if (grow((void **)&w->box, &w->capbox, nc, sizeof *w->box))
            return -1;
        for (size_t k = 0; k < nc; k++) {
            exact_pt poly[2][8];
            int at;
            size_t n = tri_in_square(&w->prep[c[k].tri], c[k].inside, i, j, poly, &at);
            box_of(poly[at], n, w->box[k]);
        }
    }
    /* An alpha-tested candidate (exact.h GLS_EXACT_HOLES) hides nothing,
     * and a pixel it shows in is point-sampled: no area there is used,
     * only which triangle is nearest at each lattice point.  So its
     * visible part decides the pixel: where one has any, every candidate
     * is handed out as it is (area NaN: not computed), which costs the
     * exact cuts of every layer behind the tree's leaves (the road
     * frame's trees: 0.47 s of CPU, a third of the frame); where none
     * has, they are left out and the pixel is exact. */
    size_t nh = 0;
    for (size_t t = 0; t < nc; t++) {
        if (!(w->tris[c[t].tri].flags & GLS_EXACT_HOLES))
            continue;
        gls_exact_frag f;
        if (visible(w, c, nc, t, i, j, &f))
            return -1;
        if (f.area > 0) {
            for (size_t k = 0; k < nc; k++)
                out[k] = (gls_exact_frag){c[k].tri, NAN, i, j};
            *nf = nc;
            return 0;
        }
        nh++;
    }
    if (nh) { /* hidden everywhere: out of the way of the boxes' indices */
        size_t kept = 0;
        for (size_t t = 0; t < nc; t++)
            if (!(w->tris[c[t].tri].flags & GLS_EXACT_HOLES)) {
                if (nc >= EXACT_CLIP_BOXES)
                    memmove(w->box[kept], w->box[t], sizeof w->box[0]);
                c[kept++] = c[t];
            }
        nc = kept;
    }
    /* visible parts are disjoint: once those found fill the square (to
     * EXACT_FULL), the rest have none.  Without this a pixel on a
     * silhouette cut every hidden layer behind it against every one in
     * front (make bench-aa's terrain: 2.4 million cuts, 4 a candidate) */
    double covered = 0;
    for (size_t t = 0; t < nc && covered < EXACT_FULL; t++) {
        gls_exact_frag f;
        if (visible(w, c, nc, t, i, j, &f))
            return -1;
        if (f.area > 0)
            out[(*nf)++] = f, covered += f.area;
    }
    return 0;
}

/* The pixels of row j that triangle T may meet, within its bounding
 * box's columns: the x extent of its part of the strip [j - 1/2, j + 1/2]
 * (its vertices in it, its edges' crossings of its lines), widened far
 * above the crossings' rounding.  classify still decides each pixel; this
 * spares it the box's pixels the triangle is nowhere near (far slivers
 * cross wide boxes diagonally: 79% of the road frame's classified pixels
 * were outside, 88% on frame 90).  0 when none. */
static int row_span(const exact_prep *T, int j, int *i0, int *i1)
{
    double y0 = j - 0.5, y1 = j + 0.5, lo = INFINITY, hi = -INFINITY, big = 1;
    for (int k = 0; k < 3; k++) {
        double ax = T->x[k], ay = T->y[k], bx = T->x[(k + 1) % 3], by = T->y[(k + 1) % 3];
        big = fmax(big, fmax(fabs(ax), fabs(ay)));
        if (ay >= y0 && ay <= y1)
            lo = fmin(lo, ax), hi = fmax(hi, ax);
        for (int s = 0; s < 2; s++) {
            double yl = s ? y1 : y0;
            if ((ay < yl && by > yl) || (ay > yl && by < yl)) {
                double x = ax + (bx - ax) * ((yl - ay) / (by - ay));
                lo = fmin(lo, x), hi = fmax(hi, x);
            }
        }
    }
    if (!(lo <= hi))
        return 0;
    double m = 1e-9 * big;
    double a = ceil(lo - 0.5 - m), b = floor(hi + 0.5 + m);
    *i0 = a > T->i0 ? (int)a : T->i0;
    *i1 = b < T->i1 ? (int)b : T->i1;
    return *i0 <= *i1;
}

/* Passes 1 and 2 of one band (rows j0..j1) over the triangles */
static int band_cands(const exact_prep *p, const gls_exact_tri *tris, const size_t *list, size_t nl, int w, int j0,
                      int j1, double *fmin, exact_cand **c, size_t *nc, size_t *capc)
{
    for (size_t k = 0; k < (size_t)w * (size_t)(j1 - j0 + 1); k++)
        fmin[k] = -INFINITY;
    /* each pixel of each triangle classified once: every one not outside
     * kept with its depth range while F is found (pass 1), then those
     * behind F dropped in place (pass 2); the survivors in the order of a
     * second walk */
    for (size_t q = 0; q < nl; q++) {
        size_t t = list[q];
        int ja = p[t].j0 > j0 ? p[t].j0 : j0, jb = p[t].j1 < j1 ? p[t].j1 : j1;
        for (int j = ja; j <= jb; j++) {
            int ia, ib;
            if (!row_span(&p[t], j, &ia, &ib))
                continue;
            for (int i = ia; i <= ib; i++) {
                int in = classify(&p[t], i, j);
                if (in < 0)
                    continue;
                size_t px = (size_t)(j - j0) * w + i;
                double lo, hi;
                zrange(&p[t].z, i, j, &lo, &hi);
                /* an alpha-tested one covers nothing for certain */
                if (in && lo > fmin[px] && !(tris[t].flags & GLS_EXACT_HOLES))
                    fmin[px] = lo;
                if (grow((void **)c, capc, *nc + 1, sizeof **c))
                    return -1;
                (*c)[(*nc)++] = (exact_cand){(uint32_t)t, (uint32_t)px, (uint32_t)in, lo, hi};
            }
        }
    }
    size_t kept = 0;
    for (size_t k = 0; k < *nc; k++)
        if ((*c)[k].zmax >= fmin[(*c)[k].pix])
            (*c)[kept++] = (*c)[k];
    *nc = kept;
    return 0;
}

/* Everything of band j0..j1 but handing it out: candidates, their
 * counting sort by pixel, each pixel resolved.  wk is this thread's
 * scratch.  0, or -1 when out of memory. */
int exact_band_compute(exact_work *wk, const band_lists *bl, int w, int h, int j0, band_slot *b)
{
    const size_t *list = bl->idx + bl->start[j0 / EXACT_BAND];
    size_t nl = bl->start[j0 / EXACT_BAND + 1] - bl->start[j0 / EXACT_BAND];
    int j1 = j0 + EXACT_BAND - 1 < h - 1 ? j0 + EXACT_BAND - 1 : h - 1;
    size_t bandpx = (size_t)w * EXACT_BAND;
    if (!b->fmin && (!(b->fmin = malloc(bandpx * sizeof *b->fmin)) ||
                     !(b->start = malloc((bandpx + 1) * sizeof *b->start)) ||
                     !(b->fstart = malloc((bandpx + 1) * sizeof *b->fstart))))
        return -1;
    b->nc = 0;
    /* a first guess at the band's candidates (a few a triangle and one a
     * pixel): fewer reallocs copying the array while it grows */
    if (grow((void **)&b->c, &b->capc, 4 * nl + bandpx, sizeof *b->c))
        return -1;
    if (band_cands(wk->prep, wk->tris, list, nl, w, j0, j1, b->fmin, &b->c, &b->nc, &b->capc))
        return -1;
    if (grow((void **)&b->sorted, &b->caps, b->nc + 1, sizeof *b->sorted) ||
        grow((void **)&b->frags, &b->capf, b->nc + 1, sizeof *b->frags))
        return -1;
    size_t *start = b->start;
    memset(start, 0, (bandpx + 1) * sizeof *start);
    for (size_t k = 0; k < b->nc; k++)
        start[b->c[k].pix + 1]++;
    for (size_t k = 0; k < bandpx; k++)
        start[k + 1] += start[k];
    for (size_t k = 0; k < b->nc; k++)
        b->sorted[start[b->c[k].pix]++] = b->c[k];
    for (size_t k = bandpx; k > 0; k--)
        start[k] = start[k - 1];
    start[0] = 0;
    size_t nf = 0;
    for (int j = j0; j <= j1; j++)
        for (int i = 0; i < w; i++) {
            size_t px = (size_t)(j - j0) * w + i, m, n = start[px + 1] - start[px];
            exact_cand *c = b->sorted + start[px];
            b->fstart[px] = nf;
            if (resolve(wk, c, n, i, j, b->frags + nf, &m))
                return -1;
            if (!wk->cands) {
                nf += m;
                continue;
            }
            /* the walk's candidates handed out (exact_edges.c): those with
             * a visible part only, in place, their count in fstart.  A
             * hidden one bounds no visible region and is in front on no
             * side of a boundary; behind a silhouette a pixel has every
             * layer of a terrain as candidates (make bench-aa's scene:
             * the edges took minutes where the image takes a second) */
            size_t kept = 0;
            for (size_t q = 0; q < n; q++)
                for (size_t r = 0; r < m; r++)
                    if (b->frags[nf + r].tri == c[q].tri) {
                        c[kept++] = c[q];
                        break;
                    }
            b->fstart[px] = kept;
        }
    b->fstart[(size_t)(j1 - j0 + 1) * w] = nf;
    return 0;
}

void exact_work_free(exact_work *wk)
{
    exact_pieces_free(&wk->cur), exact_pieces_free(&wk->next);
    free(wk->box);
    free(wk->buf[0]), free(wk->buf[1]), free(wk->buf[2]);
}
