/* Internal to the exact-coverage family (exact.h): exact_poly.c,
 * exact_pixels.c, exact_image.c, exact_project.c, exact_edges.c.  Not for other rooms.
 *
 * Pixel-local coordinates: a pixel's work is done with the pixel centre
 * subtracted (x - i, y - j), so that the square is [-0.5, 0.5]^2 whatever
 * the image position and the arithmetic keeps its precision at 1e7 px as
 * at 0.  Subtracting an integer near x is exact in double.
 *
 * Canonical lines.  A triangle edge is clipped with the line through its
 * two endpoints taken in lexicographic order (x, then y), whichever
 * triangle it belongs to, and a side sign (+1 or -1) says which half the
 * triangle keeps; negating a value is exact, and a crossing point is
 * computed from the segment's endpoints in lexicographic order too, so two
 * triangles sharing an edge cut a pixel at bit-identical points and their
 * areas add up to the covered area with no crack and no double count. */
#ifndef GLS_EXACT_INT_H
#define GLS_EXACT_INT_H

#include <math.h>
#include <stddef.h>
#include "exact.h"

typedef struct {
    double x, y;
} exact_pt;

/* f(p) = a (p.x - ox) + b (p.y - oy) + c; the kept half is s f > 0 (the
 * line itself belongs to both halves).  Edges have c = 0 and their origin
 * at the canonical first endpoint; depth lines have the origin at 0. */
typedef struct {
    double a, b, c, ox, oy;
    double s;
} exact_line;

/* convex polygons, counter-clockwise, in one growable vertex pool: piece
 * k is v[start[k]] .. v[start[k + 1] - 1] */
typedef struct {
    exact_pt *v;
    size_t nv, capv;
    size_t *start;      /* np + 1 entries once a piece is added           */
    size_t np, capp;
} exact_pieces;

/* 1/Zc of a triangle over the image: z = z0 + a (x - x0) + b (y - y0) */
typedef struct {
    double a, b, x0, y0, z0;
} exact_plane;

/* A triangle ready for the pixels: counter-clockwise vertices, its three
 * edges' canonical lines in image coordinates (origin at the canonical
 * first endpoint), its depth plane, its pixel bounds. */
typedef struct {
    double x[3], y[3];
    exact_line e[3];
    exact_plane z;
    double xmin, xmax, ymin, ymax; /* its bounding box                  */
    int i0, i1, j0, j1; /* pixels whose square meets its bounding box     */
} exact_prep;

/* exact_poly.c */
int exact_prep_tri(const gls_exact_tri *t, int w, int h, exact_prep *p);
exact_line exact_depth_line(const exact_plane *front, const exact_plane *back, double i, double j);

/* The small ones, inline: they run for every candidate pair of every
 * crossed pixel, and out of line their struct returns went through memory
 * (a sixth of the pixel work in perf on make bench-aa's 100k scene). */
static inline exact_line exact_line_local(const exact_line *l, double i, double j)
{
    exact_line r = *l;
    r.ox -= i, r.oy -= j;
    return r;
}

static inline double exact_plane_at(const exact_plane *z, double x, double y)
{
    return z->z0 + z->a * (x - z->x0) + z->b * (y - z->y0);
}

/* f at p, and 0 where its sign is not certain: |f| within the bound on
 * its rounding (a static filter in Shewchuk's sense), so a vertex on a
 * line up to rounding counts as on it, and no split makes a sliver of
 * nothing but rounding.  The bound depends on the line and the point
 * only, so two triangles sharing an edge snap alike. */
static inline double exact_line_f(const exact_line *l, exact_pt p)
{
    double fx = l->a * (p.x - l->ox), fy = l->b * (p.y - l->oy), f = fx + fy + l->c;
    return fabs(f) <= 1e-15 * (fabs(fx) + fabs(fy) + fabs(l->c)) ? 0 : f;
}

/* 1: v is all on the kept side of l (or on it), -1: all on the other, 0:
 * l splits it */
static inline int exact_line_side(const exact_pt *v, size_t n, const exact_line *l)
{
    int pos = 0, neg = 0;
    for (size_t k = 0; k < n; k++) {
        double f = l->s * exact_line_f(l, v[k]);
        pos |= f > 0, neg |= f < 0;
    }
    return pos && neg ? 0 : neg ? -1 : 1;
}
void exact_pieces_clear(exact_pieces *p);
void exact_pieces_free(exact_pieces *p);
int exact_pieces_add(exact_pieces *p, const exact_pt *v, size_t n);
/* split convex polygon v (n vertices) by l: the kept part to in (*nin),
 * the rest to out (*nout); in and out hold n + 1 vertices */
void exact_clip(const exact_pt *v, size_t n, const exact_line *l, exact_pt *in, size_t *nin, exact_pt *out,
                size_t *nout);
double exact_area(const exact_pt *v, size_t n, double *mx, double *my);

/* exact_pixels.c: one pixel's candidates resolved into fragments */
typedef struct exact_work exact_work;

/* a triangle that may show in a pixel (nearer than the nearest triangle
 * covering the pixel whole somewhere in it) */
typedef struct {
    uint32_t tri;       /* index into the caller's triangles and preps
                           (visit takes fewer than 2^32)                  */
    uint32_t pix : 31;  /* pixel in the band (a band has fewer than 2^31)  */
    uint32_t inside : 1; /* the triangle covers the pixel's square whole  */
    double zmin, zmax;  /* bounds of its 1/Zc over the square             */
} exact_cand;           /* 24 bytes: a band's candidates are most of the
                           memory the walk touches                        */

/* gls_exact_visit's walk, handing each pixel's candidates that have a
 * visible part there (area > 0, as the areas resolve them; in no order)
 * to fn instead of their frags: exact_edges.c's way in.  fn returns 0,
 * or -1 to stop (out of memory), which exact_visit_cands returns. */
typedef int (*exact_cand_fn)(void *user, const exact_prep *p, const exact_cand *c, size_t nc, int i, int j);
int exact_visit_cands(const gls_exact_tri *t, size_t n, int w, int h, exact_cand_fn fn, void *user);
/* gls_exact_visit_any_thread where a pixel of more than dense candidates
 * (0: none is) is handed out unresolved (gls_exact_render's dense). */
int exact_visit_dense(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user, size_t dense);

/* The image is done in bands of EXACT_BAND rows (exact_pixels.c computes
 * a band, exact_bands.c hands the bands to threads and out in order). */
#define EXACT_BAND 16
struct exact_work {
    const exact_prep *prep;
    const gls_exact_tri *tris;
    exact_pieces cur, next;
    exact_pt *buf[3];   /* clip buffers: the piece, its two parts          */
    size_t cap[3];
    exact_cand_fn cands; /* exact_visit_cands: the visible candidates     */
    size_t dense;       /* 0, or a pixel of more candidates than this is
                           handed out unresolved (gls_exact_render)       */
    void *cuser;
    double (*box)[4];   /* per candidate of the pixel being resolved: the
                           box of its part of the square, pixel-local
                           (x0, x1, y0, y1); x0 > x1 when it has none      */
    size_t capbox;
};

/* Each band's triangles, in index order (so candidates come in the same
 * order as from a walk over all of them): band b's are
 * idx[start[b] .. start[b + 1]).  A band looks at its own triangles only;
 * walking all of them for each band and pass read the whole prep array
 * (280 bytes a triangle) 60 times on make bench-aa's scene. */
typedef struct {
    size_t *start, *idx;
} band_lists;

/* One band's results: its candidates sorted by pixel (start: each
 * pixel's first) and, unless the walk hands out candidates, its frags
 * (fstart: each pixel's first).  Buffers are kept from band to band: no
 * page faults for each. */
typedef struct {
    double *fmin;
    size_t *start, *fstart;
    exact_cand *c, *sorted;
    size_t nc, capc, caps;
    gls_exact_frag *frags;
    size_t capf;
} band_slot;

/* Everything of band j0..j1 but handing it out: candidates, their
 * counting sort by pixel, each pixel resolved.  wk is this thread's
 * scratch.  0, or -1 when out of memory. */
int exact_band_compute(exact_work *wk, const band_lists *bl, int w, int h, int j0, band_slot *b);
/* a thread's scratch freed */
void exact_work_free(exact_work *wk);

#endif
